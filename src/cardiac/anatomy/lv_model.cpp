#include "cardiac/anatomy/lv_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cardiac/anatomy/aha_segments.h"
#include "cardiac/anatomy/lv_mid_surface.h"
#include "cardiac/anatomy/vessel_shape.h"

namespace hs::cardiac {

namespace {

using detail::Vec3d;

// Element edge length at resolution 1 relative to the endocardial radius a, chosen so the
// default model has about as many vertices as the thesis model (1,061): h = 0.21 a / resolution
// (a uniformly scaled model keeps its mesh).
constexpr double kEdgePerRadius = 0.21;
constexpr double kMinResolution = 0.25;
constexpr double kMaxResolution = 8.0;
// Proportions the mesher is built for: a ventricle at most this many endocardial radii long,
// vessels at most this many radii long and a wall at most this many radii thick. A real heart
// is about 2 radii long; the element size follows the radius, so a needle 1e6 m long would mesh
// for a minute into millions of elements before anything else could refuse it.
constexpr double kMaxLengthInRadii = 20.0;
// The least wall, plate, vessel length and aortic orifice, in cavity radii (validate). The vessel
// wall's is lower than the meshes need (about 0.006 at resolution 1): thinner walls with wide
// orifices leave slivers of plate that the plate's size check must still see.
constexpr double kMinWallInRadii = 0.1, kMinBaseInRadii = 0.05, kMinVesselWallInRadii = 0.001;
constexpr double kMinVesselLengthInRadii = 0.2, kMinAorticInRadii = 0.1;
constexpr double kMaxWallInRadii = 0.5;

// The gap between the orifices and between each orifice and the rim, in units of the vessel
// wall thickness: the outer walls must leave at least one wall thickness of plate between them.
constexpr double kMinGapInWalls = 3.0;
// The base plate is meshed at the gap's size where the gap is narrower than the elements, and
// its planar Delaunay grows faster than linearly: 20,000 points take about 5 s, 300,000 would
// take hours. The finest resolution of the default sizes needs about 5,300.
constexpr double kMaxPlatePoints = 25000;

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

[[noreturn]] void fail(const std::string& key, const std::string& what) {
  throw std::invalid_argument("model." + key + ": " + what);
}

// An anatomical heart's vessels (vessel_shape.h), as shares u of each vessel's height above the
// orifice, all from kShapeFrom above the plate's top (the mesh's first row is the sheared one):
// the sinuses of Valsalva over the next 45% of the root, with a commissure (no lobe) toward the
// mitral side; the atrium to 85% of the inflow; both vessels lean away from each other up to half
// their height.
constexpr double kShapeFrom = 0.1;
constexpr double kSinusShare = 0.45;
constexpr double kAtriumTo = 0.85;
constexpr double kLeanTo = 0.5;
constexpr double kMaxLeanDeg = 40;
constexpr double kMaxSinusInRadii = 2.5, kMaxAtriumInRadii = 3.0;
constexpr double kMaxLeafletInLongAxes = 0.5;

enum class VesselKind { Inflow, Outflow };

VesselShape vesselShape(const LvGeometryParams& p, VesselKind kind) {
  const bool inflow = kind == VesselKind::Inflow;
  const double height = double(p.baseThickness) + double(inflow ? p.inflowVesselLength : p.outflowVesselLength);
  const double from = double(p.baseThickness) / height + kShapeFrom;
  VesselShape s;
  s.awayX = inflow ? -1 : 1;  // the mitral orifice sits at -x, the aortic at +x
  s.bendFrom = from;
  s.bendEnd = std::max(kLeanTo, from + 0.1);
  // Steepest slope of offset S(t) over (bendEnd - bendFrom) of a height L: 1.5 offset / (...).
  s.offset = std::tan(double(p.vesselLeanDeg) * std::numbers::pi / 180) * (s.bendEnd - s.bendFrom) * height / 1.5;
  if (inflow && p.atriumRadius > 0) {
    s.bulgeRadius = p.atriumRadius;
    s.bulgeFrom = from;
    s.bulgeTo = std::max(kAtriumTo, from + 0.1);
  }
  if (!inflow && p.aorticSinusRadius > 0) {
    s.bulgeRadius = p.aorticSinusRadius;
    s.bulgeFrom = from;
    s.bulgeTo = from + kSinusShare;
    s.lobes = 3;
    s.lobePhase = 0;  // lobes at 0, 120 and 240 degrees: the commissure at 180 faces the mitral side
  }
  return s;
}

void validate(const LvGeometryParams& p) {
  const std::pair<const char*, Real> positive[] = {{"endo_radius", p.endoRadius},
                                                   {"endo_long_axis", p.endoLongAxis},
                                                   {"wall_thickness", p.wallThickness},
                                                   {"base_thickness", p.baseThickness},
                                                   {"mitral_radius", p.mitralRadius},
                                                   {"aortic_radius", p.aorticRadius},
                                                   {"vessel_wall_thickness", p.vesselWallThickness},
                                                   {"inflow_vessel_length", p.inflowVesselLength},
                                                   {"outflow_vessel_length", p.outflowVesselLength},
                                                   {"resolution", p.resolution}};
  for (const auto& [key, value] : positive) {
    if (!std::isfinite(value) || !(value > 0)) fail(key, "must be positive and finite, got " + fmt(value));
  }
  if (p.resolution < Real(kMinResolution) || p.resolution > Real(kMaxResolution)) {
    fail("resolution",
         "must be in [" + fmt(kMinResolution) + ", " + fmt(kMaxResolution) + "], got " + fmt(p.resolution));
  }
  if (!(p.mitralRadius > p.aorticRadius)) {
    fail("mitral_radius", "must be larger than model.aortic_radius (" + fmt(p.aorticRadius) + " m), got " +
                              fmt(p.mitralRadius));
  }
  const std::pair<const char*, Real> lengths[] = {{"endo_long_axis", p.endoLongAxis},
                                                  {"wall_thickness", p.wallThickness},
                                                  {"inflow_vessel_length", p.inflowVesselLength},
                                                  {"outflow_vessel_length", p.outflowVesselLength}};
  for (const auto& [key, value] : lengths) {
    if (double(value) > kMaxLengthInRadii * double(p.endoRadius))
      fail(key, "must be at most " + fmt(kMaxLengthInRadii) + " x model.endo_radius (" +
                    fmt(kMaxLengthInRadii * double(p.endoRadius)) + " m) for a mesh of the heart's proportions, got " +
                    fmt(value));
  }
  // The thinnest parts a mesh holds without flat tets, as shares of the cavity's radius: below
  // them buildLvModel finds a degenerate tet at some resolution from 0.25 to 8 on heart-only's
  // and normal's sizes (docs/reliability.md); every built-in scenario's parts are thicker.
  const std::pair<const char*, std::pair<Real, double>> thinnest[] = {
      {"wall_thickness", {p.wallThickness, kMinWallInRadii}},
      {"base_thickness", {p.baseThickness, kMinBaseInRadii}},
      {"vessel_wall_thickness", {p.vesselWallThickness, kMinVesselWallInRadii}},
      {"inflow_vessel_length", {p.inflowVesselLength, kMinVesselLengthInRadii}},
      {"outflow_vessel_length", {p.outflowVesselLength, kMinVesselLengthInRadii}},
      {"aortic_radius", {p.aorticRadius, kMinAorticInRadii}}};
  for (const auto& [key, valueAndShare] : thinnest) {
    const auto [value, share] = valueAndShare;
    if (double(value) < share * double(p.endoRadius))
      fail(key, "must be at least " + fmt(share) + " x model.endo_radius (" + fmt(share * double(p.endoRadius)) +
                    " m) for a mesh without flat tets, got " + fmt(value));
  }
  // A wall at most half the cavity's radius (every built-in's is under 0.45): paper-chamber-beating
  // with a wall as thick as its radius inverted a tet within 4 steps of the beat, at 0.5 it beats.
  if (double(p.wallThickness) > kMaxWallInRadii * double(p.endoRadius))
    fail("wall_thickness", "must be at most " + fmt(kMaxWallInRadii) + " x model.endo_radius (" +
                               fmt(kMaxWallInRadii * double(p.endoRadius)) + " m), got " + fmt(p.wallThickness));
  // A cavity at least as long as it is wide (even a dilated ventricle's is about twice): a
  // shorter one leaves flat tets at the apex (dilated-cardiomyopathy at 0.005 m, 0.125 radii).
  if (p.endoLongAxis < p.endoRadius)
    fail("endo_long_axis", "must be at least model.endo_radius (" + fmt(p.endoRadius) + " m), got " +
                               fmt(p.endoLongAxis));
  if (!(p.baseThickness < p.endoLongAxis)) {
    fail("base_thickness", "must be smaller than model.endo_long_axis (" + fmt(p.endoLongAxis) + " m), got " +
                               fmt(p.baseThickness));
  }
  // Orifices side by side on the x axis with three equal gaps g (rim, between, rim):
  // 2a = 2 Rm + 2 Ra + 3 g, and g >= kMinGapInWalls * w.
  const double need =
      double(p.mitralRadius) + double(p.aorticRadius) + 1.5 * kMinGapInWalls * p.vesselWallThickness;
  if (!(need < double(p.endoRadius))) {
    fail("mitral_radius", "orifices do not fit in the base plate: need mitral_radius + aortic_radius + " +
                              fmt(1.5 * kMinGapInWalls) + " * vessel_wall_thickness < endo_radius (" +
                              fmt(p.endoRadius) + " m), got " + fmt(need));
  }
  const std::pair<const char*, Real> shapes[] = {{"aortic_sinus_radius", p.aorticSinusRadius},
                                                 {"atrium_radius", p.atriumRadius},
                                                 {"vessel_lean_deg", p.vesselLeanDeg},
                                                 {"mitral_leaflet_length", p.mitralLeafletLength}};
  for (const auto& [key, value] : shapes)
    if (!std::isfinite(value) || value < 0) fail(key, "must be 0 (none) or positive and finite, got " + fmt(value));
  if (p.aorticSinusRadius > 0 && !(p.aorticSinusRadius > p.aorticRadius &&
                                   double(p.aorticSinusRadius) <= kMaxSinusInRadii * double(p.aorticRadius)))
    fail("aortic_sinus_radius", "must be 0 (a straight root) or within (model.aortic_radius, " + fmt(kMaxSinusInRadii) +
                                    " x model.aortic_radius] = (" + fmt(p.aorticRadius) + ", " +
                                    fmt(kMaxSinusInRadii * double(p.aorticRadius)) + "] m, got " +
                                    fmt(p.aorticSinusRadius));
  if (p.atriumRadius > 0 &&
      !(p.atriumRadius > p.mitralRadius && double(p.atriumRadius) <= kMaxAtriumInRadii * double(p.mitralRadius)))
    fail("atrium_radius", "must be 0 (no atrium) or within (model.mitral_radius, " + fmt(kMaxAtriumInRadii) +
                              " x model.mitral_radius] = (" + fmt(p.mitralRadius) + ", " +
                              fmt(kMaxAtriumInRadii * double(p.mitralRadius)) + "] m, got " + fmt(p.atriumRadius));
  if (double(p.vesselLeanDeg) > kMaxLeanDeg)
    fail("vessel_lean_deg", "must be within [0, " + fmt(kMaxLeanDeg) + "] degrees, got " + fmt(p.vesselLeanDeg));
  // An adult's leaflets reach a quarter of the way to the apex; past the middle they would meet
  // the apex as the ventricle empties.
  if (double(p.mitralLeafletLength) > kMaxLeafletInLongAxes * double(p.endoLongAxis))
    fail("mitral_leaflet_length", "must be within [0, " + fmt(kMaxLeafletInLongAxes) + " x model.endo_long_axis] = [0, " +
                                      fmt(kMaxLeafletInLongAxes * double(p.endoLongAxis)) + "] m, got " +
                                      fmt(p.mitralLeafletLength));
  // The plate's lattice: one point per sqrt(3)/2 h^2 of the disc, h the smaller of the element
  // size and the gap (makeDims), counted before anything is meshed.
  const double a = double(p.endoRadius);
  const double gap = (2 * a - 2 * double(p.mitralRadius) - 2 * double(p.aorticRadius)) / 3;
  const double plateH = std::min(kEdgePerRadius * a / double(p.resolution), gap);
  const double points = std::numbers::pi * a * a / (0.8660254037844386 * plateH * plateH);
  if (points > kMaxPlatePoints) {
    fail("mitral_radius", "the base plate's gaps between the orifices and the rim (" + fmt(gap) +
                              " m) would need about " + fmt(std::round(points)) + " mesh points, more than " +
                              fmt(kMaxPlatePoints) + "; widen them (smaller model.mitral_radius or "
                              "model.aortic_radius, or a larger model.endo_radius) or lower model.resolution");
  }
}

detail::ShellDims makeDims(const LvGeometryParams& p) {
  detail::ShellDims d;
  d.a = p.endoRadius;
  d.c = p.endoLongAxis;
  d.t = p.wallThickness;
  d.baseThickness = p.baseThickness;
  d.vesselWall = p.vesselWallThickness;
  d.h = nominalEdgeLength(p);
  const double gap = (2 * d.a - 2 * double(p.mitralRadius) - 2 * double(p.aorticRadius)) / 3;
  d.plateH = std::min(d.h, gap);
  d.mitral = {{-d.a + gap + double(p.mitralRadius), 0}, p.mitralRadius, p.inflowVesselLength,
              Region::InflowVessel, vesselShape(p, VesselKind::Inflow)};
  d.aortic = {{d.a - gap - double(p.aorticRadius), 0}, p.aorticRadius, p.outflowVesselLength,
              Region::OutflowVessel, vesselShape(p, VesselKind::Outflow)};
  return d;
}

// The two vessels' outer walls, level by level above the plate: their axes must stay apart by
// both largest outer radii and one more wall. Sections are horizontal (vessel_shape.h), so
// levels that clear each other mean vessels that do. Read from the dimensions the mesh is built
// from (makeDims: the orifices' places and the vessels' shapes).
void validateVesselClearance(const detail::ShellDims& d) {
  const detail::ShellDims::Orifice &inflow = d.mitral, &outflow = d.aortic;
  if (inflow.shape.straight() && outflow.shape.straight()) return;
  const double bt = d.baseThickness, w = d.vesselWall;
  const double topIn = bt + inflow.length, topOut = bt + outflow.length;
  constexpr int kLevels = 400;
  for (int k = 0; k <= kLevels; ++k) {
    const double y = bt + (std::min(topIn, topOut) - bt) * k / kLevels;
    const double uIn = y / topIn, uOut = y / topOut;
    const double apart =
        (outflow.centre.x() + outflow.shape.shift(uOut)) - (inflow.centre.x() - inflow.shape.shift(uIn));
    const double need = inflow.shape.maxRadius(uIn, inflow.radius) + outflow.shape.maxRadius(uOut, outflow.radius) + 3 * w;
    if (apart < need)
      fail(outflow.shape.bulgeRadius > 0 ? "aortic_sinus_radius" : "atrium_radius",
           "the atrium and the aortic root would come within a vessel wall of each other " + fmt(y) +
               " m above the base (axes " + fmt(apart) + " m apart, " + fmt(need) +
               " m needed); expected a larger model.vessel_lean_deg, smaller bulges or longer vessels");
  }
}

// Inner-layer ids of an orifice ring, ordered so the fan (centroid, r_k, r_k+1) faces +y.
std::vector<Index> fanRing(const detail::MidSurface& s, const detail::Ring& ring) {
  std::vector<Index> ids;
  Vec3d centroid = Vec3d::Zero();
  for (Index id : ring.ids) {
    ids.push_back(2 * id);
    centroid += s.inner[id];
  }
  centroid /= double(ring.ids.size());
  double ny = 0;
  for (std::size_t k = 0; k < ring.ids.size(); ++k) {
    const Vec3d& a = s.inner[ring.ids[k]];
    const Vec3d& b = s.inner[ring.ids[(k + 1) % ring.ids.size()]];
    ny += (a - centroid).cross(b - centroid).y();
  }
  if (ny < 0) std::reverse(ids.begin(), ids.end());
  return ids;
}

}  // namespace

namespace {
LvModel buildValidatedLvModel(const LvGeometryParams& params);
}  // namespace

namespace {

Orifice orificeOf(const LvModel& model, const std::vector<Index>& ring, Real radius, const Vec3& forward) {
  Orifice o;
  Vec3 centroid = Vec3::Zero();
  for (Index v : ring) centroid += model.mesh.vertices[v];
  o.centre = centroid / Real(ring.size());
  o.forward = forward;
  o.radius = radius;
  return o;
}

// The flow path of the finished model's rest shape (flow_path.h).
FlowPath flowPathOf(const LvModel& model) {
  const LvGeometryParams& g = model.params;
  FlowPath f;
  f.mitral = orificeOf(model, model.mitralRing, g.mitralRadius, -Vec3::UnitY());
  f.aortic = orificeOf(model, model.aorticRing, g.aorticRadius, Vec3::UnitY());
  f.inflowTop = f.mitral.centre.y() + g.baseThickness + g.inflowVesselLength;
  f.outflowTop = f.aortic.centre.y() + g.baseThickness + g.outflowVesselLength;
  f.inflowLength = f.inflowTop - f.mitral.centre.y();
  f.apexAxisOrigin = Vec3(0, f.mitral.centre.y(), 0);
  f.midWallRadius = g.endoRadius + Real(0.5) * g.wallThickness;
  f.midWallLongAxis = g.endoLongAxis + Real(0.5) * g.wallThickness;
  f.plateMid = Real(0.5) * g.baseThickness;
  f.inflowShape = vesselShape(g, VesselKind::Inflow);
  f.outflowShape = vesselShape(g, VesselKind::Outflow);
  f.mitralLeafletLength = g.mitralLeafletLength;
  return f;
}

}  // namespace

double nominalEdgeLength(const LvGeometryParams& params) {
  return kEdgePerRadius * double(params.endoRadius) / double(params.resolution);
}

LvModel buildLvModel(const LvGeometryParams& params) {
  validate(params);
  validateVesselClearance(makeDims(params));
  try {
    return buildValidatedLvModel(params);
  } catch (const std::logic_error& e) {
    // Each parameter passed its own check, but together they leave no room for a valid mesh. When
    // the same sizes mesh at the thesis's resolution, the resolution is the key to change (the
    // real-size hearts' thin vessel walls at the coarsest, a thick wall at the finest).
    std::string remedy = "change the [model] sizes";
    if (params.resolution != Real(1)) {
      LvGeometryParams atOne = params;
      atOne.resolution = 1;
      try {
        buildLvModel(atOne);
        remedy = "they mesh at model.resolution = 1, so bring model.resolution (" + fmt(params.resolution) +
                 ") nearer 1, or change the [model] sizes";
      } catch (const std::invalid_argument&) {  // the sizes alone: the first remedy stands
      }
    }
    throw std::invalid_argument(std::string("model: these parameters give no valid mesh (") + e.what() + "); " +
                                remedy);
  }
}

namespace {
LvModel buildValidatedLvModel(const LvGeometryParams& params) {
  const detail::ShellDims d = makeDims(params);
  detail::MidSurface s;
  const detail::Ring rim = detail::addCup(s, d);
  detail::Ring mitralTop;
  detail::Ring aorticTop;
  const detail::Ring mitral = detail::addVessel(s, d, d.mitral, mitralTop);
  const detail::Ring aortic = detail::addVessel(s, d, d.aortic, aorticTop);
  detail::addBasePlate(s, d, rim, mitral, aortic);
  detail::orientTriangles(s);

  LvModel model;
  model.params = params;
  model.mesh = detail::extrudeShell(s);
  model.surface = pbd::boundaryFaces(model.mesh.tets);
  const std::size_t n = model.mesh.vertices.size();
  model.region.resize(n);
  model.segment.assign(n, 0);
  Vec3d centre = Vec3d::Zero();
  std::size_t myocardium = 0;
  for (std::size_t v = 0; v < n; ++v) {
    // Both layers take the segment of their endocardial partner: segments are transmural.
    model.region[v] = s.region[v / 2];
    if (model.region[v] != Region::Myocardium) continue;
    model.segment[v] = ahaSegment(s.inner[v / 2], d.c);
    centre += model.mesh.vertices[v].cast<double>();
    ++myocardium;
  }
  model.centre = (centre / double(myocardium)).cast<Real>();
  for (const detail::Ring* top : {&mitralTop, &aorticTop}) {
    for (Index id : top->ids) {
      model.pinned.push_back(2 * id);
      model.pinned.push_back(2 * id + 1);
    }
  }
  std::sort(model.pinned.begin(), model.pinned.end());
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const pbd::Triangle& t = s.triangles[i];
    if (s.cavity[i]) model.cavitySurface.push_back({2 * t[0], 2 * t[1], 2 * t[2]});
  }
  model.mitralRing = fanRing(s, mitral);
  model.aorticRing = fanRing(s, aortic);
  model.longAxisLength = Real(d.c + d.t);
  model.flowPath = flowPathOf(model);
  return model;
}

}  // namespace

