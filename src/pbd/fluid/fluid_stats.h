#pragma once
// Measurements of a fluid's state: density error over particles with a full neighbourhood,
// speed, neighbour counts. Diagnostics only; the solver never reads them.
#include <cstddef>
#include <vector>

#include "pbd/core/particles.h"
#include "pbd/fluid/fluid.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {

struct FluidStats {
  std::size_t fluidCount = 0;
  std::size_t fullCount = 0;         // fluid particles with a full neighbourhood
  Index fullThreshold = 0;           // neighbour count that counts as full
  Real densityErrorMean = 0;         // mean |rho/rho0 - 1| over full-neighbourhood particles
  Real densityErrorMax = 0;          // max  |rho/rho0 - 1| over them
  Real densitySignedMean = 0;        // mean (rho/rho0 - 1) over them (compression > 0)
  Real maxSpeed = 0;                 // max |v| over all fluid particles
  Real meanNeighbours = 0;           // neighbours within h per fluid particle
};

// Neighbour count (|r| < h, self excluded) of an interior particle of a cubic lattice of
// spacing d.
Index latticeNeighbourCount(Real supportRadius, Real spacing);

// Density error and speed of the fluid particles at their current positions. A particle has
// a full neighbourhood when it has at least 90% of latticeNeighbourCount(h, spacing)
// neighbours (free-surface and wall particles lack neighbours and are under-dense by design).
// Builds a neighbour grid of its own.
FluidStats measureFluid(const Particles& particles, const FluidSettings& fluid, Real spacing,
                        int threads = 1);

// The density part of measureFluid (maxSpeed left 0) for positions whose neighbour lists
// exist already (a solver's, pbd::FluidSolver::measure): lists[k] are the neighbours of
// positions[k] within h when the lists were built; a pair that came closer than h since is
// missed, one that moved apart adds nothing (W = 0 beyond h).
FluidStats measureDensityOnLists(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                                 const FluidSettings& fluid, Real spacing, int threads = 1);

}  // namespace hs::pbd
