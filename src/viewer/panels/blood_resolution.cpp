#include "viewer/panels/blood_resolution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hs::viewer {

BloodResolution chooseResolution(std::span<const LevelMeasurement> measurements) {
  std::optional<BloodResolution> finestHolding, coarsestMeasured;
  for (const LevelMeasurement& m : measurements) {
    if (!m.measured) continue;
    if (!coarsestMeasured || m.level < *coarsestMeasured) coarsestMeasured = m.level;
    if (m.pace >= kHoldsRealTimePace && (!finestHolding || m.level > *finestHolding)) finestHolding = m.level;
  }
  if (finestHolding) return *finestHolding;
  return coarsestMeasured.value_or(kScenarioResolution);
}

bool worthMeasuring(std::span<const LevelMeasurement> measuredSoFar) {
  for (const LevelMeasurement& m : measuredSoFar)
    if (m.measured && m.pace < kHoldsRealTimePace) return false;
  return true;
}

std::string withThousands(long value) {
  const std::string digits = std::to_string(value < 0 ? -value : value);
  std::string text = value < 0 ? "-" : "";
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

std::string resolutionLine(const ResolutionStatus& status, double livePace, bool behind, bool paused) {
  if (status.measuring) return "measuring this computer's pace: " + status.measuringWhat;
  // A fixed count runs as given (the scenario's own level) until the student picks another.
  const bool fixed = !status.fixedBy.empty() && status.level == kScenarioResolution;
  std::string line = "blood: ";
  if (!fixed) line += std::string(resolutionName(status.level)) + ", ";
  line += withThousands(status.particles) + " particles";
  if (fixed) line += " (" + status.fixedBy + ")";
  // Paused, nothing keeps pace or falls behind: the line says only that.
  if (paused) return line + ", paused";
  char pace[64];
  // Slow motion as the pace meter sees it now (a finer level picked, a busier machine) comes
  // before what the start-up measurement promised.
  if (behind && livePace < 0.95)
    std::snprintf(pace, sizeof pace, ", %.2gx real time: slow motion", livePace);
  else if (status.measuredPace && *status.measuredPace >= kHoldsRealTimePace)
    std::snprintf(pace, sizeof pace, ", holds real time (%.2gx)", *status.measuredPace);
  else if (status.measuredPace)
    std::snprintf(pace, sizeof pace, ", measured %.2gx real time: slow motion", *status.measuredPace);
  else
    std::snprintf(pace, sizeof pace, ", holds real time");
  return line + pace;
}

}  // namespace hs::viewer
