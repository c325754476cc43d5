#pragma once
// Vortex cores in a plane cut of a flow (plane_field.h), as 4D-flow MRI studies of the filling
// vortex find them (Elbaz et al. 2014, JCMR 16:78; Toeger et al. 2012): the out-of-plane
// vorticity of the in-plane velocity, its extrema, and the circulation of each core. A vortex
// ring cut by a plane through its axis shows two cores of opposite sign.
//
// Vorticity, by central differences on the grid (spacing s), along n = u x v:
//   omega(i, j) = (v_v(i+1, j) - v_v(i-1, j)) / (2 s) - (v_u(i, j+1) - v_u(i, j-1)) / (2 s)
// at a node whose four neighbours are filled (NaN elsewhere: the wall, the field's edge).
//
// A core: a node where |omega| is largest among its filled 8 neighbours, of the same sign, and
// at least `minPeak` (1/s: below it, particle noise, not a vortex); its extent the 4-connected
// region of nodes of that sign with |omega| >= half the peak (the full width at half maximum, as
// the image-based studies delimit a core); its position the omega-weighted centroid of that
// region (finer than the grid); its circulation the integral of omega over it,
//   Gamma = sum over the region of omega s^2   (Stokes: the line integral of v around it).
// For a Lamb-Oseen core, omega = Gamma0 / (pi rc^2) exp(-r^2 / rc^2), the half-peak region is
// r <= rc sqrt(ln 2) and holds Gamma0 (1 - 1/2) = Gamma0 / 2: half the vortex's total, whatever
// rc and whatever smoothing widened it. A node belongs to one core, the strongest that reaches it.
//
// Vorticity also peaks in a shear layer (the edge of a jet), which does not swirl. Given the
// swirling strength (Zhou et al. 1999, J. Fluid Mech. 387:353), the imaginary part of the
// in-plane velocity gradient's complex eigenvalues,
//   J = [[a, b], [c, d]] = [[dv_u/du, dv_u/dv], [dv_v/du, dv_v/dv]],
//   lambda_ci = sqrt(-((a - d)^2 + 4 b c)) / 2   where that is real, else 0,
// a peak counts only where the flow swirls: lambda_ci >= kSwirlShare |omega| / 2. A solid-body
// turn (a vortex's centre) has lambda_ci = |omega| / 2; a pure shear has 0. It is the plane's
// form of the lambda-2 criterion (Jeong & Hussain 1995) that Elbaz et al. 2014 found the
// filling vortex with: for an in-plane divergence-free flow, lambda_2 < 0 exactly where
// lambda_ci > 0.
#include <cstddef>
#include <vector>

#include "pbd/fluid/plane_field.h"

namespace hs::pbd {

// Omega at each node (PlaneGrid::index), 1/s; NaN where it cannot be differenced.
std::vector<double> planeVorticity(const PlaneField& field);
// lambda_ci at each node, 1/s (0 where the flow does not swirl); NaN where it cannot be differenced.
std::vector<double> planeSwirl(const PlaneField& field);

// A core's peak swirls at least half as fast as a solid-body turn of its vorticity.
inline constexpr double kSwirlShare = 0.5;

struct VortexCore {
  double i = 0, j = 0;       // the centroid, in node units (PlaneGrid::node(i, j) is the point)
  Vec3d position = Vec3d::Zero();
  double peak = 0;           // 1/s, signed
  double circulation = 0;    // m^2/s, signed as omega
  std::size_t nodes = 0;     // the core's region
};

// The cores, strongest circulation (by magnitude) first. With `swirl` (planeSwirl), only peaks
// that swirl (above).
std::vector<VortexCore> findVortexCores(const PlaneGrid& grid, const std::vector<double>& omega, double minPeak,
                                        const std::vector<double>* swirl = nullptr);

}  // namespace hs::pbd
