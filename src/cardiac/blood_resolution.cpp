#include "cardiac/blood_resolution.h"

#include <algorithm>
#include <cmath>

namespace hs::cardiac {

const ResolutionLevel& resolutionLevel(BloodResolution level) {
  return kResolutionLevels[std::size_t(level)];
}

const char* resolutionName(BloodResolution level) { return resolutionLevel(level).name; }

std::optional<BloodResolution> parseResolution(const std::string& text) {
  for (const ResolutionLevel& l : kResolutionLevels)
    if (text == l.name) return l.level;
  return std::nullopt;
}

double resolutionSpacingScale(BloodResolution level) {
  return std::cbrt(1 / resolutionLevel(level).countFactor);
}

void applyResolution(BloodResolution level, Scenario& scenario) {
  if (level == kScenarioResolution) return;  // bitwise the scenario as written
  BloodSettings& blood = scenario.blood;
  const auto scale = Real(resolutionSpacingScale(level));
  blood.spacing *= scale;
  blood.radius *= scale;
  blood.supportRadius *= scale;
  if (blood.particles > 0)
    blood.particles = std::max(1, int(std::lround(double(blood.particles) * resolutionLevel(level).countFactor)));
}

int particlesAtLevel(BloodResolution level, BloodResolution running, int runningCount) {
  const double ratio = resolutionLevel(level).countFactor / resolutionLevel(running).countFactor;
  return int(std::lround(double(runningCount) * ratio));
}

}  // namespace hs::cardiac
