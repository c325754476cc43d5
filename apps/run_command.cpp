#include "run_command.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "exit_codes.h"
#include "io/output/circulation_plots.h"
#include "io/output/metrics_csv.h"
#include "io/output/output_paths.h"
#include "io/output/run_report.h"
#include "io/output/simulation_vtk.h"
#include "progress_bar.h"
#include "run_resume.h"
#include "simulation_setup.h"

namespace hs::app {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The scenario with --duration applied; nullopt after printing the error.
std::optional<cardiac::Scenario> runScenario(const RunOptions& options) {
  std::optional<cardiac::Scenario> scenario =
      loadScenarioOrReport(options.scenario, options.overrides, options.resolution);
  if (!scenario || !options.duration) return scenario;
  if (!std::isfinite(*options.duration) || *options.duration < 0) {
    std::cerr << "heartsim: error: --duration: must be a finite number >= 0 (s), got " << *options.duration << '\n';
    return std::nullopt;
  }
  scenario->simulation.duration = static_cast<pbd::Real>(*options.duration);
  return scenario;
}

// The output directory and metrics.csv with its header; nullopt after printing the error.
std::optional<io::MetricsCsvFile> openOutputs(const fs::path& outDir, const cardiac::HeartSimulation& sim) {
  if (!createOutputDirOrReport(outDir)) return std::nullopt;
  try {
    return io::MetricsCsvFile(outDir / "metrics.csv", {sim.hasHeart(), sim.hasBlood(), sim.circulation() != nullptr, sim.lumped() != nullptr});
  } catch (const std::runtime_error& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return std::nullopt;
  }
}

// duration / dt, or nullopt after printing why the run would be too long.
std::optional<std::int64_t> stepCountOrReport(const cardiac::Scenario& scenario, const std::string& source) {
  const double stepCount = std::round(double(scenario.simulation.duration) / double(scenario.simulation.dt));
  constexpr double kMaxSteps = 1e9;
  if (stepCount > kMaxSteps) {
    std::cerr << "heartsim: error: " << source << ": simulation.duration / simulation.dt = " << stepCount
              << " steps, more than " << kMaxSteps << "; shorten the duration or lengthen dt\n";
    return std::nullopt;
  }
  return static_cast<std::int64_t>(stepCount);
}

// Where and how often a run writes checkpoints (every `every` steps of the whole run, so a
// resumed run writes them at the same times; 0: none).
struct CheckpointPlan {
  fs::path folder;
  std::int64_t every = 0;
};

// Steps to the end, a metrics row per step, a VTK frame every vtkEvery steps and a checkpoint
// as planned; stops at the first failed health check. Times the steps alone into wallSeconds.
int simulate(cardiac::HeartSimulation& sim, cardiac::RunMonitor& monitor, std::int64_t steps,
             io::MetricsCsvFile& csv, io::SimulationVtkSeries* vtk, int vtkEvery, const CheckpointPlan& checkpoints,
             double& wallSeconds) {
  ProgressBar progress(static_cast<long>(steps));
  try {
    if (vtk) vtk->write(sim, sim.stepCount());
    for (std::int64_t s = 0; s < steps; ++s) {
      const auto stepStart = Clock::now();
      sim.step();
      wallSeconds += secondsSince(stepStart);
      if (const cardiac::Verdict& verdict = monitor.observe(); !verdict.healthy()) {
        progress.finish();
        std::cerr << "heartsim: error: " << verdict.message() << '\n';
        monitor.finish();
        csv.close();  // the rows up to the failure stay readable
        return kExitInvalidSimulation;
      }
      csv.add(monitor.last());
      if (vtk && sim.stepCount() % vtkEvery == 0) vtk->write(sim, sim.stepCount());
      if (checkpoints.every > 0 && sim.stepCount() % checkpoints.every == 0)
        io::writeCheckpointFile(checkpoints.folder / io::checkpointFileName(sim.time()),
                                io::captureCheckpoint(sim, &monitor));
      progress.update(static_cast<long>(s + 1), sim.time());
    }
    progress.finish();
    monitor.finish();
    if (vtk) vtk->finish();
    csv.close();
  } catch (const std::runtime_error& e) {
    progress.finish();
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
  return kExitOk;
}

// The heart's sizes at rest, measured on its model (none without a heart).
std::optional<cardiac::AnatomyFigures> anatomyOf(const cardiac::HeartSimulation& sim) {
  if (!sim.hasHeart()) return std::nullopt;
  return cardiac::measureAnatomy(sim.model());
}

// A run that became invalid still leaves its summary.json, with what failed, where and when
// under "failure"; stdout stays empty and the exit code says it failed.
void writeFailureSummary(const cardiac::Scenario& scenario, const io::RunTiming& timing,
                         const cardiac::RunMonitor& monitor, const cardiac::HeartSimulation& sim,
                         const fs::path& outDir) {
  const std::optional<cardiac::AnatomyFigures> anatomy = anatomyOf(sim);
  nlohmann::ordered_json report =
      io::runReport(scenario, timing, monitor.summary(), outDir.string(), anatomy ? &*anatomy : nullptr);
  const cardiac::Verdict& verdict = monitor.verdict();
  report["failure"] = {{"message", verdict.message()}, {"step", verdict.step}, {"time_s", verdict.time}};
  std::ofstream summary(outDir / "summary.json");
  summary << report.dump(2) << '\n';
  if (!summary) std::cerr << "heartsim: error: " << (outDir / "summary.json").string() << ": write failed\n";
}

// With the lumped circulation: the last complete beat's pressure-volume loop (between its
// end-systolic and end-diastolic relations) and its Wiggers diagram, beside metrics.csv.
// Nothing is drawn before a beat has completed.
bool writeCirculationPlots(const cardiac::Scenario& scenario, const cardiac::HeartSimulation& sim,
                           const cardiac::RunMonitor& monitor, const fs::path& outDir) {
  const cardiac::CirculationRecorder* recorder = monitor.circulation();
  if (!recorder) return true;
  const std::vector<cardiac::CirculationSample> beat = io::lastCompleteBeat(recorder->samples(), recorder->beatStarts());
  if (beat.size() < 2) return true;
  try {
    const cardiac::PressureVolumeRelations relations = sim.lumped()->relations(sim.drivenWall()->beatingShare());
    io::writePvLoopPng((outDir / "pv_loop.png").string(), {{scenario.name, beat}}, relations,
                       scenario.name + ": pressure-volume loop");
    io::writeWiggersPng((outDir / "wiggers.png").string(), beat, scenario.name + ": one beat (Wiggers diagram)");
  } catch (const std::exception& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return false;
  }
  return true;
}

// summary.json, then the same report on stdout (--json) or one line on stderr.
int report(const cardiac::Scenario& scenario, const io::RunTiming& timing, const cardiac::RunMonitor& monitor,
           const cardiac::HeartSimulation& sim, const fs::path& outDir, bool json) {
  const cardiac::RunSummary run = monitor.summary();
  const std::optional<cardiac::AnatomyFigures> anatomy = anatomyOf(sim);
  const nlohmann::ordered_json report =
      io::runReport(scenario, timing, run, outDir.string(), anatomy ? &*anatomy : nullptr);
  std::ofstream summary(outDir / "summary.json");
  summary << report.dump(2) << '\n';
  if (!summary) {
    std::cerr << "heartsim: error: " << (outDir / "summary.json").string() << ": write failed\n";
    return kExitFailure;
  }
  if (json) return writeStdoutOrReport(report.dump()) ? kExitOk : kExitFailure;
  std::cerr << "heartsim: " << io::runSummaryLine(scenario, timing, run, outDir.string()) << '\n';
  return kExitOk;
}

}  // namespace

int runCommand(const RunOptions& options) {
  const auto setupStart = Clock::now();
  std::optional<ResumedRun> resumed;
  if (!options.resume.empty() && !options.resolution.empty()) {
    std::cerr << "heartsim: error: --resolution: a resumed run goes on with the checkpoint's blood; leave it out\n";
    return kExitBadInput;
  }
  if (!options.resume.empty() && !(resumed = readResumedRun(options))) return kExitBadInput;
  const std::optional<cardiac::Scenario> scenario = resumed ? resumed->scenario : runScenario(options);
  if (!scenario) return kExitBadInput;
  const std::optional<std::int64_t> checkpointEvery = checkpointIntervalOrReport(options, *scenario);
  if (!checkpointEvery) return kExitBadInput;
  io::RunTiming timing;
  timing.threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  int setupError = kExitOk;
  const std::string source = resumed ? options.resume : options.scenario;
  const auto sim = makeSimulation(*scenario, timing.threads, source, setupError);
  if (!sim) return setupError;
  try {
    if (resumed) io::restoreSimulation(resumed->checkpoint, *sim, options.resume);
  } catch (const io::CheckpointError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitBadInput;
  }
  timing.setupSeconds = secondsSince(setupStart);
  // The summary counts the steps its monitor watched: the whole run's when the checkpoint holds
  // the monitor's state (`heartsim run`), those after the checkpoint when not (the viewer's).
  if (resumed && !resumed->checkpoint.monitor.empty()) timing.resumedAtStep = sim->stepCount();

  const fs::path outDir = options.outDir.empty() ? io::defaultOutputFolder(scenario->name) : fs::path(options.outDir);
  std::optional<io::MetricsCsvFile> csv = openOutputs(outDir, *sim);
  if (!csv) return kExitFailure;
  const std::optional<std::int64_t> steps = stepCountOrReport(*scenario, source);
  if (!steps) return kExitBadInput;

  cardiac::MonitorSettings settings;
  settings.everyColumn = true;
  settings.endTime = double(*steps) * double(scenario->simulation.dt);
  settings.limits.bloodLost = std::size_t(scenario->blood.lossAllowed);  // more lost: exit 3, when and where
  cardiac::RunMonitor monitor(*sim, settings);
  try {
    if (resumed) io::restoreMonitor(resumed->checkpoint, monitor, options.resume);
  } catch (const io::CheckpointError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitBadInput;
  }
  std::optional<io::SimulationVtkSeries> vtk;
  if (options.vtk || scenario->output.vtk) vtk.emplace(outDir, sim->hasHeart(), sim->hasBlood());
  const CheckpointPlan checkpoints{outDir, *checkpointEvery};
  const int simulated = simulate(*sim, monitor, *steps - sim->stepCount(), *csv, vtk ? &*vtk : nullptr,
                                 scenario->output.vtkEvery, checkpoints, timing.wallSeconds);
  if (simulated == kExitInvalidSimulation) writeFailureSummary(*scenario, timing, monitor, *sim, outDir);
  if (simulated != kExitOk) return simulated;
  if (!writeCirculationPlots(*scenario, *sim, monitor, outDir)) return kExitFailure;
  return report(*scenario, timing, monitor, *sim, outDir, options.json);
}

}  // namespace hs::app
