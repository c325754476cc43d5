#pragma once
// The arithmetic of the dam-break validation (`heartsim validate dam-break`), kept apart from the
// simulation so it can be tested on synthetic fronts: the surge front of a particle cloud, the
// non-dimensional variables of Martin & Moyce (1952), interpolation of the simulated front and
// the relative error at each experimental point. docs/validation.md describes the method.
#include <array>
#include <span>
#include <vector>

#include "pbd/core/types.h"

namespace hs::app {

// One experimental point: front Z = x/a reached at non-dimensional time T = t sqrt(2 g / a).
struct DamBreakPoint {
  double z;
  double t;
};

// Martin, J.C. & Moyce, W.J. (1952), "An experimental study of the collapse of liquid columns on
// a rigid horizontal plane", Phil. Trans. R. Soc. A 244:312-324, Table 2: surge front of the
// n^2 = 2 column (a = 2.25 in, mean of up to 9 runs), Z against T = n t sqrt(g/a). Transcribed
// from public validation repositories (several independent copies agree; the paper itself was
// not consulted), via /work/shared/reference/martin-moyce-1952.md. The transcriptions' time
// origin is aligned so that T = 1.19 at Z = 1.44.
inline constexpr std::array<DamBreakPoint, 21> kMartinMoyceN2Front = {{
    {1.11, 0.41}, {1.22, 0.84}, {1.44, 1.19}, {1.67, 1.43}, {1.89, 1.63}, {2.11, 1.83}, {2.33, 1.98},
    {2.56, 2.20}, {2.78, 2.32}, {3.00, 2.51}, {3.22, 2.65}, {3.44, 2.83}, {3.67, 2.97}, {3.89, 3.11},
    {4.11, 3.33}, {5.00, 4.02}, {5.89, 4.44}, {7.00, 5.09}, {8.00, 5.69}, {9.00, 6.30}, {10.0, 6.83},
}};

// The surge front, in metres from the wall at wallX: the largest x + radius over the particles
// whose lowest point (y - radius) lies within floorBand of the floor at floorY. The band keeps
// droplets thrown ahead of the front from counting: the experiment photographed the leading
// edge of the liquid on the plate. floorBand = infinity gives the front of all particles.
// Returns 0 when no particle is in the band.
double surgeFront(std::span<const pbd::Vec3> positions, double radius, double wallX, double floorY,
                  double floorBand);

// Non-dimensional time of a column of width a whose height is n2 * a: T = sqrt(n2) t sqrt(g/a)
// (Martin & Moyce's T = n t sqrt(g/a)).
double damBreakTime(double t, double g, double a, double n2);

// Sampled front Z(T), T increasing.
struct FrontCurve {
  std::vector<double> t;  // s
  std::vector<double> T;
  std::vector<double> Z;
};

// Linear interpolation of Z at T; clamps to the first/last sample outside the sampled range.
// Requires a non-empty curve.
double interpolateFront(const FrontCurve& curve, double T);

struct PointComparison {
  double zExp = 0;
  double tExp = 0;         // experimental T
  double tSim = 0;         // simulated time compared with it: tExp - shift
  double zSim = 0;         // simulated Z at tSim
  double relativeError = 0;  // |zSim - zExp| / zExp
};

// Compares every experimental point with T <= tMax against the simulated curve delayed by
// `shift` (the simulation's release is instantaneous, the experiment's was not): Z_sim is read at
// T - shift, or at 0 when that is negative.
std::vector<PointComparison> compareFront(const FrontCurve& curve, std::span<const DamBreakPoint> experiment,
                                          double shift, double tMax);

// Largest relative error of the comparison (0 for none).
double maxRelativeError(std::span<const PointComparison> points);

}  // namespace hs::app
