// Text helpers of the scenario reader: number and string formatting, value descriptions for
// error messages, and "did you mean" suggestions.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "io/scenario/scenario_internal.h"

namespace hs::io::detail {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string_view leafOf(std::string_view dotted) {
  const auto dot = dotted.rfind('.');
  return dot == std::string_view::npos ? dotted : dotted.substr(dot + 1);
}

}  // namespace

std::string nearMiss(std::string_view unknown) {
  const std::string u = lower(unknown);
  std::string best;
  std::size_t bestScore = std::string::npos;
  auto consider = [&](const std::string& candidate) {
    std::size_t score = editDistance(u, candidate);
    if (lower(leafOf(u)) == leafOf(candidate)) score = std::min<std::size_t>(score, 1);
    if (score < bestScore) {
      bestScore = score;
      best = candidate;
    }
  };
  for (const KeySpec& k : keyTable()) consider(k.name);
  for (const TableSpec& t : tableTable()) consider(t.name);
  const std::size_t limit = std::max<std::size_t>(2, u.size() / 4);
  return bestScore <= limit ? " (did you mean " + best + "?)" : "";
}

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

std::string formatReal(pbd::Real value) {
  if (!std::isfinite(value)) return formatNumber(static_cast<double>(value));
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string quoteString(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          static const char* hex = "0123456789abcdef";
          out += "\\u00";
          out += hex[(c >> 4) & 0xf];
          out += hex[c & 0xf];
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string describeNode(const toml::node& node) {
  constexpr std::size_t kMax = 60;
  std::string d;
  if (const auto* s = node.as_string()) {
    d = quoteString(s->get());
  } else if (const auto* i = node.as_integer()) {
    d = std::to_string(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    d = formatNumber(f->get());
  } else if (const auto* b = node.as_boolean()) {
    d = b->get() ? "true" : "false";
  } else if (const auto* a = node.as_array()) {
    d = "[";
    for (const toml::node& e : *a) {
      d += (d.size() > 1 ? ", " : "") + (e.is_table() ? std::string("{...}") : describeNode(e));
      if (d.size() > kMax) break;
    }
    d += "]";
  } else if (node.is_table()) {
    d = "a table";
  } else {
    d = "a date/time";
  }
  if (d.size() > kMax) d = d.substr(0, kMax - 3) + "...";
  return d;
}

}  // namespace hs::io::detail
