#pragma once
// Plain-data streams for a simulation's state (checkpoints, io/output/checkpoint.h). Each stateful
// piece writes its own fields with save(StateWriter&) and reads them back in the same order
// with load(StateReader&), next to the fields themselves, so that a field added later is
// saved where it is declared. Values are stored as their bytes (little-endian hosts only, the
// same Real as the build: io/output/checkpoint.h refuses a file of another precision); a vector is its
// element count, then its elements. A piece starts with a named section, so a reader that
// meets the sections of another piece (a file of another version, a forgotten field) says
// which one and where, instead of reading nonsense.
//
// Scratch (buffers rebuilt every step) and settings (rebuilt from the scenario) are not state
// and are not written.
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <deque>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "pbd/core/types.h"

namespace hs::pbd {

static_assert(std::endian::native == std::endian::little, "checkpoints store little-endian bytes");
static_assert(sizeof(Vec3) == 3 * sizeof(Real), "a Vec3 is stored as its three coordinates");

// Values stored as their bytes: arithmetic types, enums and Vec3 (no padding in any of them).
template <class T>
concept PlainValue = std::is_arithmetic_v<T> || std::is_enum_v<T> || std::is_same_v<T, Vec3>;

class StateWriter;
class StateReader;
// A record that writes and reads its own fields (save(StateWriter&) const, load(StateReader&)).
template <class T>
concept SavedRecord = requires(const T& c, T& m, StateWriter& w, StateReader& r) {
  c.save(w);
  m.load(r);
};

// What a reader found wrong, with the byte offset in the stream (io/output/checkpoint.h adds the
// file's name and the offset of the stream in it).
struct StateError : std::runtime_error {
  StateError(const std::string& what, std::size_t at)
      : std::runtime_error(what), offset(at) {}
  std::size_t offset;
};

class StateWriter {
 public:
  void section(std::string_view name) { put(std::string(name)); }

  template <PlainValue T>
  void put(const T& value) {
    append(&value, sizeof(T));
  }
  void put(bool value) { put(std::uint8_t(value ? 1 : 0)); }
  void put(const std::string& text) {
    put(std::uint64_t(text.size()));
    append(text.data(), text.size());
  }
  template <PlainValue T>
  void put(const std::vector<T>& values) {
    put(std::uint64_t(values.size()));
    append(values.data(), values.size() * sizeof(T));
  }
  template <PlainValue T>
  void put(const std::deque<T>& values) {
    put(std::vector<T>(values.begin(), values.end()));
  }
  template <class T>
  void put(const std::optional<T>& value) {
    put(value.has_value());
    if (value) put(*value);
  }
  template <PlainValue T, std::size_t N>
  void put(const std::array<T, N>& values) {
    append(values.data(), N * sizeof(T));
  }
  template <SavedRecord T>
  void put(const T& record) {
    record.save(*this);
  }
  template <SavedRecord T>
  void put(const std::vector<T>& records) {
    put(std::uint64_t(records.size()));
    for (const T& r : records) r.save(*this);
  }
  // Several fields in order: w.fields(a, b, c) is put(a), put(b), put(c).
  template <class... T>
  void fields(const T&... values) {
    (put(values), ...);
  }
  // The generator's state in the standard's text form (operator<<): exact and portable.
  void put(const std::mt19937& random);

  [[nodiscard]] const std::vector<std::uint8_t>& bytes() const { return m_bytes; }

 private:
  void append(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    m_bytes.insert(m_bytes.end(), p, p + size);
  }
  std::vector<std::uint8_t> m_bytes;
};

class StateReader {
 public:
  explicit StateReader(std::span<const std::uint8_t> bytes) : m_bytes(bytes) {}

  // Throws StateError unless the next section is `name`.
  void section(std::string_view name);

  template <PlainValue T>
  void get(T& value) {
    take(&value, sizeof(T), "a value");
  }
  void get(bool& value);
  void get(std::string& text);
  template <PlainValue T>
  void get(std::vector<T>& values) {
    const std::size_t count = length(sizeof(T));
    values.resize(count);
    take(values.data(), count * sizeof(T), "a list");
  }
  template <PlainValue T>
  void get(std::deque<T>& values) {
    std::vector<T> all;
    get(all);
    values.assign(all.begin(), all.end());
  }
  template <class T>
  void get(std::optional<T>& value) {
    bool present = false;
    get(present);
    if (!present) {
      value.reset();
      return;
    }
    T inner{};
    get(inner);
    value = std::move(inner);
  }
  template <PlainValue T, std::size_t N>
  void get(std::array<T, N>& values) {
    take(values.data(), N * sizeof(T), "an array");
  }
  template <SavedRecord T>
  void get(T& record) {
    record.load(*this);
  }
  template <SavedRecord T>
  void get(std::vector<T>& records) {
    const std::size_t count = length(1);  // every record takes at least a byte
    records.assign(count, T{});
    for (T& r : records) r.load(*this);
  }
  void get(std::mt19937& random);
  // Several fields in the order StateWriter::fields wrote them.
  template <class... T>
  void fields(T&... values) {
    (get(values), ...);
  }
  // A list whose length the simulation already knows (a particle column, a region's vertices):
  // a different count means the state is of another model. `what` names it in the error.
  template <PlainValue T>
  void getSized(std::vector<T>& values, std::size_t expected, const char* what) {
    const std::size_t at = m_offset;
    std::uint64_t count = 0;
    get(count);
    if (count != expected)
      throw StateError(std::string(what) + ": " + std::to_string(count) + " values where the scenario has " +
                           std::to_string(expected),
                       at);
    m_offset = at;
    get(values);
  }

  [[nodiscard]] std::size_t offset() const { return m_offset; }
  [[nodiscard]] bool atEnd() const { return m_offset == m_bytes.size(); }

 private:
  // Reads a list's element count and checks that the stream holds that many elements.
  std::size_t length(std::size_t elementSize);
  void take(void* out, std::size_t size, const char* what);

  std::span<const std::uint8_t> m_bytes;
  std::size_t m_offset = 0;
};

}  // namespace hs::pbd
