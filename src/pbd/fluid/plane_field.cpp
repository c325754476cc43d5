#include "pbd/fluid/plane_field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hs::pbd {

PlaneField sampleOnPlane(const PlaneGrid& grid, const Particles& particles, const PlaneSampling& sampling) {
  PlaneField field;
  field.grid = grid;
  const std::size_t n = grid.size();
  field.vu.assign(n, 0.0);
  field.vv.assign(n, 0.0);
  field.fill.assign(n, 0.0);
  field.filled.assign(n, 0);
  std::vector<double> weight(n, 0.0);
  const double h = sampling.h, h2 = h * h;
  // Poly6 (Mueller et al. 2003, eq. 20) in double: W(r) = 315 / (64 pi h^3) (1 - r^2/h^2)^3.
  const double coeff = 315.0 / (64.0 * std::numbers::pi * h * h * h);
  const Vec3d normal = grid.normal();
  const int reach = int(std::ceil(h / grid.spacing));
  for (std::size_t p = sampling.first; p < particles.size(); ++p) {
    if (!particles.active(p)) continue;
    const Vec3d d = particles.position[p].cast<double>() - grid.origin;
    const double off = normal.dot(d);
    if (std::abs(off) >= h) continue;
    // The particle's place on the grid, in node units, and its in-plane velocity.
    const double a = grid.u.dot(d) / grid.spacing, b = grid.v.dot(d) / grid.spacing;
    const Vec3d vel = particles.velocity[p].cast<double>();
    const double pu = grid.u.dot(vel), pv = grid.v.dot(vel);
    const int i0 = std::max(0, int(std::floor(a)) - reach), i1 = std::min(grid.columns - 1, int(std::ceil(a)) + reach);
    const int j0 = std::max(0, int(std::floor(b)) - reach), j1 = std::min(grid.rows - 1, int(std::ceil(b)) + reach);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double du = (a - i) * grid.spacing, dv = (b - j) * grid.spacing;
        const double r2 = du * du + dv * dv + off * off;
        if (r2 >= h2) continue;
        const double t = 1.0 - r2 / h2;
        const double w = coeff * t * t * t;
        const std::size_t k = grid.index(i, j);
        weight[k] += w;
        field.vu[k] += w * pu;
        field.vv[k] += w * pv;
      }
  }
  for (std::size_t k = 0; k < n; ++k) {
    field.fill[k] = weight[k] * sampling.particleVolume;
    if (field.fill[k] >= sampling.minFill && weight[k] > 0) {
      field.filled[k] = 1;
      field.vu[k] /= weight[k];
      field.vv[k] /= weight[k];
    } else {
      field.vu[k] = field.vv[k] = 0;
    }
  }
  return field;
}

}  // namespace hs::pbd
