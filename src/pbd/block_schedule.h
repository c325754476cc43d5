#pragma once
// Parallel Gauss-Seidel by graph colouring of spatial blocks.
//
// Particles are binned into cubic cells (blocks) at least twice as wide as the largest
// constraint; each constraint belongs to the block of its first particle. Two blocks conflict
// when their constraints share a particle; a greedy colouring of the block conflict graph
// gives a few colours (about 8 on a grid) whose blocks are independent. An iteration visits
// the colours in order; the blocks of one colour run in parallel, and inside a block the
// constraints are projected sequentially (Gauss-Seidel). Because blocks of one colour touch
// disjoint particles, the result does not depend on the number of threads, bitwise.
// Compared with colouring single constraints (~50 colours on a tet mesh, one barrier each),
// threads meet far less often, which is what a small mesh on two cores needs.
#include <vector>

#include "pbd/types.h"

namespace hs::pbd {

struct ConstraintSet;

struct BlockSchedule {
  std::vector<Index> blockOrder;          // block ids grouped by colour
  std::vector<std::size_t> colourStart{0};  // colour k spans blockOrder[colourStart[k], colourStart[k+1])
  std::size_t blockCount = 0;
  Real cellSize = 0;

  [[nodiscard]] std::size_t colourCount() const { return colourStart.size() - 1; }
};

// Sorts every group of `constraints` by block, fills their blockStart offsets and returns the
// colour schedule. Deterministic: depends only on positions and constraint order.
BlockSchedule buildBlockSchedule(ConstraintSet& constraints, const std::vector<Vec3>& positions);

// Greedy colouring of a graph given as sorted adjacency lists, visiting vertices in index
// order: each takes the smallest colour none of its coloured neighbours has.
std::vector<Index> greedyColouring(const std::vector<std::vector<Index>>& adjacency);

}  // namespace hs::pbd
