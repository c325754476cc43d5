#include "cardiac/heart_sites.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "cardiac/flow_path.h"
#include "pbd/sph_kernels.h"

namespace hs::cardiac {
namespace {

// Sites of a vertical lumen from `first` up to a particle radius `r` under `top`.
std::vector<Vec3> lumenColumn(const Orifice& lumen, Real first, Real top, Real r, Real d) {
  std::vector<Vec3> out;
  int layer = 0;
  for (Real y = first; y <= top - r + Real(1e-6) * d; y = first + Real(++layer) * d)
    for (const Vec3& site : lumenDiscSites(lumen, y, lumen.radius - r, d, layer % 2 == 1)) out.push_back(site);
  return out;
}

}  // namespace

std::vector<Vec3> cavitySites(const Scenario& scenario) {
  const Real d = scenario.blood.spacing, r = scenario.blood.radius;
  const LvGeometryParams& g = scenario.geometry;
  const Real a = g.endoRadius - r, c = g.endoLongAxis - r;
  std::vector<Vec3> x;
  if (!(a > 0 && c > 0 && d > 0)) return x;
  const Orifice axis{Vec3::Zero(), Vec3::UnitY(), a};
  int layer = 0;
  for (Real y = -r; y >= -c; y = -r - Real(++layer) * d) {
    const Real reach = a * std::sqrt(std::max(Real(0), 1 - (y / c) * (y / c)));  // the section's radius
    for (const Vec3& site : lumenDiscSites(axis, y, reach, d, layer % 2 == 1)) x.push_back(site);
  }
  return x;
}

VesselSites vesselSites(const Scenario& scenario, const LvModel& model) {
  const Real d = scenario.blood.spacing, r = scenario.blood.radius;
  const FlowPath& path = model.flowPath;
  VesselSites sites;
  sites.lowest = -r + d;  // a spacing above the cavity's top layer
  if (!(d > 0)) return sites;
  sites.inflow = lumenColumn(path.mitral, sites.lowest, path.inflowTop, r, d);
  sites.outflow = lumenColumn(path.aortic, sites.lowest, path.outflowTop, r, d);
  std::vector<Vec3> full = cavitySites(scenario);
  full.insert(full.end(), sites.inflow.begin(), sites.inflow.end());
  full.insert(full.end(), sites.outflow.begin(), sites.outflow.end());
  sites.inflowFull = bloodColour(sites.inflow, full, d, scenario.blood.supportRadius);
  sites.outflowFull = bloodColour(sites.outflow, full, d, scenario.blood.supportRadius);
  return sites;
}

void VesselSites::drop(const std::function<bool(const Vec3&)>& dropped) {
  auto filter = [&](std::vector<Vec3>& sites, std::vector<double>& full) {
    std::size_t kept = 0;
    for (std::size_t s = 0; s < sites.size(); ++s) {
      if (dropped(sites[s])) continue;
      sites[kept] = sites[s];
      full[kept] = full[s];
      ++kept;
    }
    sites.resize(kept);
    full.resize(kept);
  };
  filter(inflow, inflowFull);
  filter(outflow, outflowFull);
}

std::vector<Vec3> heartSites(const Scenario& scenario, const LvModel& model) {
  std::vector<Vec3> x = cavitySites(scenario);
  const VesselSites vessels = vesselSites(scenario, model);
  x.insert(x.end(), vessels.inflow.begin(), vessels.inflow.end());
  x.insert(x.end(), vessels.outflow.begin(), vessels.outflow.end());
  return x;
}

std::vector<double> bloodColour(const std::vector<Vec3>& sites, const std::vector<Vec3>& blood, Real spacing,
                                Real supportRadius) {
  std::vector<double> colour(sites.size(), 0.0);
  const Real h = supportRadius;
  if (sites.empty() || !(h > 0)) return colour;
  // Blood sorted by its cell of edge h (a key packing the three cell indices, 21 bits each, so
  // distinct cells never share one); a site sums over its 27 cells in a fixed order, each
  // cell's blood in index order, so the sum does not depend on anything but the input.
  auto cellOf = [h](const Vec3& p) {
    return std::array<std::int64_t, 3>{std::int64_t(std::floor(p.x() / h)), std::int64_t(std::floor(p.y() / h)),
                                       std::int64_t(std::floor(p.z() / h))};
  };
  constexpr std::int64_t kBias = std::int64_t(1) << 20, kMask = (std::int64_t(1) << 21) - 1;
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (((i + kBias) & kMask) << 42) | (((j + kBias) & kMask) << 21) | ((k + kBias) & kMask);
  };
  std::vector<std::pair<std::int64_t, std::size_t>> cells(blood.size());
  for (std::size_t b = 0; b < blood.size(); ++b) {
    const auto c = cellOf(blood[b]);
    cells[b] = {key(c[0], c[1], c[2]), b};
  }
  std::sort(cells.begin(), cells.end());
  const pbd::SphKernels kernels = pbd::makeSphKernels(h);
  const double volume = double(spacing) * double(spacing) * double(spacing);
  for (std::size_t s = 0; s < sites.size(); ++s) {
    const auto c = cellOf(sites[s]);
    double sum = 0;
    for (std::int64_t dk = -1; dk <= 1; ++dk)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t di = -1; di <= 1; ++di) {
          const std::int64_t k = key(c[0] + di, c[1] + dj, c[2] + dk);
          auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(k, std::size_t(0)));
          for (; it != cells.end() && it->first == k; ++it)
            sum += double(pbd::poly6(kernels, (blood[it->second] - sites[s]).squaredNorm()));
        }
    colour[s] = volume * sum;
  }
  return colour;
}

double vesselFillShare(const std::vector<Vec3>& sites, const std::vector<double>& full,
                       const std::vector<Vec3>& blood, Real spacing, Real supportRadius) {
  if (sites.empty()) return 1;
  const std::vector<double> colour = bloodColour(sites, blood, spacing, supportRadius);
  std::size_t filled = 0;
  for (std::size_t s = 0; s < sites.size(); ++s) filled += colour[s] >= 0.5 * full[s];
  return double(filled) / double(sites.size());
}

}  // namespace hs::cardiac
