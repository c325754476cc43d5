#include "cardiac/heart_sites.h"

#include <algorithm>
#include <cmath>

#include "cardiac/flow_path.h"
#include "pbd/cell_grid.h"
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
  if (sites.empty() || blood.empty() || !(h > 0)) return colour;
  // The blood binned in cells of edge h over its box (the engine's CellGrid); a site sums over
  // the cells of its box +- h, in the grid's fixed order, so the sum depends on the input alone.
  Vec3 lo = blood.front(), hi = lo;
  for (const Vec3& x : blood) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  pbd::CellIndexing cells;
  cells.coverWithin({double(lo[0]), double(lo[1]), double(lo[2])}, {double(hi[0]), double(hi[1]), double(hi[2])},
                    double(h), 8.0 * double(blood.size()) + 64, 1.001, 1e15);
  pbd::CellGrid grid;
  const bool binned = grid.bin(blood.size(), cells.cellCount(), 1, [&](std::size_t b, auto&& emit) {
    std::size_t cell = 0;
    if (cells.cellOf(blood[b], cell)) emit(cell);
  });
  if (!binned) return colour;
  const pbd::SphKernels kernels = pbd::makeSphKernels(h);
  const double volume = double(spacing) * double(spacing) * double(spacing);
  for (std::size_t s = 0; s < sites.size(); ++s) {
    pbd::CellBox r;
    if (!cells.cellRange(sites[s] - Vec3::Constant(h), sites[s] + Vec3::Constant(h), r)) continue;
    double sum = 0;
    grid.forEachItem(cells, r, [&](Index b) { sum += double(pbd::poly6(kernels, (blood[b] - sites[s]).squaredNorm())); });
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
