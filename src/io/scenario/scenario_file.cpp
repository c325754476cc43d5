// Scenario files: parse TOML, walk it against the key table, apply --set overrides.
#include "io/scenario/scenario_file.h"
#include "io/scenario/toml_text.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <fstream>
#include <iterator>
#include <limits>

#include "cardiac/anatomy/lv_model.h"
#include "io/mesh/patient_surfaces.h"
#include "io/mesh/recorded_frames.h"
#include "io/scenario/scenario_internal.h"

namespace hs::io {
namespace {

using cardiac::Scenario;
using detail::KeySpec;
using detail::TableSpec;
using detail::ValueError;

using pbd::Real;

// Messages are one line: newlines (e.g. from a parser description) become spaces.
[[noreturn]] void fail(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  throw ScenarioError(message);
}

std::string quoteOrEmpty(const std::string& text) { return text.empty() ? "nothing" : "'" + text + "'"; }

std::uint32_t lineOf(const toml::node& node) {
  std::uint32_t line = node.source().begin.line;
  if (line == 0) {
    if (const auto* t = node.as_table()) {
      for (auto&& [k, v] : *t) {
        const std::uint32_t l = k.source().begin.line != 0 ? k.source().begin.line : lineOf(v);
        if (l != 0 && (line == 0 || l < line)) line = l;
      }
    }
  }
  return line;
}

// Where an entry came from: "file:line" or "--set KEY=VALUE".
struct Origin {
  std::string source;  // file name, or the whole "--set ..." text
  bool isFile = true;
  std::string at(std::uint32_t line) const {
    return isFile && line != 0 ? source + ":" + std::to_string(line) : source;
  }
};

struct ParseState {
  Scenario scenario;
  std::string sphereOrigin;  // where [cycle.sphere] was enabled, for the final check
  std::string source;        // the file (or built-in) name
  std::map<std::string, std::string, std::less<>> keyOrigin;  // "file:line" of each key set
  std::filesystem::path fileDir;  // the scenario file's folder: relative paths start there
  std::map<std::string, std::filesystem::path, std::less<>> keyDir;  // per key set: where its paths start