Real cavityVolume(const LvModel& model, const std::vector<Vec3>& positions) {
  // V = (1/6) sum (a x b) . c over the closed, outward-oriented cavity boundary.
  auto term = [](const Vec3d& a, const Vec3d& b, const Vec3d& c) { return a.cross(b).dot(c); };
  double sum = 0;
  for (const pbd::Triangle& f : model.cavitySurface) {
    sum +=
        term(positions[f[0]].cast<double>(), positions[f[1]].cast<double>(), positions[f[2]].cast<double>());
  }
  for (const std::vector<Index>* ring : {&model.mitralRing, &model.aorticRing}) {
    if (ring->empty()) continue;
    Vec3d centroid = Vec3d::Zero();
    for (Index v : *ring) centroid += positions[v].cast<double>();
    centroid /= double(ring->size());
    for (std::size_t k = 0; k < ring->size(); ++k) {
      sum += term(centroid, positions[(*ring)[k]].cast<double>(),
                  positions[(*ring)[(k + 1) % ring->size()]].cast<double>());
    }
  }
  return Real(sum / 6.0);
}

std::vector<pbd::Triangle> closedOverAnnuli(const LvModel& model, std::vector<Vec3>& vertices) {
  std::vector<pbd::Triangle> closed = model.cavitySurface;
  for (const std::vector<Index>* ring : {&model.mitralRing, &model.aorticRing}) {
    if (ring->empty()) continue;
    Vec3 centroid = Vec3::Zero();
    for (Index v : *ring) centroid += vertices[v];
    vertices.push_back(centroid / Real(ring->size()));
    const auto c = Index(vertices.size() - 1);
    for (std::size_t k = 0; k < ring->size(); ++k) closed.push_back({c, (*ring)[k], (*ring)[(k + 1) % ring->size()]});
  }
  return closed;
}

double myocardiumShare(const LvModel& model, const std::vector<Index>& vertices) {
  auto cavitySide = [&model](Index v) { return v % 2 == 0 && model.region[v] == Region::Myocardium; };
  std::size_t all = 0;
  for (std::size_t v = 0; v < model.region.size(); ++v) all += cavitySide(Index(v));
  const auto chosen = std::size_t(std::count_if(vertices.begin(), vertices.end(), cavitySide));
  return all > 0 ? double(chosen) / double(all) : 0;
}

}  // namespace hs::cardiac
