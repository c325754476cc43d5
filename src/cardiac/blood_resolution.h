#pragma once
// The blood's resolution: a few levels of particle spacing that `heartsim run`, `render`,
// `bench` and `view` name alike (--resolution coarse|medium|fine|finest; the scenario as
// written is `fine`). Each level scales the scenario's own blood: the spacing by s, the
// particle radius and the kernel's support radius alike (normal: radius = spacing / 2, support =
// 2 x spacing, at every level), and the particle count by 1 / s^3, so the same volume is filled:
// the heart stays full and the same share waits in the body. The physics keys (density,
// viscosity, XSPH, iterations, dt) stay as the scenario says.
#include <array>
#include <optional>
#include <string>

#include "cardiac/scenario.h"

namespace hs::cardiac {

// Coarsest first. Fine is the scenario as written.
enum class BloodResolution { Coarse, Medium, Fine, Finest };
inline constexpr int kResolutionCount = 4;
inline constexpr BloodResolution kScenarioResolution = BloodResolution::Fine;

struct ResolutionLevel {
  BloodResolution level;
  const char* name;
  double countFactor;  // particles relative to the scenario's; the spacing scales by its cube root's inverse
};
inline constexpr std::array<ResolutionLevel, kResolutionCount> kResolutionLevels = {{
    {BloodResolution::Coarse, "coarse", 0.25},
    {BloodResolution::Medium, "medium", 0.5},
    {BloodResolution::Fine, "fine", 1.0},
    {BloodResolution::Finest, "finest", 2.0},
}};

const ResolutionLevel& resolutionLevel(BloodResolution level);
const char* resolutionName(BloodResolution level);
// "coarse", "medium", "fine" or "finest"; nullopt for anything else.
std::optional<BloodResolution> parseResolution(const std::string& text);
// The factor of the spacing (and radius and support radius): countFactor^(-1/3).
double resolutionSpacingScale(BloodResolution level);

// The scenario's blood at `level`: spacing, radius and support radius scaled alike, the count
// by countFactor (a count of 0, "fill the start region", stays 0: the fill follows the spacing).
void applyResolution(BloodResolution level, Scenario& scenario);
// The count `level` gives, from the count of the run at `running` (what a count of 0 came to).
int particlesAtLevel(BloodResolution level, BloodResolution running, int runningCount);

}  // namespace hs::cardiac
