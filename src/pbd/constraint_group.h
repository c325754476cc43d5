#pragma once
// A group of constraints of one type sharing compliance and stiffness, stored sorted by
// graph colour so that constraints of one colour touch disjoint particles and can be
// projected in parallel (Gauss-Seidel across colours, thread-count independent results).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "pbd/types.h"

namespace hs::pbd {

template <class Constraint>
struct ConstraintGroup {
  std::vector<Constraint> constraints;     // sorted by colour
  std::vector<std::size_t> colourStart{0};  // colour k spans [colourStart[k], colourStart[k+1])
  std::vector<Real> lambda;                // XPBD Lagrange multipliers, reset every step
  Real compliance = 0;                     // alpha (XPBD); 0 = plain PBD
  Real stiffness = 1;                      // k in [0, 1]

  [[nodiscard]] std::size_t size() const { return constraints.size(); }
  [[nodiscard]] std::size_t colourCount() const { return colourStart.size() - 1; }
};

// Greedy colouring in input order: each constraint takes the smallest colour not used by any
// constraint sharing one of its particles. Then a stable sort by colour. Deterministic.
template <class Constraint>
void colourConstraints(ConstraintGroup<Constraint>& group, std::size_t particleCount) {
  std::vector<std::vector<bool>> used;  // used[colour][particle]
  std::vector<std::uint32_t> colour(group.constraints.size());
  for (std::size_t c = 0; c < group.constraints.size(); ++c) {
    const auto& particles = group.constraints[c].particles;
    std::uint32_t k = 0;
    for (;; ++k) {
      if (k == used.size()) used.emplace_back(particleCount, false);
      const bool free = std::none_of(particles.begin(), particles.end(),
                                     [&](Index p) { return used[k][p]; });
      if (free) break;
    }
    for (Index p : particles) used[k][p] = true;
    colour[c] = k;
  }
  std::vector<std::size_t> order(group.constraints.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return colour[a] < colour[b]; });
  std::vector<Constraint> sorted;
  sorted.reserve(order.size());
  for (std::size_t i : order) sorted.push_back(group.constraints[i]);
  group.constraints = std::move(sorted);
  group.colourStart.assign(used.size() + 1, 0);
  for (std::uint32_t k : colour) ++group.colourStart[k + 1];
  for (std::size_t k = 1; k < group.colourStart.size(); ++k)
    group.colourStart[k] += group.colourStart[k - 1];
  group.lambda.assign(group.constraints.size(), Real(0));
}

}  // namespace hs::pbd
