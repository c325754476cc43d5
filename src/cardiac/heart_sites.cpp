#include "cardiac/heart_sites.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "cardiac/anatomy/flow_path.h"
#include "mesh/surface_inside.h"
#include "pbd/core/closest_point.h"
#include "pbd/fluid/sph_kernels.h"
#include "pbd/grid/cell_grid.h"

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

// Sites across a lobed section (the sinuses of Valsalva) at height y: the axis, then n rings
// that each follow the lumen's shape, ring k at k/n of the reach rho(th) = radius(th) - r (n
// the mean reach in spacings), each with sites a spacing apart along its own length; `turned`
// turns them by half a site. Like lumenDiscSites for a round lumen: one site per d^2, out to a
// particle radius from the wall at every azimuth, with no gap between the lobes for blood to
// spread into (a round disc cut at the lobes' radius leaves half the sinuses empty).
std::vector<Vec3> lobedDiscSites(const Orifice& section, Real y, const std::function<double(double)>& reach, Real d,
                                 bool turned) {
  constexpr int kSamples = 720;
  const Vec3 centre(section.centre.x(), y, section.centre.z());
  std::vector<double> rho(kSamples + 1);
  double mean = 0;
  for (int j = 0; j <= kSamples; ++j) {
    rho[j] = std::max(0.0, reach(2 * std::numbers::pi * j / kSamples));
    if (j < kSamples) mean += rho[j] / kSamples;
  }
  std::vector<Vec3> sites{centre};
  const int rings = mean > 0 ? std::max(1, int(std::lround(mean / double(d)))) : 0;
  std::vector<double> along(kSamples + 1, 0.0);  // the ring's length from th = 0 to sample j
  auto at = [&](double share, double theta, double radius) -> Vec3 {
    const Vec3 offset(Real(share * radius * std::cos(theta)), 0, Real(share * radius * std::sin(theta)));
    return centre + offset;
  };
  for (int k = 1; k <= rings; ++k) {
    const double share = double(k) / rings;
    for (int j = 1; j <= kSamples; ++j) {
      const double t0 = 2 * std::numbers::pi * (j - 1) / kSamples, t1 = 2 * std::numbers::pi * j / kSamples;
      along[j] = along[j - 1] + double((at(share, t1, rho[j]) - at(share, t0, rho[j - 1])).norm());
    }
    const int count = std::max(1, int(std::lround(along[kSamples] / double(d))));
    int j = 1;
    for (int m = 0; m < count; ++m) {
      const double target = along[kSamples] * (m + (turned ? 0.5 : 0.0)) / count;
      while (j < kSamples && along[j] < target) ++j;
      const double f = (target - along[j - 1]) / std::max(along[j] - along[j - 1], 1e-300);
      const double theta = 2 * std::numbers::pi * (j - 1 + f) / kSamples;
      sites.push_back(at(share, theta, rho[j - 1] + f * (rho[j] - rho[j - 1])));
    }
  }
  return sites;
}

// The sites of a procedural vessel's lumen from `first` up to a particle radius under its far
// end, a layer a spacing: at each height the disc of the lumen's radius there (lumenDiscSites:
// rings evenly out to a particle radius from the wall, so an atrium's bulb fills as a straight
// vessel does), or where the sinuses bulge, rings that follow their lobes (lobedDiscSites).
// Where the vessel does not bulge this is the straight vessel's disc, and a straight vessel's
// column is lumenColumn's.
std::vector<Vec3> vesselColumn(const FlowPath& path, bool inflow, Real first, Real r, Real d) {
  const Orifice& orifice = inflow ? path.mitral : path.aortic;
  const Real top = inflow ? path.inflowTop : path.outflowTop;
  const VesselShape& shape = inflow ? path.inflowShape : path.outflowShape;
  if (shape.straight()) return lumenColumn(orifice, first, top, r, d);
  std::vector<Vec3> out;
  int layer = 0;
  for (Real y = first; y <= top - r + Real(1e-6) * d; y = first + Real(++layer) * d) {
    const Orifice section = inflow ? path.inflowSection(y) : path.outflowSection(y);
    const double u = FlowPath::heightShare(orifice, top, y);
    const bool turned = layer % 2 == 1;
    const std::vector<Vec3> disc =
        shape.lobes > 0 && shape.bulge(u) > 0
            ? lobedDiscSites(section, y,
                             [&](double theta) { return shape.radius(u, theta, double(orifice.radius)) - double(r); }, d,
                             turned)
            : lumenDiscSites(section, y, section.radius - r, d, turned);
    out.insert(out.end(), disc.begin(), disc.end());
  }
  return out;
}

