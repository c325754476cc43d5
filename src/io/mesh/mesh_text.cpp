#include "io/mesh/mesh_text.h"

#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hs::io {

std::string excerpt(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  if (s.size() > 40) out += "...";
  return out;
}

void MeshTokens::fail(const std::string& message) const {
  throw std::invalid_argument(m_name + ":" + std::to_string(m_tokenLine) + ": " + message);
}

void MeshTokens::skipSpace() {
  while (m_pos < m_text.size()) {
    const char c = m_text[m_pos];
    if (c == '\n') {
      ++m_line;
      ++m_pos;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++m_pos;
    } else if (m_comment != '\0' && c == m_comment) {
      while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
    } else {
      return;
    }
  }
}

std::string_view MeshTokens::peek() {
  skipSpace();
  std::size_t end = m_pos;
  while (end < m_text.size() && static_cast<unsigned char>(m_text[end]) > ' ' &&
         (m_comment == '\0' || m_text[end] != m_comment))
    ++end;
  return m_text.substr(m_pos, end - m_pos);
}

std::string_view MeshTokens::next(std::string_view what) {
  const std::string_view token = peek();
  m_tokenLine = m_line;
  if (token.empty()) fail("expected " + std::string(what) + ", got the end of the file (truncated?)");
  m_pos += token.size();
  return token;
}

std::string_view MeshTokens::restOfLine() {
  std::size_t end = m_pos;
  while (end < m_text.size() && m_text[end] != '\n') ++end;
  std::string_view rest = m_text.substr(m_pos, end - m_pos);
  m_tokenLine = m_line;
  m_pos = end < m_text.size() ? end + 1 : end;
  if (end < m_text.size()) ++m_line;
  while (!rest.empty() && static_cast<unsigned char>(rest.front()) <= ' ') rest.remove_prefix(1);
  while (!rest.empty() && static_cast<unsigned char>(rest.back()) <= ' ') rest.remove_suffix(1);
  return rest;
}

double MeshTokens::real(std::string_view what) {
  std::string_view token = next(what);
  std::string_view digits = token;
  if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc() || end != digits.data() + digits.size())
    fail("expected " + std::string(what) + " (a number), got '" + excerpt(token) + "'");
  if (!std::isfinite(value)) fail("expected " + std::string(what) + " to be finite, got '" + excerpt(token) + "'");
  return value;
}

pbd::Vec3 MeshTokens::point(std::string_view what) {
  const double x = real(what), y = real(what), z = real(what);
  const pbd::Vec3 p(static_cast<pbd::Real>(x), static_cast<pbd::Real>(y), static_cast<pbd::Real>(z));
  if (!p.allFinite()) {
    std::ostringstream got;
    got << std::setprecision(6) << '(' << x << ", " << y << ", " << z << ')';
    fail("expected " + std::string(what) + " within the range of pbd::Real, got " + got.str());
  }
  return p;
}

long long MeshTokens::integer(std::string_view what) {
  std::string_view token = next(what);
  std::string_view digits = token;
  if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc() || end != digits.data() + digits.size())
    fail("expected " + std::string(what) + " (an integer), got '" + excerpt(token) + "'");
  return value;
}

long long MeshTokens::count(std::string_view what, long long limit) {
  const long long value = integer(what);
  if (value < 0 || value > limit)
    fail("expected " + std::string(what) + " in [0, " + std::to_string(limit) + "], got " + std::to_string(value));
  return value;
}

void MeshTokens::expect(std::string_view keyword) {
  const std::string_view token = next(keyword);
  if (token != keyword) fail("expected '" + std::string(keyword) + "', got '" + excerpt(token) + "'");
}

}  // namespace hs::io
