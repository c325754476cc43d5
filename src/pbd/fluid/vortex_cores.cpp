#include "pbd/fluid/vortex_cores.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace hs::pbd {

namespace {

// The in-plane velocity gradient at node (i, j) by central differences: a = du/du, b = du/dv,
// c = dv/du, d = dv/dv (u, v the plane's axes); none where a neighbour holds no blood.
struct PlaneGradient {
  double a, b, c, d;
};
std::optional<PlaneGradient> gradientAt(const PlaneField& field, int i, int j) {
  const PlaneGrid& g = field.grid;
  if (!field.isFilled(i - 1, j) || !field.isFilled(i + 1, j) || !field.isFilled(i, j - 1) || !field.isFilled(i, j + 1))
    return std::nullopt;
  const double twoS = 2 * g.spacing;
  const std::size_t e = g.index(i + 1, j), w = g.index(i - 1, j), n = g.index(i, j + 1), s = g.index(i, j - 1);
  return PlaneGradient{(field.vu[e] - field.vu[w]) / twoS, (field.vu[n] - field.vu[s]) / twoS,
                       (field.vv[e] - field.vv[w]) / twoS, (field.vv[n] - field.vv[s]) / twoS};
}

// f(gradient) at every node with a whole stencil; NaN elsewhere.
template <class F>
std::vector<double> mapGradient(const PlaneField& field, F f) {
  const PlaneGrid& g = field.grid;
  std::vector<double> out(g.size(), std::numeric_limits<double>::quiet_NaN());
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.columns; ++i)
      if (const std::optional<PlaneGradient> grad = gradientAt(field, i, j)) out[g.index(i, j)] = f(*grad);
  return out;
}

}  // namespace

// omega = dv/du - du/dv.
std::vector<double> planeVorticity(const PlaneField& field) {
  return mapGradient(field, [](const PlaneGradient& g) { return g.c - g.b; });
}

// The swirling strength: the imaginary part of the gradient's complex eigenvalues,
// sqrt(-((a - d)^2 + 4 b c)) / 2 where the discriminant is negative, else 0.
std::vector<double> planeSwirl(const PlaneField& field) {
  return mapGradient(field, [](const PlaneGradient& g) {
    const double discriminant = (g.a - g.d) * (g.a - g.d) + 4 * g.b * g.c;
    return discriminant < 0 ? 0.5 * std::sqrt(-discriminant) : 0.0;
  });
}

namespace {

// |omega| at (i, j) is at least that of each differenced 8-neighbour of the same sign.
bool isPeak(const PlaneGrid& g, const std::vector<double>& omega, int i, int j) {
  const double w = omega[g.index(i, j)];
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di) {
      const int ni = i + di, nj = j + dj;
      if ((di == 0 && dj == 0) || ni < 0 || nj < 0 || ni >= g.columns || nj >= g.rows) continue;
      const double o = omega[g.index(ni, nj)];
      if (std::isnan(o) || (o > 0) != (w > 0)) continue;
      if (std::abs(o) > std::abs(w)) return false;
    }
  return true;
}

}  // namespace

std::vector<VortexCore> findVortexCores(const PlaneGrid& g, const std::vector<double>& omega, double minPeak,
                                        const std::vector<double>* swirl) {
  // Candidates in order of falling |omega| (ties by node index: the same order every time).
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < omega.size(); ++k)
    if (!std::isnan(omega[k]) && std::abs(omega[k]) >= minPeak) order.push_back(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return std::abs(omega[a]) > std::abs(omega[b]); });
  std::vector<std::uint8_t> claimed(omega.size(), 0);
  std::vector<VortexCore> cores;
  std::vector<std::size_t> stack;
  const double area = g.spacing * g.spacing;
  for (const std::size_t start : order) {
    const int si = int(start % std::size_t(g.columns)), sj = int(start / std::size_t(g.columns));
    if (claimed[start] || !isPeak(g, omega, si, sj)) continue;
    if (swirl && !((*swirl)[start] >= kSwirlShare * 0.5 * std::abs(omega[start]))) continue;
    const double peak = omega[start];
    const double half = 0.5 * std::abs(peak);
    VortexCore core;
    core.peak = peak;
    double weight = 0;
    stack.assign(1, start);
    claimed[start] = 1;
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      const int i = int(k % std::size_t(g.columns)), j = int(k / std::size_t(g.columns));
      const double w = omega[k];
      core.circulation += w * area;
      weight += w;
      core.i += w * i;
      core.j += w * j;
      ++core.nodes;
      constexpr int kStep[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (const auto& s : kStep) {
        const int ni = i + s[0], nj = j + s[1];
        if (ni < 0 || nj < 0 || ni >= g.columns || nj >= g.rows) continue;
        const std::size_t nk = g.index(ni, nj);
        const double o = omega[nk];
        if (claimed[nk] || std::isnan(o) || (o > 0) != (peak > 0) || std::abs(o) < half) continue;
        claimed[nk] = 1;
        stack.push_back(nk);
      }
    }
    core.i /= weight;
    core.j /= weight;
    core.position = g.node(core.i, core.j);
    cores.push_back(core);
  }
  std::stable_sort(cores.begin(), cores.end(), [](const VortexCore& a, const VortexCore& b) {
    return std::abs(a.circulation) > std::abs(b.circulation);
  });
  return cores;
}

}  // namespace hs::pbd