  // Where `key` was last set, or the file name when it kept its default.
  std::string at(std::string_view key) const {
    const auto it = keyOrigin.find(key);
    return it != keyOrigin.end() ? it->second : source;
  }
};

// Calls onPresent of every known table that is `dotted` or a prefix of it.
void markPresent(ParseState& st, std::string_view dotted, const std::string& where) {
  for (const TableSpec& t : detail::tableTable()) {
    const bool prefix = dotted.size() > t.name.size() && dotted.substr(0, t.name.size()) == t.name &&
                        dotted[t.name.size()] == '.';
    if ((dotted == t.name || prefix) && t.onPresent) {
      t.onPresent(st.scenario);
      if (t.name == "cycle.sphere" && st.sphereOrigin.empty()) st.sphereOrigin = where;
    }
  }
}

void applyLeaf(ParseState& st, const std::string& dotted, const toml::node& node, std::uint32_t line,
               const Origin& origin) {
  const KeySpec* spec = detail::findKey(dotted);
  if (!spec) {
    if (detail::findTable(dotted))
      fail(origin.at(line) + ": " + dotted + ": expected a table, got " + detail::describeNode(node));
    fail(origin.at(line) + ": " + dotted + ": unknown " + (node.is_table() ? "table" : "key") +
         detail::nearMiss(dotted));
  }
  try {
    spec->set(st.scenario, node);
  } catch (const ValueError& e) {
    fail(origin.at(e.line != 0 ? e.line : line) + ": " + dotted + ": " + e.message);
  }
  st.keyOrigin[dotted] = origin.at(line);
  st.keyDir[dotted] = origin.isFile ? st.fileDir : std::filesystem::path();  // --set: the working directory
  markPresent(st, dotted, origin.at(line));
}

struct Entry {
  std::string key;
  const toml::node* node;
  std::uint32_t line;
  bool isTable;  // a known table (its keys are separate entries)
};

void flatten(const toml::table& table, const std::string& prefix, std::vector<Entry>& out) {
  for (auto&& [k, v] : table) {
    // A quoted key with a dot ("simulation.dt" = 1) is not the dotted key: keep its quotes.
    std::string part(k.str());
    if (part.empty() || part.find_first_of(". \t\"") != std::string::npos) part = detail::quoteString(part);
    const std::string dotted = prefix.empty() ? part : prefix + "." + part;
    std::uint32_t line = k.source().begin.line;
    if (line == 0) line = lineOf(v);
    const bool knownTable = detail::findTable(dotted) != nullptr && v.is_table();
    out.push_back({dotted, &v, line, knownTable});
    if (knownTable) flatten(*v.as_table(), dotted, out);
  }
}

// Applies every entry of `table` (whose own dotted name is `prefix`), in file order so the first
// error reported is the first in the file.
void applyTable(ParseState& st, const toml::table& table, const std::string& prefix, const Origin& origin) {
  std::vector<Entry> entries;
  flatten(table, prefix, entries);
  std::stable_sort(entries.begin(), entries.end(),
                   [](const Entry& a, const Entry& b) { return a.line < b.line; });
  for (const Entry& e : entries) {
    if (e.isTable)
      markPresent(st, e.key, origin.at(e.line));
    else
      applyLeaf(st, e.key, *e.node, e.line, origin);
  }
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return std::string(s.substr(b, e - b + 1));
}

void applyOverride(ParseState& st, const std::string& text) {
  const Origin origin{"--set " + text, false};
  const auto eq = text.find('=');
  const std::string key = eq == std::string::npos ? "" : trim(std::string_view(text).substr(0, eq));
  if (key.empty()) fail(origin.source + ": expected KEY=VALUE, e.g. --set simulation.dt=0.001");
  const std::string value = trim(std::string_view(text).substr(eq + 1));
  const KeySpec* spec = detail::findKey(key);
  const TableSpec* table = detail::findTable(key);
  if (!spec && !table) fail(origin.source + ": " + key + ": unknown key" + detail::nearMiss(key));

  // VALUE as a TOML value: the document "x = VALUE" must hold exactly that one key.
  toml::table doc;
  const toml::node* node = nullptr;
  try {
    const std::string wrapped = "x = " + value;
    doc = toml::parse(std::string_view(wrapped), std::string_view("--set"));
    if (doc.size() == 1) node = doc.get("x");
  } catch (const toml::parse_error&) {
    node = nullptr;
  }
  if (spec) {
    // A bare word is a string (--set scenario.name=mine); a quoted one must be TOML's whole.
    const bool quoted = !value.empty() && (value.front() == '"' || value.front() == '\'');
    if (spec->stringLike && quoted && !node)
      fail(origin.source + ": " + key + ": the string " + value +
           " has no closing quote; expected it quoted whole or not at all");
    if (spec->stringLike && (!node || !node->is_string())) {
      applyLeaf(st, key, toml::value<std::string>(value), 0, origin);
      return;
    }
    if (!node) fail(origin.source + ": " + key + ": expected " + spec->expect + ", got '" + value + "'");
    applyLeaf(st, key, *node, 0, origin);
    return;
  }
  if (!node || !node->is_table())
    fail(origin.source + ": " + key + ": expected an inline table, e.g. {key = value}, got '" + value + "'");
  markPresent(st, key, origin.source);
  applyTable(st, *node->as_table(), key, origin);
}

// Blood settings the scene cannot hold, refused before any work. Gravity: from rest, one step
// moves a particle g dt^2; beyond a tenth of the spacing the density solve cannot keep up and
// blood is lost through the walls. Support radius: a kernel wider than the space the blood
// lives in (the container's smallest side, the cavity's short-axis radius) makes every
// particle everybody's neighbour.
void validateBloodScale(const ParseState& st) {
  const cardiac::Scenario& sc = st.scenario;
  const auto& b = sc.blood;
  auto number = [](double v) { return detail::formatNumber(v); };
  const double dt = double(sc.simulation.dt);
  const double gravityMax = 0.1 * double(b.spacing) / (dt * dt);
  if (double(sc.simulation.gravity.norm()) > gravityMax)
    fail(st.at("simulation.gravity") + ": simulation.gravity: |g| = " + number(double(sc.simulation.gravity.norm())) +
         " m/s^2 moves blood more than a tenth of blood.spacing in one step of simulation.dt; expected |g| <= 0.1 "
         "spacing / dt^2 = " + number(gravityMax) + " m/s^2");
  double room = std::numeric_limits<double>::infinity();
  std::string where;
  if (sc.container.enabled) {
    room = double((sc.container.max - sc.container.min).minCoeff());
    where = "the container's smallest side";
  } else if (sc.heart) {
    room = double(sc.geometry.endoRadius);
    where = "the cavity's radius (model.endo_radius)";
  }
  if (double(b.supportRadius) > room)
    fail(st.at("blood.support_radius") + ": blood.support_radius: must not exceed " + where + " (" + number(room) +
         " m), got " + number(double(b.supportRadius)) + " m");
}

// The thesis's beat moves each beating vertex cycle.beating_displace inward every systolic step;
// a step that carries a vertex past its neighbours inverts the tets between them before the
// constraints can answer. Over 20 steps (docs/reliability.md) 0.45 of the wall's edge beats on
// heart-only at resolutions 1 to 8 and on paper-chamber-beating at 8, while half of it inverts a
// tet on heart-only at 8 and its own 0.08 m inverted tets at 4 and above. Checked for the
// procedural heart, whose edge the reader knows.
constexpr double kMaxDisplaceInEdges = 0.45;

void validateBeatingDisplace(const ParseState& st) {
  const cardiac::Scenario& sc = st.scenario;
  const auto& c = sc.cycle;
  // The lumped circulation drives the wall by its volume, never by this step (and refuses thesis
  // timing itself, with its own message).
  if (!sc.heart || sc.patient.kind != cardiac::ModelKind::Procedural || !c.enabled ||
      c.mode != cardiac::TimingMode::Thesis || sc.circulation.lumped)
    return;
  const double edge = cardiac::nominalEdgeLength(sc.geometry);
  const double limit = kMaxDisplaceInEdges * edge;
  if (double(c.beatingDisplace) > limit)
    fail(st.at("cycle.beating_displace") + ": cycle.beating_displace: " + detail::formatReal(c.beatingDisplace) +
         " m per step inverts the wall's tets; expected at most " + detail::formatNumber(kMaxDisplaceInEdges) +
         " of its edge, 0.21 model.endo_radius / model.resolution = " + detail::formatReal(Real(edge)) + " m: " +
         detail::formatReal(Real(limit)) + " m");
}

// Checks that involve more than one key.
void validate(const ParseState& st) {
  validateBeatingDisplace(st);
  const auto& c = st.scenario.cycle;
  if (c.sphereEnabled && !(c.sphereRadius > 0))
    fail(st.sphereOrigin + ": cycle.sphere.radius: required when [cycle.sphere] is used, expected " +
         detail::findKey("cycle.sphere.radius")->expect + ", got nothing");
  const auto& b = st.scenario.blood;
  auto number = [](pbd::Real v) { return detail::formatReal(v); };  // as the file gave it
  if (b.supportRadius <= b.spacing)
    fail(st.at("blood.support_radius") + ": blood.support_radius: must be larger than blood.spacing (" +
         number(b.spacing) + " m) so that each particle has neighbours, got " + number(b.supportRadius) + " m");
  // The walls keep each particle a radius away; a radius beyond the spacing its lattice gives it
  // overlaps its neighbours and, as it nears the cavity's size, leaves the blood no room.
  if (b.radius > b.spacing)
    fail(st.at("blood.radius") + ": blood.radius: must not exceed blood.spacing (" + number(b.spacing) +
         " m), the room each particle has; got " + number(b.radius) + " m");
  // A radius under half the spacing lets the wall's push-out hold particles closer than their
  // lattice: dilated-cardiomyopathy lost blood through its wall within 12 steps at 0.45 of its
  // spacing, anterior-infarct at 0.1. Half is the thesis's and every built-in's.
  if (b.radius < Real(0.5) * b.spacing)
    fail(st.at("blood.radius") + ": blood.radius: must be at least half blood.spacing (" +
         number(Real(0.5) * b.spacing) + " m) to keep the blood off the wall; got " + number(b.radius) + " m");
  if (b.enabled) validateBloodScale(st);
  for (int a = 0; a < 3; ++a) {
    if (b.blockMax[a] <= b.blockMin[a])
      fail(st.at("blood.block_max") + ": blood.block_max: must be larger than blood.block_min on every axis, got " +
           detail::findKey("blood.block_max")->get(st.scenario) + " and " +
           detail::findKey("blood.block_min")->get(st.scenario));
    const auto& box = st.scenario.container;
    if (box.max[a] <= box.min[a])
      fail(st.at("container.max") + ": container.max: must be larger than container.min on every axis, got " +
           detail::findKey("container.max")->get(st.scenario) + " and " +
           detail::findKey("container.min")->get(st.scenario));
  }
}

// A path set by `key`, made absolute from where the key was set: the scenario file's folder,
// or the working directory for --set.
std::string pathFromKey(const ParseState& st, const char* key, const std::string& path) {
  const auto dir = st.keyDir.find(key);
  const std::filesystem::path base = dir != st.keyDir.end() ? dir->second : std::filesystem::path();
  std::error_code ec;
  const std::filesystem::path full = std::filesystem::absolute(base / path, ec);
  return (ec ? base / path : full).lexically_normal().string();
}

// [model] kind = "mesh": the paths made absolute from where each was set (the scenario file's
// folder, or the working directory for --set), the unset wall thickness a real heart's, and
// the files read, so that a missing or bad mesh stops the run here with its key.
void resolveMeshModel(ParseState& st) {
  cardiac::PatientModelSettings& p = st.scenario.patient;
  if (p.kind != cardiac::ModelKind::Mesh) return;
  const std::pair<const char*, std::string*> paths[] = {
      {"model.endocardium", &p.endocardium}, {"model.epicardium", &p.epicardium}, {"model.volume_mesh", &p.volumeMesh}};
  for (const auto& [key, path] : paths)
    if (!path->empty()) *path = pathFromKey(st, key, *path);
  const std::string kindAt = st.at("model.kind") + ": ";
  if (p.endocardium.empty() == p.volumeMesh.empty())
    fail(kindAt + "model.endocardium: expected exactly one of model.endocardium (a surface file) and "
                  "model.volume_mesh when model.kind = \"mesh\", got " +
         (p.endocardium.empty() ? "neither" : "both"));
  if (!p.volumeMesh.empty() && !p.epicardium.empty())
    fail(st.at("model.epicardium") + ": model.epicardium: expected no epicardium file with model.volume_mesh "
                                     "(its markers give the epicardium), got " + quoteOrEmpty(p.epicardium));
  if (st.keyOrigin.find("model.wall_thickness") == st.keyOrigin.end()) st.scenario.geometry.wallThickness = Real(0.010);
  const double t = double(st.scenario.geometry.wallThickness);
  if (!(t >= 0.002 && t <= 0.03))
    fail(st.at("model.wall_thickness") + ": model.wall_thickness: must be within [0.002, 0.03] m for a patient's "
                                         "wall (model.kind = \"mesh\"), got " + detail::formatNumber(t));
  // A patient's blood starts in its cavity and vessels, full at rest (heart_sites.h): the other
  // starts are laid out for the procedural heart. Unset, the start is that one.
  cardiac::BloodSettings& blood = st.scenario.blood;
  if (blood.enabled && st.keyOrigin.find("blood.start") == st.keyOrigin.end())
    blood.start = cardiac::BloodSettings::Start::Heart;
  if (blood.enabled && blood.start != cardiac::BloodSettings::Start::Heart)
    fail(st.at("blood.start") + ": blood.start: expected \"heart\" with model.kind = \"mesh\" (a patient's cavity "
                                "and vessels filled at rest; the other starts are laid out for the procedural "
                                "heart), got " + detail::findKey("blood.start")->get(st.scenario));
  // Blood enters and leaves a patient's ventricle by vessels on its annuli (patient_vessels.h),
  // sized as a real heart's unless the scenario says (the procedural defaults are the thesis's).
  struct VesselKey {
    const char* key;
    Real* value;
    double unset, lo, hi;  // m
  };
  const VesselKey vesselKeys[] = {
      {"model.inflow_vessel_length", &st.scenario.geometry.inflowVesselLength, 0.03, 0.01, 0.1},
      {"model.outflow_vessel_length", &st.scenario.geometry.outflowVesselLength, 0.03, 0.01, 0.1},
      {"model.vessel_wall_thickness", &st.scenario.geometry.vesselWallThickness, 0.002, 0.0005, 0.005}};
  for (const auto& [key, value, unset, lo, hi] : vesselKeys) {
    if (!blood.enabled) break;  // no blood, no vessels
    if (st.keyOrigin.find(key) == st.keyOrigin.end()) *value = Real(unset);
    const double v = double(*value);
    if (!(v >= lo && v <= hi))
      fail(st.at(key) + ": " + key + ": must be within [" + detail::formatNumber(lo) + ", " +
           detail::formatNumber(hi) + "] m for a patient's vessels (model.kind = \"mesh\"), got " +
           detail::formatNumber(v));
  }
  if (st.scenario.circulation.lumped)
    fail(st.at("circulation.lumped") + ": circulation.lumped: expected false with model.kind = \"mesh\" (a "
                                       "patient's heart beats with heartsim's own cycle for now), got true");
  const char* key = p.volumeMesh.empty() ? "model.endocardium" : "model.volume_mesh";
  try {
    io::readPatientModelFiles(p);
  } catch (const std::invalid_argument& e) {
    fail(st.at(key) + std::string(": ") + key + ": " + e.what());
  }
  // Where only the heart's scale matters (the pictures' colour scales, the viewer's thesis or
  // human grouping, the blood's support radius against the cavity), the procedural sizes stand
  // for the patient's: the endocardium's extent, the longest as the long axis and half the
  // middle one as the radius. The model itself measures its own (patient_lv_model.h).
  if (!p.endocardiumSurface.vertices.empty()) {
    pbd::Vec3 lo = p.endocardiumSurface.vertices.front(), hi = lo;
    for (const pbd::Vec3& v : p.endocardiumSurface.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    std::array<double, 3> extent{};
    for (int a = 0; a < 3; ++a) extent[std::size_t(a)] = double(hi[a] - lo[a]) * cardiac::metresPer(p.units);
    std::sort(extent.begin(), extent.end());
    cardiac::LvGeometryParams& g = st.scenario.geometry;
    g.endoLongAxis = Real(extent[2]);
    g.endoRadius = Real(0.5 * extent[1]);
    g.baseThickness = g.wallThickness;
  }
  if (st.scenario.blood.enabled) validateBloodScale(st);  // again, against the patient's cavity
}

// [motion]: a recorded beat drives a patient's heart and sets its timing (the cycle's heart rate,
// systolic fraction and contraction are not used, docs/scenarios.md); what would contradict it
// (another pattern, a beat count, parts that beat alone) is refused. The frames are read here,
// each checked against the endocardium, so that a bad frame stops the run with its key.
void resolveMotion(ParseState& st) {
  cardiac::MotionSettings& m = st.scenario.motion;
  if (m.frames.empty()) return;
  const std::string at = st.at("motion.frames") + ": motion.frames: ";
  const cardiac::PatientModelSettings& p = st.scenario.patient;
  if (p.kind != cardiac::ModelKind::Mesh)
    fail(at + "a recorded beat drives a patient's heart; expected model.kind = \"mesh\", got \"procedural\"");
  if (m.count < 2)
    fail(st.at("motion.count") + ": motion.count: expected at least 2 frames with motion.frames, got " +
         std::to_string(m.count));
  if (!(double(m.period) >= 0.24))
    fail(st.at("motion.period") + ": motion.period: expected at least 0.24 s (250 bpm) with motion.frames, got " +
         detail::formatNumber(double(m.period)));
  const cardiac::CycleSettings& c = st.scenario.cycle;
  if (!c.enabled || c.pattern != cardiac::BeatPattern::Normal || c.beats != 0)
    fail(st.at(!c.enabled ? "cycle.enabled" : c.pattern != cardiac::BeatPattern::Normal ? "cycle.pattern" : "cycle.beats") +
         ": cycle: the recorded beat repeats as recorded; expected cycle.enabled = true, pattern = \"normal\" and "
         "beats = 0 with motion.frames");
  if (!c.segments.empty() || !c.vertices.empty() || c.sphereEnabled)
    fail(st.at(!c.segments.empty() ? "cycle.segments" : !c.vertices.empty() ? "cycle.vertices" : "cycle.sphere") +
         ": cycle: the recorded beat moves the whole endocardium; expected no cycle.segments, cycle.vertices or "
         "[cycle.sphere] with motion.frames");
  m.frames = pathFromKey(st, "motion.frames", m.frames);
  try {
    m.frameSurfaces = io::readRecordedFrames(m.frames, m.count, p.endocardiumSurface,
                                             p.volumeMesh.empty() ? p.endocardium : p.volumeMesh, p.markerEndocardium);
  } catch (const std::invalid_argument& e) {
    fail(at + e.what());
  }
}

std::string builtinList() {
  std::string list;
  for (const auto& e : detail::embeddedScenarios()) list += (list.empty() ? "" : ", ") + std::string(e.name);
  return list.empty() ? "none" : list;
}

}  // namespace

namespace {

Scenario parseScenarioIn(std::string_view tomlText, const std::string& sourceName,
                         const std::vector<std::string>& overrides, const std::filesystem::path& fileDir) {
  ParseState st;
  st.source = sourceName;
  st.fileDir = fileDir;
  const std::string stem = std::filesystem::path(sourceName).stem().string();
  if (!stem.empty()) st.scenario.name = stem;

  io::TomlText parsed = io::parseTomlText(tomlText, sourceName);
  if (!parsed.error.empty()) fail(parsed.error);
  const toml::table& root = parsed.table;
  applyTable(st, root, "", Origin{sourceName, true});
  for (const std::string& o : overrides) applyOverride(st, o);
  validate(st);
  resolveMeshModel(st);
  resolveMotion(st);
  return st.scenario;
}

}  // namespace

Scenario parseScenario(std::string_view tomlText, const std::string& sourceName,
                       const std::vector<std::string>& overrides) {
  return parseScenarioIn(tomlText, sourceName, overrides, std::filesystem::path(sourceName).parent_path());
}

std::vector<std::string> builtinScenarioNames() {
  std::vector<std::string> names;
  for (const auto& e : detail::embeddedScenarios()) names.emplace_back(e.name);
  std::sort(names.begin(), names.end());
  return names;
}

std::string builtinScenarioText(const std::string& name) {
  for (const auto& e : detail::embeddedScenarios())
    if (e.name == name) return std::string(e.text);
  fail("no such built-in scenario: '" + name + "' (built-ins: " + builtinList() + ")");
}

Scenario loadScenario(const std::string& nameOrPath, const std::vector<std::string>& overrides) {
  for (const auto& e : detail::embeddedScenarios())
    // A built-in's relative paths (its meshes) start in the source tree's scenarios folder,
    // from whatever directory heartsim runs in.
    if (e.name == nameOrPath)
      return parseScenarioIn(e.text, "scenarios/" + nameOrPath + ".toml", overrides, HS_SCENARIO_SOURCE_DIR);

  std::error_code ec;
  const std::filesystem::path path(nameOrPath);
  if (nameOrPath.empty() || !std::filesystem::exists(path, ec))
    fail("no such scenario file or built-in scenario: '" + nameOrPath + "' (built-ins: " + builtinList() +
         ")");
  if (!std::filesystem::is_regular_file(path, ec)) fail(nameOrPath + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(nameOrPath + ": cannot open the file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) fail(nameOrPath + ": cannot read the file");
  return parseScenario(text, nameOrPath, overrides);
}

std::vector<ScenarioKeyInfo> scenarioKeys() {
  const Scenario defaults;
  std::vector<ScenarioKeyInfo> out;
  for (const KeySpec& k : detail::keyTable())
    out.push_back({k.name, k.type, k.unit, k.range, k.get(defaults), k.doc, k.bounds});
  return out;
}

std::string scenarioToToml(const Scenario& scenario) {
  std::string out;
  std::string currentTable;
  for (const KeySpec& k : detail::keyTable()) {
    const auto dot = k.name.rfind('.');
    const std::string table = k.name.substr(0, dot);
    const TableSpec* t = detail::findTable(table);
    if (t && t->written && !t->written(scenario)) continue;
    if (table != currentTable) {
      out += (out.empty() ? "[" : "\n[") + table + "]\n";
      currentTable = table;
    }
    out += k.name.substr(dot + 1) + " = " + k.get(scenario) + "\n";
  }
  return out;
}

}  // namespace hs::io
