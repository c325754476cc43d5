#include "pbd/core/block_schedule.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "pbd/core/solver.h"

namespace hs::pbd {
namespace {

// Stable sort of a group's constraints by their block.
template <class Constraint, class BlockOf>
void sortByBlock(ConstraintGroup<Constraint>& group, const BlockOf& blockOf, std::size_t blockCount) {
  std::stable_sort(group.constraints.begin(), group.constraints.end(),
                   [&](const Constraint& a, const Constraint& b) { return blockOf(a) < blockOf(b); });
  group.blockStart.assign(blockCount + 1, 0);
  for (const Constraint& c : group.constraints) ++group.blockStart[blockOf(c) + 1];
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
template <class Constraint, class BlockOf>
void collectTouches(const ConstraintGroup<Constraint>& group, const BlockOf& blockOf,
                    std::vector<std::vector<Index>>& blocksTouching) {
  for (const Constraint& c : group.constraints) {
    const Index owner = blockOf(c);
    for (Index p : c.particles) blocksTouching[p].push_back(owner);
  }
}

// Recursive bisection: splits `ids` at the median along the axis of largest extent until
// there are `parts` regions; region ids are assigned in the order the halves are visited.
void bisect(std::vector<Index> ids, const std::vector<Vec3>& x, std::size_t parts, Index& nextRegion,
            std::vector<Index>& region) {
  if (parts <= 1 || ids.size() < 2) {
    for (Index i : ids) region[i] = nextRegion;
    ++nextRegion;
    return;
  }
  Vec3 lower = Vec3::Constant(std::numeric_limits<Real>::max());
  Vec3 upper = -lower;
  for (Index i : ids) {
    lower = lower.cwiseMin(x[i]);
    upper = upper.cwiseMax(x[i]);
  }
  Eigen::Index axis = 0;
  (upper - lower).maxCoeff(&axis);
  std::sort(ids.begin(), ids.end(), [&](Index a, Index b) {
    return x[a][axis] < x[b][axis] || (x[a][axis] == x[b][axis] && a < b);
  });
  const auto half = ids.begin() + static_cast<std::ptrdiff_t>(ids.size() / 2);
  bisect(std::vector<Index>(ids.begin(), half), x, parts / 2, nextRegion, region);
  bisect(std::vector<Index>(half, ids.end()), x, parts - parts / 2, nextRegion, region);
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
  constraints.movableListedFor.clear();  // the constraints are sorted anew: their lists too
  // Regions: the particles split into a fixed number of spatial parts, independent of the
  // thread count (so the result is too). A constraint inside one region belongs to that
  // region's block; a constraint across regions belongs to the seam block of the regions it
  // touches. Region blocks never share a particle and run in parallel; the seams, a small
  // share, follow in later colours.
  constexpr std::size_t kParticlesPerRegion = 4096;
  std::size_t regions = 2;
  while (regions * kParticlesPerRegion < positions.size()) regions *= 2;
  std::vector<Index> region(positions.size(), 0);
  std::vector<Index> all(positions.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<Index>(i);
  Index nextRegion = 0;
  bisect(all, positions, regions, nextRegion, region);

  // Block ids in the sorted order of their region sets: regions first, then seams.
  std::map<std::vector<Index>, Index> blockIds;
  auto regionSet = [&](const auto& c) {
    std::vector<Index> set;
    for (Index p : c.particles) set.push_back(region[p]);
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    return set;
  };
  auto collectSets = [&](const auto& group) {
    for (const auto& c : group.constraints) blockIds.emplace(regionSet(c), 0);
  };
  collectSets(constraints.distances);
  collectSets(constraints.areas);
  collectSets(constraints.volumes);
  std::vector<std::vector<Index>> sets;
  for (const auto& [set, id] : blockIds) sets.push_back(set);
  std::stable_sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
  for (std::size_t i = 0; i < sets.size(); ++i) blockIds[sets[i]] = static_cast<Index>(i);
  schedule.blockCount = sets.size();
  schedule.regionCount = regions;
  auto blockOf = [&](const auto& c) { return blockIds.at(regionSet(c)); };

  sortByBlock(constraints.distances, blockOf, schedule.blockCount);
  sortByBlock(constraints.areas, blockOf, schedule.blockCount);
  sortByBlock(constraints.volumes, blockOf, schedule.blockCount);

  // Block conflict graph: blocks that touch a common particle.
  std::vector<std::vector<Index>> blocksTouching(positions.size());
  collectTouches(constraints.distances, blockOf, blocksTouching);
  collectTouches(constraints.areas, blockOf, blocksTouching);
  collectTouches(constraints.volumes, blockOf, blocksTouching);
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
