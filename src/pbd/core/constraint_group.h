#pragma once
// A group of constraints of one type sharing compliance and stiffness. The constraints are
// stored sorted by the spatial block that owns them (block_schedule.h): block b's constraints
// span [blockStart[b], blockStart[b + 1]).
#include <cstddef>
#include <vector>

#include "pbd/core/types.h"

namespace hs::pbd {

template <class Constraint>
struct ConstraintGroup {
  std::vector<Constraint> constraints;    // sorted by block
  std::vector<std::size_t> blockStart{0};  // offsets, one more than there are blocks
  std::vector<Real> lambda;               // XPBD Lagrange multipliers, reset every step
  Real compliance = 0;                    // alpha (XPBD); 0 = plain PBD
  Real stiffness = 1;                     // k in [0, 1]
  // Scratch of a projection: the constraints that can move a particle (some w > 0), block by
  // block in the stored order, found again when the inverse masses change
  // (ConstraintSet::movableListedFor) so that the iterations skip the rest unread.
  std::vector<Index> movable;
  std::vector<std::size_t> movableStart{0};

  [[nodiscard]] std::size_t size() const { return constraints.size(); }
};

}  // namespace hs::pbd
