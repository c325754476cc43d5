#include "pbd/core/state_stream.h"

#include <sstream>

namespace hs::pbd {

void StateWriter::put(const std::mt19937& random) {
  std::ostringstream text;
  text << random;
  put(text.str());
}

void StateReader::section(std::string_view name) {
  const std::size_t at = m_offset;
  std::string found;
  try {
    get(found);
  } catch (const StateError&) {
    throw StateError("expected section '" + std::string(name) + "', found the end of the state", at);
  }
  if (found != name)
    throw StateError("expected section '" + std::string(name) + "', found '" + found.substr(0, 40) + "'", at);
}

void StateReader::get(bool& value) {
  const std::size_t at = m_offset;
  std::uint8_t byte = 0;
  get(byte);
  if (byte > 1) throw StateError("a flag holds " + std::to_string(byte) + ", expected 0 or 1", at);
  value = byte == 1;
}

void StateReader::get(std::string& text) {
  const std::size_t count = length(1);
  text.assign(reinterpret_cast<const char*>(m_bytes.data() + m_offset), count);
  m_offset += count;
}

void StateReader::get(std::mt19937& random) {
  const std::size_t at = m_offset;
  std::string text;
  get(text);
  std::istringstream in(text);
  in >> random;
  if (!in) throw StateError("a random generator's state does not parse", at);
}

std::size_t StateReader::length(std::size_t elementSize) {
  const std::size_t at = m_offset;
  std::uint64_t count = 0;
  get(count);
  const std::size_t left = m_bytes.size() - m_offset;
  if (count > left / elementSize)
    throw StateError("a list of " + std::to_string(count) + " values runs past the end of the state", at);
  return std::size_t(count);
}

void StateReader::take(void* out, std::size_t size, const char* what) {
  if (size > m_bytes.size() - m_offset)
    throw StateError(std::string(what) + " runs past the end of the state", m_offset);
  if (size > 0) std::memcpy(out, m_bytes.data() + m_offset, size);
  m_offset += size;
}

}  // namespace hs::pbd
