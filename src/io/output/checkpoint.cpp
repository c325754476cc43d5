#include "io/output/checkpoint.h"

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "io/scenario/scenario_file.h"
#include "pbd/core/state_stream.h"

namespace hs::io {
namespace {

constexpr std::array<std::uint8_t, 8> kMagic{'H', 'S', 'C', 'K', '\r', '\n', 0x1a, '\n'};

std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const std::uint8_t b : bytes) {
    hash ^= b;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

CheckpointError fail(const std::string& source, const std::string& what) {
  return CheckpointError(source + ": " + what);
}

// The fixed header: magic, version and real size, each checked before anything after it.
void checkHeader(std::span<const std::uint8_t> bytes, const std::string& source) {
  const std::size_t magicBytes = std::min(bytes.size(), kMagic.size());
  if (!std::equal(bytes.begin(), bytes.begin() + std::ptrdiff_t(magicBytes), kMagic.begin()))
    throw fail(source, "bad magic: not a heartsim checkpoint (.hsck)");
  constexpr std::size_t kHeader = kMagic.size() + 8;
  if (bytes.size() < kHeader)
    throw fail(source, "truncated at byte " + std::to_string(bytes.size()) + " (inside the header of " +
                           std::to_string(kHeader) + " bytes)");
  std::uint32_t version = 0, realSize = 0;
  std::memcpy(&version, bytes.data() + 8, 4);
  std::memcpy(&realSize, bytes.data() + 12, 4);
  if (version != kCheckpointVersion)
    throw fail(source, "format version " + std::to_string(version) + "; this heartsim reads version " +
                           std::to_string(kCheckpointVersion));
  if (realSize != sizeof(pbd::Real))
    throw fail(source, "written with " + std::to_string(realSize) + "-byte reals; this heartsim build uses " +
                           std::to_string(sizeof(pbd::Real)) + "-byte reals (HS_DOUBLE)");
}

}  // namespace

Checkpoint captureCheckpoint(const cardiac::HeartSimulation& sim, const cardiac::RunMonitor* monitor) {
  Checkpoint c;
  c.scenarioToml = scenarioToToml(sim.scenario());
  pbd::StateWriter values;
  saveScenarioValues(sim.scenario(), values);
  c.scenarioValues = values.bytes();
  c.step = sim.stepCount();
  c.time = sim.time();
  pbd::StateWriter state;
  sim.save(state);
  c.simulation = state.bytes();
  if (monitor) {
    pbd::StateWriter watched;
    monitor->save(watched);
    c.monitor = watched.bytes();
  }
  return c;
}

std::vector<std::uint8_t> encodeCheckpoint(const Checkpoint& checkpoint) {
  pbd::StateWriter w;
  for (const std::uint8_t b : kMagic) w.put(b);
  w.fields(kCheckpointVersion, std::uint32_t(sizeof(pbd::Real)), checkpoint.scenarioToml, checkpoint.scenarioValues, checkpoint.step,
           checkpoint.time, checkpoint.simulation, checkpoint.monitor);
  std::vector<std::uint8_t> bytes = w.bytes();
  const std::uint64_t checksum = fnv1a(bytes);
  const auto* c = reinterpret_cast<const std::uint8_t*>(&checksum);
  bytes.insert(bytes.end(), c, c + sizeof checksum);
  return bytes;
}

Checkpoint decodeCheckpoint(std::span<const std::uint8_t> bytes, const std::string& source) {
  checkHeader(bytes, source);
  Checkpoint c;
  pbd::StateReader r(bytes.subspan(16));
  std::uint64_t checksum = 0;
  try {
    r.fields(c.scenarioToml, c.scenarioValues, c.step, c.time);
    c.simulationOffset = 16 + r.offset() + 8;
    r.get(c.simulation);
    c.monitorOffset = 16 + r.offset() + 8;
    r.fields(c.monitor, checksum);
  } catch (const pbd::StateError&) {
    throw fail(source, "truncated at byte " + std::to_string(bytes.size()) + " (the file ends inside its " +
                           (c.simulationOffset == 0 ? "scenario" : c.monitorOffset == 0 ? "simulation state" : "monitor state or checksum") +
                           ")");
  }
  const std::size_t end = 16 + r.offset();
  if (end != bytes.size())
    throw fail(source, std::to_string(bytes.size() - end) + " unexpected bytes after the checksum at byte " +
                           std::to_string(end - 8));
  const std::uint64_t computed = fnv1a(bytes.first(end - 8));
  if (computed != checksum)
    throw fail(source, "checksum mismatch (stored " + hex(checksum) + ", computed " + hex(computed) +
                           "): the file is corrupt");
  return c;
}

void writeCheckpointFile(const std::filesystem::path& path, const Checkpoint& checkpoint) {
  const std::vector<std::uint8_t> bytes = encodeCheckpoint(checkpoint);
  std::filesystem::path partial = path;
  partial += ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) throw CheckpointError(path.string() + ": cannot write the checkpoint (disk full or no permission?)");
  }
  std::error_code ec;
  std::filesystem::rename(partial, path, ec);
  if (ec) throw CheckpointError(path.string() + ": cannot write the checkpoint: " + ec.message());
}

Checkpoint readCheckpointFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path.string() + ": cannot open the checkpoint (no such file?)");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw CheckpointError(path.string() + ": cannot read the checkpoint");
  return decodeCheckpoint(bytes, path.string());
}

cardiac::Scenario checkpointScenario(const Checkpoint& checkpoint, const std::string& source) {
  cardiac::Scenario scenario;
  try {
    scenario = parseScenario(checkpoint.scenarioToml, source);
  } catch (const ScenarioError& e) {
    throw CheckpointError(source + ": the checkpoint's scenario: " + e.what());
  }
  pbd::StateReader r(checkpoint.scenarioValues);
  try {
    loadScenarioValues(scenario, r);
    if (!r.atEnd()) throw pbd::StateError("more scenario values than keys", r.offset());
  } catch (const pbd::StateError& e) {
    throw fail(source, std::string("the checkpoint's scenario values: ") + e.what());
  }
  return scenario;
}

void restoreSimulation(const Checkpoint& checkpoint, cardiac::HeartSimulation& sim, const std::string& source) {
  pbd::StateReader r(checkpoint.simulation);
  try {
    sim.load(r);
    if (!r.atEnd()) throw pbd::StateError("more simulation state than the scenario has", r.offset());
  } catch (const pbd::StateError& e) {
    throw fail(source, std::string("state does not fit the scenario at byte ") +
                           std::to_string(checkpoint.simulationOffset + e.offset) + ": " + e.what());
  }
}

void restoreMonitor(const Checkpoint& checkpoint, cardiac::RunMonitor& monitor, const std::string& source) {
  if (checkpoint.monitor.empty()) return;
  pbd::StateReader r(checkpoint.monitor);
  try {
    monitor.load(r);
    if (!r.atEnd()) throw pbd::StateError("more monitor state than this run gathers", r.offset());
  } catch (const pbd::StateError& e) {
    throw fail(source, std::string("monitor state does not fit at byte ") +
                           std::to_string(checkpoint.monitorOffset + e.offset) + ": " + e.what());
  }
}

std::string checkpointFileName(double time) {
  char text[64];
  std::snprintf(text, sizeof text, "checkpoint_%08.3fs.hsck", time);
  return text;
}

}  // namespace hs::io
