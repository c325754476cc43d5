#pragma once
// `heartsim run --resume FILE` and `--checkpoint-every S`: reading a checkpoint and its scenario
// for a run, and the checkpoint interval in steps, with the commands' error convention (one
// line on stderr naming the file, exit 2).
#include <cstdint>
#include <optional>

#include "cardiac/scenario.h"
#include "io/output/checkpoint.h"
#include "run_command.h"

namespace hs::app {

struct ResumedRun {
  io::Checkpoint checkpoint;
  cardiac::Scenario scenario;
};

// The checkpoint and its scenario with --duration (default: the scenario's); a scenario
// argument or --set must give the same scenario (only simulation.duration and output.* may
// differ). nullopt after printing why not.
std::optional<ResumedRun> readResumedRun(const RunOptions& options);

// Steps between checkpoints (0: none), or nullopt after printing why --checkpoint-every is
// not usable.
std::optional<std::int64_t> checkpointIntervalOrReport(const RunOptions& options, const cardiac::Scenario& scenario);

}  // namespace hs::app