// A patient's heart (FlowPath::cavity set, patient_vessels.h). Its cavity is no spheroid: the
// sites are a cubic lattice a spacing apart inside the endocardium closed over both annuli, and
// each vessel's column starts a particle radius above its own orifice's plane. Every site keeps a
// particle radius from the wall's surface (brute force over its faces, boxes first: once, at the
// start).
bool farFromWall(const LvModel& model, const Vec3& p, Real r) {
  const std::vector<Vec3>& x = model.mesh.vertices;
  for (const pbd::Triangle& t : model.surface) {
    const Vec3 lo = x[t[0]].cwiseMin(x[t[1]]).cwiseMin(x[t[2]]) - Vec3::Constant(r);
    const Vec3 hi = x[t[0]].cwiseMax(x[t[1]]).cwiseMax(x[t[2]]) + Vec3::Constant(r);
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
    // A site exactly a radius away passes, whatever the rounding: 0.1% of slack.
    const Real reach = Real(0.999) * r;
    if ((pbd::closestPointOnTriangleOf(p, x[t[0]], x[t[1]], x[t[2]]) - p).squaredNorm() < reach * reach) return false;
  }
  return true;
}

Real vesselStart(const Orifice& orifice, Real r) { return orifice.centre.y() + r; }

std::vector<Vec3> patientCavitySites(const Scenario& scenario, const LvModel& model) {
  const Real d = scenario.blood.spacing, r = scenario.blood.radius;
  std::vector<Vec3> x = model.mesh.vertices;
  const std::vector<pbd::Triangle> closed = closedOverAnnuli(model, x);
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::max()), hi = -lo;
  for (const pbd::Triangle& t : closed)
    for (Index v : t) {
      lo = lo.cwiseMin(x[v]);
      hi = hi.cwiseMax(x[v]);
    }
  const pbd::SurfaceInside cavity(x, closed, d);
  const FlowPath& path = model.flowPath;
  // Below the vessels' columns: a spacing under a column's first layer, within its lumen.
  auto underAColumn = [&](const Vec3& p) {
    for (const Orifice* o : {&path.mitral, &path.aortic})
      if (p.y() > vesselStart(*o, r) - d && o->radial(p) < o->radius) return false;
    return true;
  };
  std::vector<Vec3> sites;
  const Vec3 extent = (hi - lo) / d;
  const int nx = int(extent.x()) + 1, ny = int(extent.y()) + 1, nz = int(extent.z()) + 1;
  for (int j = ny - 1; j >= 0; --j)  // from the base down, as the spheroid's layers
    for (int i = 0; i < nx; ++i)
      for (int k = 0; k < nz; ++k) {
        const Vec3 p = lo + d * Vec3(Real(i) + Real(0.5), Real(j) + Real(0.5), Real(k) + Real(0.5));
        if (cavity.contains(p) && underAColumn(p) && farFromWall(model, p, r)) sites.push_back(p);
      }
  return sites;
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

std::vector<Vec3> cavitySites(const Scenario& scenario, const LvModel& model) {
  return model.flowPath.cavity ? patientCavitySites(scenario, model) : cavitySites(scenario);
}

VesselSites vesselSites(const Scenario& scenario, const LvModel& model) {
  const Real d = scenario.blood.spacing, r = scenario.blood.radius;
  const FlowPath& path = model.flowPath;
  VesselSites sites;
  sites.lowest = -r + d;  // a spacing above the cavity's top layer
  if (!(d > 0)) return sites;
  if (path.cavity) {
    // The vessel's lumen is the polygon of its ring's n vertices on the orifice's circle: its
    // sites reach to the polygon's inscribed circle, R cos(pi / n), less a particle radius.
    auto inscribed = [](Orifice o, std::size_t n) {
      o.radius *= std::cos(std::numbers::pi_v<Real> / Real(std::max<std::size_t>(n, 3)));
      return o;
    };
    const Real inflowStart = vesselStart(path.mitral, r), outflowStart = vesselStart(path.aortic, r);
    sites.lowest = std::min(inflowStart, outflowStart);
    sites.inflow = lumenColumn(inscribed(path.mitral, model.mitralRing.size()), inflowStart, path.inflowTop, r, d);
    sites.outflow = lumenColumn(inscribed(path.aortic, model.aorticRing.size()), outflowStart, path.outflowTop, r, d);
    for (std::vector<Vec3>* column : {&sites.inflow, &sites.outflow})
      std::erase_if(*column, [&](const Vec3& p) { return !farFromWall(model, p, r); });
  } else {
    sites.inflow = vesselColumn(path, true, sites.lowest, r, d);
    sites.outflow = vesselColumn(path, false, sites.lowest, r, d);
  }
  std::vector<Vec3> full = cavitySites(scenario, model);
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

VesselSites VesselSites::descended(const FlowPath& path, Real descent) const {
  VesselSites moved = *this;
  const FlowPath low = path.descended(descent);
  auto carry = [](std::vector<Vec3>& sites, const Orifice& rest, const Orifice& now, Real top) {
    for (Vec3& site : sites) {
      const double u = FlowPath::heightShare(rest, top, site.y());
      site.y() = now.centre.y() + Real(u * double(top - now.centre.y()));
    }
  };
  carry(moved.inflow, path.mitral, low.mitral, path.inflowTop);
  carry(moved.outflow, path.aortic, low.aortic, path.outflowTop);
  moved.lowest -= descent;
  return moved;
}

std::vector<Vec3> heartSites(const Scenario& scenario, const LvModel& model) {
  std::vector<Vec3> x = cavitySites(scenario, model);
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
