#include "compare_command.h"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <filesystem>
#include <iostream>
#include <optional>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "exit_codes.h"
#include "io/output/circulation_plots.h"
#include "io/output/output_paths.h"
#include "progress_bar.h"
#include "simulation_setup.h"

namespace hs::app {
namespace {

namespace fs = std::filesystem;

struct ComparedRun {
  io::PvLoopCurve loop;
  cardiac::PressureVolumeRelations relations;
  // The 3D blood's flow components as summary.json's heart.flow_components (the mean of the
  // beats after the first two), or of every beat when a short run has no more; none without
  // blood and valves or a beat.
  std::optional<cardiac::FlowComponents> flow;
  std::string flowBeats;  // which beats: "beats 3-6", "beat 1"
};

constexpr std::size_t kSettlingBeats = 2;  // as summary.json skips (io/output/run_report.cpp)

std::string beatRange(std::size_t first, std::size_t last) {
  return first == last ? "beat " + std::to_string(first)
                       : "beats " + std::to_string(first) + "-" + std::to_string(last);
}

// Both runs' four shares side by side, in % of the end-diastolic volume.
void printFlowComponents(const std::vector<ComparedRun>& runs) {
  std::printf("flow components, %% of the end-diastolic volume (3D blood):\n");
  std::printf("  %-18s %24s %24s\n", "", runs[0].loop.label.c_str(), runs[1].loop.label.c_str());
  std::printf("  %-18s %24s %24s\n", "", runs[0].flowBeats.c_str(), runs[1].flowBeats.c_str());
  struct Row {
    const char* name;
    double cardiac::FlowComponents::*share;
  };
  for (const Row& row : {Row{"direct flow", &cardiac::FlowComponents::direct},
                         Row{"retained inflow", &cardiac::FlowComponents::retainedInflow},
                         Row{"delayed ejection", &cardiac::FlowComponents::delayedEjection},
                         Row{"residual volume", &cardiac::FlowComponents::residual},
                         Row{"stayed > 3 beats", &cardiac::FlowComponents::stayedOverThreeBeats}}) {
    std::printf("  %-18s", row.name);
    for (const ComparedRun& run : runs) {
      if (run.flow)
        std::printf(" %24.1f", 100 * (*run.flow).*row.share);
      else
        std::printf(" %24s", "-");
    }
    std::printf("\n");
  }
  std::printf("  (healthy, 4D-flow MRI, Stoll et al. 2018: direct 38, retained 16, delayed 16, residual 30)\n");
}

// One scenario to `duration`, health-checked each step; its last complete beat. Exit code in
// `exitCode` (and nullopt) when it cannot be compared.
std::optional<ComparedRun> runOne(const std::string& source, double duration, int threads, int& exitCode) {
  std::optional<cardiac::Scenario> scenario = loadScenarioOrReport(source, {});
  exitCode = kExitBadInput;
  if (!scenario) return std::nullopt;
  if (!scenario->circulation.lumped) {
    std::cerr << "heartsim: error: compare: " << source << " has no lumped circulation (circulation.lumped = false); "
              << "expected a scenario such as normal or a pathology preset\n";
    return std::nullopt;
  }
  scenario->simulation.duration = static_cast<pbd::Real>(duration);
  const auto sim = makeSimulation(*scenario, threads, source, exitCode);
  if (!sim) return std::nullopt;
  cardiac::RunMonitor monitor(*sim);
  const auto steps = static_cast<long>(std::lround(duration / double(scenario->simulation.dt)));
  ProgressBar progress(steps);
  for (long s = 0; s < steps; ++s) {
    sim->step();
    if (const cardiac::Verdict& verdict = monitor.observe(); !verdict.healthy()) {
      progress.finish();
      std::cerr << "heartsim: error: " << source << ": " << verdict.message() << '\n';
      exitCode = kExitInvalidSimulation;
      return std::nullopt;
    }
    progress.update(s + 1, sim->time());
  }
  progress.finish();
  monitor.finish();
  const cardiac::CirculationRecorder& recorder = *monitor.circulation();
  ComparedRun run;
  run.loop = {scenario->name, io::lastCompleteBeat(recorder.samples(), recorder.beatStarts())};
  if (run.loop.samples.size() < 2) {
    std::cerr << "heartsim: error: compare: " << source << " completed no beat in " << duration
              << " s; expected --duration of at least two beats\n";
    return std::nullopt;
  }
  run.relations = sim->lumped()->relations(sim->drivenWall()->beatingShare());
  if (const cardiac::VentricleBlood* blood = monitor.ventricleBlood(); blood && !blood->beats().empty()) {
    const std::size_t n = blood->beats().size(), skipped = n > kSettlingBeats ? kSettlingBeats : 0;
    run.flow = cardiac::meanFlowComponents(blood->beats(), skipped);
    run.flowBeats = beatRange(skipped + 1, n);
  } else {
    run.flowBeats = "no beat";
  }
  exitCode = kExitOk;
  return run;
}

}  // namespace

int compareCommand(const CompareOptions& options) {
  if (options.scenarios.size() != 2) {
    std::cerr << "heartsim: error: compare: expected two scenarios, got " << options.scenarios.size() << '\n';
    return kExitBadInput;
  }
  if (!std::isfinite(options.duration) || options.duration <= 0) {
    std::cerr << "heartsim: error: --duration: must be a finite number > 0 (s), got " << options.duration << '\n';
    return kExitBadInput;
  }
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  std::vector<ComparedRun> runs;
  for (const std::string& source : options.scenarios) {
    int exitCode = kExitOk;
    std::optional<ComparedRun> run = runOne(source, options.duration, threads, exitCode);
    if (!run) return exitCode;
    runs.push_back(std::move(*run));
  }
  printFlowComponents(runs);
  const fs::path outDir = options.outDir.empty()
                              ? io::defaultOutputFolder("compare_" + runs[0].loop.label + "_" + runs[1].loop.label)
                              : fs::path(options.outDir);
  if (!createOutputDirOrReport(outDir)) return kExitFailure;
  const fs::path png = outDir / "pv_compare.png";
  try {
    // The relations drawn are the first scenario's; each loop shows where its own heart works.
    io::writePvLoopPng(png.string(), {runs[0].loop, runs[1].loop}, runs[0].relations,
                       "PV loops; the relations are " + runs[0].loop.label + "'s");
  } catch (const std::exception& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
  std::cerr << "heartsim: compare: " << runs[0].loop.label << " and " << runs[1].loop.label << " in " << png.string()
            << '\n';
  return kExitOk;
}

}  // namespace hs::app
