#include "cardiac/patient/patient_vessels.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "mesh/surface_inside.h"
#include "mesh/wall_extrusion.h"

namespace hs::cardiac {
namespace {

using Vec3d = Eigen::Vector3d;

std::string mm(double metres) {
  std::ostringstream os;
  os.precision(3);
  os << metres * 1000 << " mm";
  return os.str();
}

// The unit vector in the xz plane from the axis through `centre` toward x.
Vec3d radialFrom(const Vec3d& centre, const Vec3d& x) {
  Vec3d d = x - centre;
  d.y() = 0;
  const double n = d.norm();
  return n > 0 ? Vec3d(d / n) : Vec3d::UnitX();
}

// Appends 6V > 0 tets of a prism, the bottom's winding turned toward the top if it is not.
void addPrism(const std::vector<Vec3>& x, pbd::Triangle bottom, pbd::Triangle top, std::vector<pbd::Tet>& tets) {
  const Vec3d a = x[bottom[0]].cast<double>(), b = x[bottom[1]].cast<double>(), c = x[bottom[2]].cast<double>();
  const Vec3d rise = (x[top[0]] + x[top[1]] + x[top[2]] - x[bottom[0]] - x[bottom[1]] - x[bottom[2]]).cast<double>();
  if ((b - a).cross(c - a).dot(rise) < 0) {
    std::swap(bottom[1], bottom[2]);
    std::swap(top[1], top[2]);
  }
  for (const pbd::Tet& t : pbd::splitPrism(bottom, top)) tets.push_back(t);
}

// One vessel on `ring` (inner-layer model ids, in ring order). Layer k >= 1 of the lumen is the
// ring blended toward its circle by s_k = min(1, k / T), raised k h: p_k,j = (1 - s_k) P_j +
// s_k C_j + k h y^, where C_j is the circle's point at P_j's angle around the axis, at the ring's
// mean height. T layers take the ring's tilt out gradually, each rising at least h / 2.
// Returns the height of the vessel's far end.
Real addVessel(LvModel& model, const std::vector<Index>& ring, const Orifice& orifice, Real length,
                    const PatientVesselSizes& sizes, Region region) {
  std::vector<Vec3>& x = model.mesh.vertices;
  const std::size_t n = ring.size();
  const Vec3d centre = orifice.centre.cast<double>();
  const double h = double(sizes.edge), radius = double(orifice.radius);
  double tilt = 0;
  for (Index v : ring) tilt = std::max(tilt, std::abs(double(x[v].y()) - centre.y()));
  const int blend = std::max(2, int(std::ceil(2 * tilt / h)));
  const int layers = std::max(blend + 1, int(std::ceil(double(length) / h)));
  // Vertex ids: layer k >= 1, ring position j -> inner first + 2 (n (k - 1) + j), outer + 1.
  const auto first = Index(x.size());
  auto inner = [&](int k, std::size_t j) { return k == 0 ? ring[j] : first + Index(2 * (n * std::size_t(k - 1) + j)); };
  auto outer = [&](int k, std::size_t j) { return inner(k, j) + 1; };
  for (int k = 1; k <= layers; ++k) {
    const double s = std::min(1.0, double(k) / double(blend));
    for (std::size_t j = 0; j < n; ++j) {
      const Vec3d ringPoint = x[ring[j]].cast<double>();
      const Vec3d toward = radialFrom(centre, ringPoint);
      const Vec3d circle(centre.x() + radius * toward.x(), centre.y(), centre.z() + radius * toward.z());
      const Vec3d lumen = (1 - s) * ringPoint + s * circle + Vec3d(0, double(k) * h, 0);
      x.push_back(lumen.cast<Real>());
      x.push_back((lumen + double(sizes.wallThickness) * radialFrom(centre, lumen)).cast<Real>());
      model.region.push_back(region);
      model.region.push_back(region);
      model.segment.push_back(0);
      model.segment.push_back(0);
    }
  }
  std::vector<pbd::Tet>& tets = model.mesh.tets;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t j1 = (j + 1) % n;
    // The wedge on the ring's edge: its cross-section (P_j, lumen_1,j, outer_1,j) swept to j + 1.
    addPrism(x, {inner(0, j), inner(1, j), outer(1, j)}, {inner(0, j1), inner(1, j1), outer(1, j1)}, tets);
    for (int k = 1; k < layers; ++k) {
      addPrism(x, {inner(k, j), inner(k, j1), inner(k + 1, j)}, {outer(k, j), outer(k, j1), outer(k + 1, j)}, tets);
      addPrism(x, {inner(k, j1), inner(k + 1, j1), inner(k + 1, j)}, {outer(k, j1), outer(k + 1, j1), outer(k + 1, j)},
               tets);
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    model.pinned.insert(model.pinned.end(), {inner(layers, j), outer(layers, j)});
    for (int k = 1; k < layers; ++k) {
      const Real share = Real(1) - Real(k) / Real(layers);
      model.vesselFollowers.push_back({inner(k, j), ring[j], share});
      model.vesselFollowers.push_back({outer(k, j), ring[j], share});
    }
  }
  return Real(centre.y() + double(layers) * h);
}

// The mid-wall surface closed over both annuli: the cavity test of a patient's flow path.
std::shared_ptr<const pbd::SurfaceInside> midWallCavity(const LvModel& model, Real column) {
  const std::vector<Vec3>& x = model.mesh.vertices;
  std::vector<Vec3> mid(x.size());
  for (std::size_t v = 0; v + 1 < x.size(); v += 2) mid[v] = mid[v + 1] = Real(0.5) * (x[v] + x[v + 1]);
  std::vector<pbd::Triangle> triangles = closedOverAnnuli(model, mid);
  return std::make_shared<const pbd::SurfaceInside>(std::move(mid), std::move(triangles), column);
}

// A valve in its ring's plane: the ring's centroid, the unit normal of its fan's area
// (1/2 sum (p_k - c) x (p_k+1 - c), toward the base: the fan faces +y, lv_model.h) times
// `towardFlow` (-1 into the cavity for the mitral valve, +1 out of it for the aortic), and a
// radius out to the ring's farthest vertex (at least the lumen's), so the closed valve walls off
// the whole opening however oval and tilted the ring is, and no more.
Orifice valveDisc(const LvModel& model, const std::vector<Index>& ring, const Orifice& lumen, double towardFlow) {
  const std::vector<Vec3>& x = model.mesh.vertices;
  Vec3d centroid = Vec3d::Zero();
  for (Index v : ring) centroid += x[v].cast<double>();
  centroid /= double(ring.size());
  Vec3d area = Vec3d::Zero();
  for (std::size_t k = 0; k < ring.size(); ++k)
    area += 0.5 * (x[ring[k]].cast<double>() - centroid).cross(x[ring[(k + 1) % ring.size()]].cast<double>() - centroid);
  Orifice disc;
  disc.centre = centroid.cast<Real>();
  disc.forward = (towardFlow * area.normalized()).cast<Real>();
  disc.radius = lumen.radius;
  for (Index v : ring) disc.radius = std::max(disc.radius, disc.radial(x[v]));
  return disc;
}

}  // namespace

void attachPatientVessels(LvModel& model, const PatientVesselSizes& sizes) {
  FlowPath& path = model.flowPath;
  // The lumens must not reach into each other's walls.
  Vec3 apart = path.aortic.centre - path.mitral.centre;
  apart.y() = 0;
  const Real needed = path.mitral.radius + path.aortic.radius + sizes.wallThickness;
  if (!(apart.norm() >= needed))
    throw std::invalid_argument("the vessels on the mitral and aortic annuli would overlap: their axes are " +
                                mm(double(apart.norm())) + " apart, expected at least " + mm(double(needed)) +
                                " (the two orifices' radii and a vessel wall)");
  // Columns (and cubes) of half an edge: a particle in a cube no triangle's box reaches is
  // answered at once, and at half an edge most of the cavity's blood is (the meter asks for
  // every particle every step: 0.24 -> 0.12 ms a step on the coarse wall, the same answers).
  path.cavity = midWallCavity(model, Real(0.5) * sizes.edge);
  path.mitralValveDisc = valveDisc(model, model.mitralRing, path.mitral, -1);
  path.aorticValveDisc = valveDisc(model, model.aorticRing, path.aortic, +1);
  const Real inflowTop = addVessel(model, model.mitralRing, path.mitral, sizes.inflowLength, sizes, Region::InflowVessel);
  const Real outflowTop =
      addVessel(model, model.aorticRing, path.aortic, sizes.outflowLength, sizes, Region::OutflowVessel);
  std::sort(model.pinned.begin(), model.pinned.end());
  for (const pbd::Tet& t : model.mesh.tets) {
    const std::vector<Vec3>& x = model.mesh.vertices;
    if (!(pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]) > 0))
      throw std::invalid_argument("a vessel on an annulus came out inverted at vertex " + std::to_string(t[0]) +
                                  " (a ring too twisted for a straight vessel); choose other annuli (model.mitral_loop, "
                                  "model.aortic_loop)");
  }
  model.surface = pbd::boundaryFaces(model.mesh.tets);
  path.inflowTop = inflowTop;
  path.outflowTop = outflowTop;
  path.inflowLength = path.inflowTop - path.mitral.centre.y();
  LvGeometryParams& g = model.params;
  g.inflowVesselLength = path.inflowTop - path.mitral.centre.y();
  g.outflowVesselLength = path.outflowTop - path.aortic.centre.y();
  g.vesselWallThickness = sizes.wallThickness;
  g.baseThickness = sizes.edge;
}

}  // namespace hs::cardiac
