#pragma once
// Parallel Gauss-Seidel by graph colouring of blocks of constraints.
//
// The particles are split by recursive bisection into a fixed number of spatial regions (a
// power of two, from the particle count, never from the thread count). A constraint whose
// particles all lie in one region belongs to that region's block; one that crosses regions
// belongs to the seam block of the set of regions it touches. Two blocks conflict when their
// constraints share a particle; a greedy colouring of the block conflict graph puts all
// region blocks in the first colour (they share no particle by construction) and the seams in
// a few more. An iteration visits the colours in order; the blocks of one colour run in
// parallel, and inside a block the constraints are projected sequentially (Gauss-Seidel).
// Because blocks of one colour touch disjoint particles, the result does not depend on the
// number of threads, bitwise. Threads meet once per colour: a handful of times per sweep,
// against ~50 when single constraints are coloured, which is what a small mesh on two cores
// needs.
#include <vector>

#include "pbd/core/types.h"

namespace hs::pbd {

struct ConstraintSet;

struct BlockSchedule {
  std::vector<Index> blockOrder;          // block ids grouped by colour
  std::vector<std::size_t> colourStart{0};  // colour k spans blockOrder[colourStart[k], colourStart[k+1])
  std::size_t blockCount = 0;
  std::size_t regionCount = 0;  // spatial regions; the other blocks are seams between them

  [[nodiscard]] std::size_t colourCount() const { return colourStart.size() - 1; }
};

// Sorts every group of `constraints` by block, fills their blockStart offsets and returns the
// colour schedule. Deterministic: depends only on positions and constraint order.
BlockSchedule buildBlockSchedule(ConstraintSet& constraints, const std::vector<Vec3>& positions);

// Greedy colouring of a graph given as sorted adjacency lists, visiting vertices in index
// order: each takes the smallest colour none of its coloured neighbours has.
std::vector<Index> greedyColouring(const std::vector<std::vector<Index>>& adjacency);

}  // namespace hs::pbd
