// The flat base of a truncated ventricle, made with its two orifices (cardiac/patient/patient_wall.h,
// step 3): the idealized benchmark ventricles and many research meshes end in a plane at the
// base, with no valve openings.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/patient/patient_wall_internal.h"
#include "mesh/planar_cap.h"

namespace hs::cardiac::detail {

LoopShape loopShape(const std::vector<Vec3>& vertices, const std::vector<Index>& loop) {
  LoopShape s;
  for (Index i : loop) s.centroid += vertices[i].cast<double>();
  s.centroid /= double(loop.size());
  for (std::size_t k = 0; k < loop.size(); ++k)
    s.vectorArea += 0.5 * (vertices[loop[k]].cast<double>() - s.centroid)
                              .cross(vertices[loop[(k + 1) % loop.size()]].cast<double>() - s.centroid);
  return s;
}

OrificeLayout proceduralOrificeLayout() {
  // lv_model.cpp places the orifices on the x axis of a base of radius a with equal gaps
  // between the rim, the mitral, the aortic and the rim again: gap = (2a - 2 r_m - 2 r_a) / 3.
  const LvGeometryParams p;
  const double a = p.endoRadius, rm = p.mitralRadius / a, ra = p.aorticRadius / a;
  const double gap = (2.0 - 2 * rm - 2 * ra) / 3.0;
  return {-1.0 + gap + rm, rm, 1.0 - gap - ra, ra};
}

OpenedBase openFlatBase(const Surface& cup, const std::vector<Index>& rim, double spacing,
                        const std::string& file) {
  const LoopShape shape = loopShape(cup.vertices, rim);
  Vec3d n = shape.vectorArea.normalized();
  if (n.y() < 0) n = -n;  // out of the cavity: up, toward the base
  double radius = 0, outOfPlane = 0;
  for (Index i : rim) {
    const Vec3d d = cup.vertices[i].cast<double>() - shape.centroid;
    radius += d.norm() / double(rim.size());
    outOfPlane = std::max(outOfPlane, std::abs(d.dot(n)));
  }
  if (outOfPlane > 0.1 * radius)
    throw std::invalid_argument(file + ": the one boundary loop (" + std::to_string(rim.size()) +
                                " vertices) is not flat (" + std::to_string(outOfPlane * 1e3) +
                                " mm out of its plane); expected a flat truncated base or two annuli");
  // In-plane axes u (the heart's x, projected) and v = n x u, so u x v = n: counter-clockwise
  // triangles in (u, v) face out of the cavity, as the cup's do.
  const Vec3d u = (Vec3d::UnitX() - n * n.x()).normalized(), v = n.cross(u);
  std::vector<Eigen::Vector2d> rim2d;
  std::vector<Index> rimIds = rim;
  for (Index i : rim) {
    const Vec3d d = cup.vertices[i].cast<double>() - shape.centroid;
    rim2d.emplace_back(d.dot(u), d.dot(v));
  }
  double signedArea = 0;
  for (std::size_t k = 0; k < rim2d.size(); ++k) {
    const auto& a = rim2d[k];
    const auto& b = rim2d[(k + 1) % rim2d.size()];
    signedArea += a.x() * b.y() - a.y() * b.x();
  }
  if (signedArea < 0) {
    std::reverse(rim2d.begin(), rim2d.end());
    std::reverse(rimIds.begin(), rimIds.end());
  }
  const OrificeLayout layout = proceduralOrificeLayout();
  const auto planar = [&](double x) {  // a point x * radius along the heart's x, in (u, v)
    const Vec3d d = Vec3d::UnitX() * (x * radius);
    return Eigen::Vector2d(d.dot(u), d.dot(v));
  };
  const std::vector<pbd::CircularHole> holes = {{planar(layout.mitralCentreX), layout.mitralRadius * radius},
                                                {planar(layout.aorticCentreX), layout.aorticRadius * radius}};
  OpenedBase out;
  out.surface = cup;
  const auto first = static_cast<Index>(cup.vertices.size());
  pbd::PlanarCap cap;
  try {
    cap = pbd::capWithHoles(rim2d, rimIds, first, holes, spacing);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(file + ": cannot open the orifices in the flat base (" + e.what() + ")");
  }
  for (const Eigen::Vector2d& p : cap.newPoints)
    out.surface.vertices.push_back((shape.centroid + u * p.x() + v * p.y()).cast<pbd::Real>());
  out.surface.triangles.insert(out.surface.triangles.end(), cap.triangles.begin(), cap.triangles.end());
  out.basePlate.assign(out.surface.vertices.size(), false);
  for (std::size_t i = first; i < out.basePlate.size(); ++i) out.basePlate[i] = true;
  out.mitralRing = cap.holeRings[0];
  out.aorticRing = cap.holeRings[1];
  const pbd::SurfaceCheck check = pbd::checkSurface(out.surface.triangles);
  if (pbd::boundaryLoopVertices(out.surface.triangles).size() != 2 || check.nonManifoldEdges != 0)
    throw std::invalid_argument(file + ": the flat base made over the rim does not join it (" +
                                std::to_string(check.boundaryEdges) + " open edges); expected a convex rim");
  return out;
}

}  // namespace hs::cardiac::detail
