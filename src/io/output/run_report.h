#pragma once
// summary.json of `heartsim run` (also its --json line) and the one-line summary on stderr:
// the run's timing, the wall's mesh, volume errors, cavity and beats, the heart as a pump in
// clinical units, and the blood's statistics, from a RunMonitor's RunSummary.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "cardiac/anatomy/lv_anatomy.h"
#include "cardiac/run_monitor.h"
#include "cardiac/scenario.h"

namespace hs::io {

struct RunTiming {
  double setupSeconds = 0;  // scenario and model
  double wallSeconds = 0;   // stepping only
  int threads = 1;
  std::int64_t resumedAtStep = 0;  // a run resumed from a checkpoint timed only the steps after it
  [[nodiscard]] double stepsPerSecond(std::int64_t steps) const {
    return wallSeconds > 0 ? double(steps - resumedAtStep) / wallSeconds : 0.0;
  }
};

// `anatomy`: the heart's sizes (cardiac/anatomy/lv_anatomy.h) as "model", before the wall's figures.
nlohmann::ordered_json runReport(const cardiac::Scenario& scenario, const RunTiming& timing,
                                 const cardiac::RunSummary& run, const std::string& outputDir,
                                 const cardiac::AnatomyFigures* anatomy = nullptr);

// "model": the annuli's areas in cm^2, the aortic root's diameter and the long axis in mm (the
// root null on a heart without an outflow vessel).
nlohmann::ordered_json anatomyReport(const cardiac::AnatomyFigures& anatomy);

// "heart": beats and the means over complete beats after the first, in mL, L/min.
nlohmann::ordered_json heartPumpReport(const cardiac::BeatTracker& beats);

// "<scenario>: N steps in S s (R steps/s, T threads); EF ...; ...; results in DIR".
std::string runSummaryLine(const cardiac::Scenario& scenario, const RunTiming& timing,
                           const cardiac::RunSummary& run, const std::string& outputDir);

}  // namespace hs::io
