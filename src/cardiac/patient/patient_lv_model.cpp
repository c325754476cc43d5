#include "cardiac/patient/patient_lv_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hs::cardiac {
namespace {

Index pairId(Index wallVertex, std::size_t endoVertices) {
  const auto n = Index(endoVertices);
  return wallVertex < n ? 2 * wallVertex : 2 * (wallVertex - n) + 1;
}

// A ring's endocardial ids as model ids, ordered so the fan (centroid, r_k, r_k+1) faces +y
// (the base side): the cavity closed with outward normals (lv_model.h).
std::vector<Index> fanRing(const std::vector<Index>& ring, const std::vector<Vec3>& x) {
  std::vector<Index> ids;
  Vec3d centroid = Vec3d::Zero();
  for (Index i : ring) {
    ids.push_back(2 * i);
    centroid += x[i].cast<double>();
  }
  centroid /= double(ring.size());
  Vec3d normal = Vec3d::Zero();
  for (std::size_t k = 0; k < ring.size(); ++k)
    normal += (x[ring[k]].cast<double>() - centroid).cross(x[ring[(k + 1) % ring.size()]].cast<double>() - centroid);
  if (normal.y() < 0) std::reverse(ids.begin(), ids.end());
  return ids;
}

// The lumen disc of a ring: its centroid, the radius of a disc of its flat cap's area
// (1/2 |sum (p_k - c) x (p_k+1 - c)|).
Orifice orificeOf(const LvModel& model, const std::vector<Index>& ring, const Vec3& forward) {
  Vec3d centroid = Vec3d::Zero();
  for (Index v : ring) centroid += model.mesh.vertices[v].cast<double>();
  centroid /= double(ring.size());
  Vec3d twiceArea = Vec3d::Zero();
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Vec3d a = model.mesh.vertices[ring[k]].cast<double>() - centroid;
    const Vec3d b = model.mesh.vertices[ring[(k + 1) % ring.size()]].cast<double>() - centroid;
    twiceArea += a.cross(b);
  }
  Orifice o;
  o.centre = centroid.cast<Real>();
  o.forward = forward;
  o.radius = Real(std::sqrt(0.5 * twiceArea.norm() / std::numbers::pi));
  return o;
}

// The geometry's figures the rest of the simulation reads from LvGeometryParams (orifice
// radii for the lumped valves, sizes for the blood's scale checks), measured on the wall; the
// flow path without vessels: both far ends at their orifices.
void describeGeometry(LvModel& model, const PatientWall& wall) {
  FlowPath& f = model.flowPath;
  f.mitral = orificeOf(model, model.mitralRing, -Vec3::UnitY());
  f.aortic = orificeOf(model, model.aorticRing, Vec3::UnitY());
  f.inflowTop = f.mitral.centre.y();
  f.outflowTop = f.aortic.centre.y();
  f.inflowLength = 0;
  f.apexAxisOrigin = Vec3::Zero();
  double radius = 0, thickness = 0;
  const std::size_t n = wall.endoVertices;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d endo = wall.mesh.vertices[i].cast<double>();
    radius = std::max(radius, std::hypot(endo.x(), endo.z()));
    thickness += (wall.mesh.vertices[n + i] - wall.mesh.vertices[i]).cast<double>().norm();
  }
  thickness /= double(n);
  f.midWallRadius = Real(radius + 0.5 * thickness);
  f.midWallLongAxis = Real(wall.cavityLength + 0.5 * thickness);
  f.plateMid = 0;
  LvGeometryParams& g = model.params;
  g.endoRadius = Real(radius);
  g.endoLongAxis = Real(wall.cavityLength);
  g.wallThickness = Real(thickness);
  g.mitralRadius = f.mitral.radius;
  g.aorticRadius = f.aortic.radius;
  g.inflowVesselLength = g.outflowVesselLength = 0;
}

}  // namespace

LvModel lvModelFromPatientWall(const PatientWall& wall) {
  const std::size_t n = wall.endoVertices;
  if (wall.mesh.vertices.size() != 2 * n)
    throw std::invalid_argument("lvModelFromPatientWall: expected a wall of one layer (" + std::to_string(2 * n) +
                                " vertices), got " + std::to_string(wall.mesh.vertices.size()));
  LvModel model;
  model.mesh.vertices.resize(2 * n);
  model.region.assign(2 * n, Region::Myocardium);
  model.segment.assign(2 * n, 0);
  for (Index v = 0; v < Index(2 * n); ++v) {
    const Index id = pairId(v, n);
    model.mesh.vertices[id] = wall.mesh.vertices[v];
    model.segment[id] = wall.segment[v];
    if (wall.basePlate[v % n]) model.region[id] = Region::BasePlate;
  }
  model.mesh.tets.reserve(wall.mesh.tets.size());
  for (const pbd::Tet& t : wall.mesh.tets)
    model.mesh.tets.push_back({pairId(t[0], n), pairId(t[1], n), pairId(t[2], n), pairId(t[3], n)});
  model.surface = pbd::boundaryFaces(model.mesh.tets);
  for (const pbd::Triangle& t : wall.endocardium) model.cavitySurface.push_back({2 * t[0], 2 * t[1], 2 * t[2]});
  model.mitralRing = fanRing(wall.mitralRing, wall.mesh.vertices);
  model.aorticRing = fanRing(wall.aorticRing, wall.mesh.vertices);
  Vec3d centre = Vec3d::Zero();
  std::size_t myocardium = 0;
  Real lowest = 0;
  for (std::size_t v = 0; v < 2 * n; ++v) {
    lowest = std::min(lowest, model.mesh.vertices[v].y());
    if (model.region[v] != Region::Myocardium) continue;
    centre += model.mesh.vertices[v].cast<double>();
    ++myocardium;
  }
  model.centre = (centre / double(std::max<std::size_t>(myocardium, 1))).cast<Real>();
  model.longAxisLength = -lowest;  // the base plane is y = 0
  describeGeometry(model, wall);
  return model;
}

const std::string& patientModelFile(const PatientModelSettings& patient) {
  return patient.volumeMesh.empty() ? patient.endocardium : patient.volumeMesh;
}

LvModel buildPatientLvModel(const PatientModelSettings& patient, Real wallThickness) {
  return lvModelFromPatientWall(buildPatientShell(patient, wallThickness));
}

PatientWall buildPatientShell(const PatientModelSettings& patient, Real wallThickness) {
  PatientWallSettings s;
  s.file = patientModelFile(patient);
  s.units = patient.units;
  s.wallThickness = double(wallThickness);
  s.resolution = wallResolution(patient.resolution);
  s.resolution.layers = 1;  // the simulation's shell is one tet thick (lv_model.h)
  s.mitralLoop = patient.mitralLoop;
  s.aorticLoop = patient.aorticLoop;
  if (patient.septum != Vec3::Zero()) s.septum = patient.septum.cast<double>();
  s.mitralLoopName = "model.mitral_loop", s.aorticLoopName = "model.aortic_loop";
  s.septumName = "model.septum, the septum direction,";
  const Surface* epicardium = patient.epicardiumSurface ? &*patient.epicardiumSurface : nullptr;
  return buildPatientWall(patient.endocardiumSurface, epicardium, s);
}

}  // namespace hs::cardiac
