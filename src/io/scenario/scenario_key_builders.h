#pragma once
// Private to hs_io: the building blocks of the scenario key table (scenario_keys.cpp). Each
// builder turns (dotted name, field accessor, range, unit, doc) into a KeySpec whose setter
// checks type and range and throws ValueError, and whose getter prints the value as TOML.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/scenario/scenario_internal.h"

namespace hs::io::detail::builders {

using cardiac::Scenario;
using pbd::Real;
using pbd::Vec3;

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Allowed interval of a number; infinite bounds are absent.
struct Range {
  double lo = -kInf;
  double hi = kInf;
  bool loOpen = false;
  bool hiOpen = false;

  bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
  ScenarioKeyBounds bounds(bool integer = false, int components = 1) const {
    return {lo, hi, loOpen, hiOpen, integer, components};
  }
  std::string text() const {
    std::string t;
    if (std::isfinite(lo)) t += (loOpen ? "> " : ">= ") + formatNumber(lo);
    if (std::isfinite(hi))
      t += (t.empty() ? "" : " and ") + std::string(hiOpen ? "< " : "<= ") + formatNumber(hi);
    return t;
  }
};
inline Range gt(double lo) { return {lo, kInf, true, false}; }
inline Range ge(double lo) { return {lo, kInf, false, false}; }
inline Range between(double lo, double hi) { return {lo, hi, false, false}; }  // inclusive
inline Range gtLe(double lo, double hi) { return {lo, hi, true, false}; }

inline std::string withUnit(const std::string& text, const std::string& unit) {
  return unit.empty() ? text : text + " (" + unit + ")";
}
inline std::string spaced(const std::string& range) { return range.empty() ? "" : " " + range; }

template <class F>
auto& fieldOf(const F& field, const Scenario& s) {
  return field(const_cast<Scenario&>(s));  // read only
}

// ---- Value readers: throw ValueError ----

// A TOML integer or float as a double; nullopt-like flag for other types.
inline bool numberOf(const toml::node& n, double& out) {
  if (const auto* i = n.as_integer()) {
    out = static_cast<double>(i->get());
    return true;
  }
  if (const auto* f = n.as_floating_point()) {
    out = f->get();
    return true;
  }
  return false;
}

inline Real readReal(const toml::node& n, const Range& range, const std::string& expect) {
  double v = 0;
  if (!numberOf(n, v)) throw ValueError{"expected " + expect + ", got " + describeNode(n)};
  if (!std::isfinite(v) || !range.contains(v))
    throw ValueError{"must be " + expect + ", got " + describeNode(n)};
  const Real r = static_cast<Real>(v);
  if (!std::isfinite(r)) throw ValueError{"must be " + expect + ", got " + describeNode(n) + " (too large)"};
  return r;
}

inline std::int64_t readInt(const toml::node& n, std::int64_t lo, std::int64_t hi,
                            const std::string& expect) {
  const auto* i = n.as_integer();
  if (!i) throw ValueError{"expected " + expect + ", got " + describeNode(n)};
  const std::int64_t v = i->get();
  if (v < lo || v > hi) throw ValueError{"must be " + expect + ", got " + describeNode(n)};
  return v;
}

inline std::string intRangeText(std::int64_t lo, std::int64_t hi, std::int64_t typeMax) {
  std::string t = ">= " + std::to_string(lo);
  if (hi < typeMax) t += " and <= " + std::to_string(hi);
  return t;
}

// ---- Row builders ----

// The exact value of a field for checkpoints, whatever its type.
template <class F>
void addExactValue(KeySpec& k, F field) {
  k.save = [field](const Scenario& s, pbd::StateWriter& w) { w.put(fieldOf(field, s)); };
  k.load = [field](Scenario& s, pbd::StateReader& r) { r.get(field(s)); };
}

inline KeySpec makeSpec(std::string name, std::string type, std::string unit, std::string range,
                        std::string doc) {
  KeySpec k;
  k.name = std::move(name);
  k.type = std::move(type);
  k.unit = std::move(unit);
  k.range = std::move(range);
  k.doc = std::move(doc);
  return k;
}

// A number given in clinical units (the key's `unit`) and kept in SI: field = value * toSi.
template <class F>
KeySpec clinicalKey(std::string name, F field, double toSi, Range range, std::string unit, std::string doc) {
  KeySpec k = makeSpec(std::move(name), "number", std::move(unit), range.text(), std::move(doc));
  k.expect = withUnit("a finite number" + spaced(k.range), k.unit);
  k.bounds = range.bounds();
  k.set = [field, toSi, range, expect = k.expect](Scenario& s, const toml::node& n) {
    using T = std::remove_reference_t<decltype(field(s))>;
    field(s) = static_cast<T>(double(readReal(n, range, expect)) * toSi);
  };
  k.get = [field, toSi](const Scenario& s) { return formatReal(static_cast<Real>(double(fieldOf(field, s)) / toSi)); };
  addExactValue(k, field);
  return k;
}

// A number kept in the units the file gives it.
template <class F>
KeySpec realKey(std::string name, F field, Range range, std::string unit, std::string doc) {
  return clinicalKey(std::move(name), field, 1.0, range, std::move(unit), std::move(doc));
}

template <class F>
KeySpec intKey(std::string name, F field, std::int64_t lo, std::string unit, std::string doc,
               std::int64_t hi = std::numeric_limits<std::int64_t>::max()) {
  using T = std::remove_reference_t<decltype(field(std::declval<Scenario&>()))>;
  constexpr auto typeMax = static_cast<std::int64_t>(std::numeric_limits<T>::max());
  hi = std::min(hi, typeMax);
  KeySpec k =
      makeSpec(std::move(name), "integer", std::move(unit), intRangeText(lo, hi, typeMax), std::move(doc));
  // The message names the real limit even where the documented range leaves it out (the
  // field's type).
  k.expect = withUnit("an integer >= " + std::to_string(lo) + " and <= " + std::to_string(hi), k.unit);
  k.bounds = ScenarioKeyBounds{double(lo), double(hi), false, false, true, 1};
  k.set = [field, lo, hi, expect = k.expect](Scenario& s, const toml::node& n) {
    field(s) = static_cast<T>(readInt(n, lo, hi, expect));
  };
  k.get = [field](const Scenario& s) { return std::to_string(fieldOf(field, s)); };
  addExactValue(k, field);
  return k;
}

template <class F>
KeySpec boolKey(std::string name, F field, std::string doc) {
  KeySpec k = makeSpec(std::move(name), "boolean", "", "true or false", std::move(doc));
  k.expect = "true or false";
  k.set = [field](Scenario& s, const toml::node& n) {
    const auto* b = n.as_boolean();
    if (!b) throw ValueError{"expected true or false, got " + describeNode(n)};
    field(s) = b->get();
  };
  k.get = [field](const Scenario& s) { return std::string(fieldOf(field, s) ? "true" : "false"); };
  addExactValue(k, field);
  return k;
}

template <class F>
KeySpec stringKey(std::string name, F field, bool nonEmpty, std::string doc) {
  KeySpec k = makeSpec(std::move(name), "string", "", nonEmpty ? "not empty" : "any", std::move(doc));
  k.expect = nonEmpty ? "a non-empty string" : "a string";
  k.stringLike = true;
  k.set = [field, nonEmpty, expect = k.expect](Scenario& s, const toml::node& n) {
    const auto* str = n.as_string();
    if (!str) throw ValueError{"expected " + expect + ", got " + describeNode(n)};
    if (nonEmpty && str->get().empty()) throw ValueError{"must be " + expect + ", got \"\""};
    field(s) = str->get();
  };
  k.get = [field](const Scenario& s) { return quoteString(fieldOf(field, s)); };
  addExactValue(k, field);
  return k;
}

template <class F, class E>
KeySpec choiceKey(std::string name, F field, std::vector<std::pair<std::string, E>> options,
                  std::string doc) {
  std::string list;
  for (const auto& [text, value] : options) list += (list.empty() ? "" : ", ") + quoteString(text);
  KeySpec k = makeSpec(std::move(name), "string", "", list, std::move(doc));
  k.expect = "one of " + list;
  k.stringLike = true;
  k.set = [field, options, expect = k.expect](Scenario& s, const toml::node& n) {
    const auto* str = n.as_string();
    if (!str) throw ValueError{"expected " + expect + ", got " + describeNode(n)};
    for (const auto& [text, value] : options) {
      if (str->get() == text) {
        field(s) = value;
        return;
      }
    }
    throw ValueError{"must be " + expect + ", got " + describeNode(n)};
  };
  k.get = [field, options](const Scenario& s) {
    for (const auto& [text, value] : options)
      if (fieldOf(field, s) == value) return quoteString(text);
    return std::string("\"?\"");
  };
  addExactValue(k, field);
  return k;
}

// An array of 3 numbers, each within `range` (a position, a direction, an acceleration).
template <class F>
KeySpec vec3Key(std::string name, F field, Range range, std::string unit, std::string doc) {
  KeySpec k = makeSpec(std::move(name), "array of 3 numbers", std::move(unit), "each " + range.text(), std::move(doc));
  k.expect = withUnit("an array of 3 finite numbers, each " + range.text(), k.unit);
  k.bounds = range.bounds(false, 3);
  k.set = [field, range, expect = k.expect](Scenario& s, const toml::node& n) {
    const auto* a = n.as_array();
    if (!a) throw ValueError{"expected " + expect + ", got " + describeNode(n)};
    Vec3 v = Vec3::Zero();
    bool ok = a->size() == 3;
    for (std::size_t i = 0; ok && i < 3; ++i) {
      double x = 0;
      ok = numberOf(*a->get(i), x) && std::isfinite(x) && range.contains(x) && std::isfinite(static_cast<Real>(x));
      v[static_cast<Eigen::Index>(i)] = static_cast<Real>(x);
    }
    if (!ok) throw ValueError{"must be " + expect + ", got " + describeNode(n)};
    field(s) = v;
  };
  k.get = [field](const Scenario& s) {
    const Vec3& v = fieldOf(field, s);
    return "[" + formatReal(v.x()) + ", " + formatReal(v.y()) + ", " + formatReal(v.z()) + "]";
  };
  addExactValue(k, field);
  return k;
}

template <class F>
KeySpec intListKey(std::string name, F field, std::int64_t lo, std::int64_t hi, bool unique,
                   std::string doc) {
  using T = typename std::remove_reference_t<decltype(field(std::declval<Scenario&>()))>::value_type;
  constexpr auto typeMax = static_cast<std::int64_t>(std::numeric_limits<T>::max());
  hi = std::min(hi, typeMax);
  const std::string each = "an integer " + intRangeText(lo, hi, typeMax);
  KeySpec k =
      makeSpec(std::move(name), "array of integers", "",
               "each " + intRangeText(lo, hi, typeMax) + (unique ? ", no duplicates" : ""), std::move(doc));
  k.expect =
      "an array of integers, each " + intRangeText(lo, hi, typeMax) + (unique ? ", no duplicates" : "");
  k.set = [field, lo, hi, unique, each, expect = k.expect](Scenario& s, const toml::node& n) {
    const auto* a = n.as_array();
    if (!a) throw ValueError{"expected " + expect + ", got " + describeNode(n)};
    std::vector<T> out;
    std::set<std::int64_t> seen;
    for (const toml::node& e : *a) {
      const std::uint32_t line = e.source().begin.line;
      const auto* i = e.as_integer();
      if (!i) throw ValueError{"each entry must be " + each + ", got " + describeNode(e), line};
      if (i->get() < lo || i->get() > hi)
        throw ValueError{"each entry must be " + each + ", got " + describeNode(e), line};
      if (unique && !seen.insert(i->get()).second)
        throw ValueError{"must not contain duplicates, got " + describeNode(e) + " twice", line};
      out.push_back(static_cast<T>(i->get()));
    }
    field(s) = std::move(out);
  };
  k.get = [field](const Scenario& s) {
    std::string t = "[";
    for (const auto& v : fieldOf(field, s)) t += (t.size() > 1 ? ", " : "") + std::to_string(v);
    return t + "]";
  };
  addExactValue(k, field);
  return k;
}

}  // namespace hs::io::detail::builders
