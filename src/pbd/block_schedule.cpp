#include "pbd/block_schedule.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "pbd/solver.h"

namespace hs::pbd {
namespace {

// Appends each constraint's extent: the largest distance between two of its particles.
template <class Constraint>
void collectExtents(const ConstraintGroup<Constraint>& group, const std::vector<Vec3>& x,
                    std::vector<Real>& extents) {
  for (const Constraint& c : group.constraints) {
    Real extent = 0;
    for (Index a : c.particles)
      for (Index b : c.particles) extent = std::max(extent, (x[a] - x[b]).norm());
    extents.push_back(extent);
  }
}

// Stable sort of a group's constraints by the block of their first particle.
template <class Constraint>
void sortByBlock(ConstraintGroup<Constraint>& group, const std::vector<Index>& particleBlock,
                 std::size_t blockCount) {
  std::stable_sort(group.constraints.begin(), group.constraints.end(),
                   [&](const Constraint& a, const Constraint& b) {
                     return particleBlock[a.particles[0]] < particleBlock[b.particles[0]];
                   });
  group.blockStart.assign(blockCount + 1, 0);
  for (const Constraint& c : group.constraints) ++group.blockStart[particleBlock[c.particles[0]] + 1];
  for (std::size_t b = 1; b <= blockCount; ++b) group.blockStart[b] += group.blockStart[b - 1];
  group.lambda.assign(group.constraints.size(), Real(0));
  // Inside a block, order the constraints by a local greedy colouring, so that neighbours in
  // the sequence rarely share a particle: the CPU then need not wait for the previous
  // correction to be stored before loading the next constraint's positions.
  std::map<Index, std::vector<bool>> used;  // particle -> colours taken, per block
  for (std::size_t b = 0; b < blockCount; ++b) {
    const auto first = group.constraints.begin() + static_cast<std::ptrdiff_t>(group.blockStart[b]);
    const auto last = group.constraints.begin() + static_cast<std::ptrdiff_t>(group.blockStart[b + 1]);
    used.clear();
    std::vector<std::pair<Index, Constraint>> keyed;
    for (auto it = first; it != last; ++it) {
      Index k = 0;
      for (;; ++k) {
        bool free = true;
        for (Index p : it->particles) {
          const auto& taken = used[p];
          if (k < taken.size() && taken[k]) free = false;
        }
        if (free) break;
      }
      for (Index p : it->particles) {
        auto& taken = used[p];
        if (taken.size() <= k) taken.resize(k + 1, false);
        taken[k] = true;
      }
      keyed.emplace_back(k, *it);
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& c) { return a.first < c.first; });
    for (std::size_t i = 0; i < keyed.size(); ++i) *(first + static_cast<std::ptrdiff_t>(i)) = keyed[i].second;
  }
}

// For every particle, the blocks whose constraints touch it.
template <class Constraint>
void collectTouches(const ConstraintGroup<Constraint>& group, const std::vector<Index>& particleBlock,
                    std::vector<std::vector<Index>>& blocksTouching) {
  for (const Constraint& c : group.constraints) {
    const Index owner = particleBlock[c.particles[0]];
    for (Index p : c.particles) blocksTouching[p].push_back(owner);
  }
}

}  // namespace

std::vector<Index> greedyColouring(const std::vector<std::vector<Index>>& adjacency) {
  constexpr Index kNone = ~Index(0);
  std::vector<Index> colour(adjacency.size(), kNone);
  std::vector<bool> taken;
  for (std::size_t v = 0; v < adjacency.size(); ++v) {
    taken.assign(adjacency[v].size() + 1, false);
    for (Index u : adjacency[v])
      if (colour[u] != kNone && colour[u] < taken.size()) taken[colour[u]] = true;
    Index k = 0;
    while (taken[k]) ++k;
    colour[v] = k;
  }
  return colour;
}

BlockSchedule buildBlockSchedule(ConstraintSet& constraints, const std::vector<Vec3>& positions) {
  BlockSchedule schedule;
  std::vector<Real> extents;
  collectExtents(constraints.distances, positions, extents);
  collectExtents(constraints.areas, positions, extents);
  collectExtents(constraints.volumes, positions, extents);
  // Cells of kCellsPerExtent typical constraint extents (the median): most blocks then
  // conflict only with their neighbours, and there are enough blocks per colour to share
  // between threads. Conflicts are computed exactly, so any cell size is correct.
  constexpr Real kCellsPerExtent = 2;
  Real typical = 0;
  if (!extents.empty()) {
    auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
    std::nth_element(extents.begin(), middle, extents.end());
    typical = *middle;
  }
  schedule.cellSize = typical > Real(0) ? kCellsPerExtent * typical : Real(1);
  Vec3 lower = Vec3::Constant(std::numeric_limits<Real>::max());
  for (const Vec3& x : positions) lower = lower.cwiseMin(x);

  // Block ids in the sorted order of non-empty cells: deterministic.
  std::vector<std::array<long, 3>> cellOf(positions.size());
  std::map<std::array<long, 3>, Index> cellIds;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3 c = (positions[i] - lower) / schedule.cellSize;
    cellOf[i] = {std::lround(std::floor(c.x())), std::lround(std::floor(c.y())), std::lround(std::floor(c.z()))};
    cellIds.emplace(cellOf[i], 0);
  }
  Index next = 0;
  for (auto& [cell, id] : cellIds) id = next++;
  schedule.blockCount = cellIds.size();
  std::vector<Index> particleBlock(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) particleBlock[i] = cellIds.at(cellOf[i]);

  sortByBlock(constraints.distances, particleBlock, schedule.blockCount);
  sortByBlock(constraints.areas, particleBlock, schedule.blockCount);
  sortByBlock(constraints.volumes, particleBlock, schedule.blockCount);

  // Block conflict graph: blocks that touch a common particle.
  std::vector<std::vector<Index>> blocksTouching(positions.size());
  collectTouches(constraints.distances, particleBlock, blocksTouching);
  collectTouches(constraints.areas, particleBlock, blocksTouching);
  collectTouches(constraints.volumes, particleBlock, blocksTouching);
  std::vector<std::vector<Index>> adjacency(schedule.blockCount);
  for (auto& blocks : blocksTouching) {
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    for (Index a : blocks)
      for (Index b : blocks)
        if (a != b) adjacency[a].push_back(b);
  }
  for (auto& list : adjacency) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }

  const std::vector<Index> colour = greedyColouring(adjacency);
  const Index colours = colour.empty() ? 0 : *std::max_element(colour.begin(), colour.end()) + 1;
  schedule.colourStart.assign(colours + 1, 0);
  for (Index c : colour) ++schedule.colourStart[c + 1];
  for (std::size_t k = 1; k < schedule.colourStart.size(); ++k) schedule.colourStart[k] += schedule.colourStart[k - 1];
  schedule.blockOrder.resize(schedule.blockCount);
  std::vector<std::size_t> fill(schedule.colourStart.begin(), schedule.colourStart.end() - 1);
  for (Index b = 0; b < schedule.blockCount; ++b) schedule.blockOrder[fill[colour[b]]++] = b;
  return schedule;
}

}  // namespace hs::pbd
