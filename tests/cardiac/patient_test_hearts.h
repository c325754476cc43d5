#pragma once
// Synthetic patient ventricles for the patient-wall tests: a half prolate spheroid (the
// procedural heart's endocardium, cardiac/anatomy/lv_model.h) of radius a and length c in mm, built in
// the heart frame (base plane y = 0, apex at -y), then placed in a "scanner" frame by a known
// rotation and translation.
#include <Eigen/Geometry>
#include <numbers>

#include "cardiac/patient/patient_wall_internal.h"
#include "sphere_surface.h"

namespace hs::cardiac::testing {

inline constexpr double kRadiusMm = 25, kLengthMm = 50;

// The half spheroid y < 0, its triangles facing out of the cavity; one loop at y = 0.
inline Surface spheroidCup(int subdivisions = 4) {
  const auto sphere = pbd::testing::makeSphere(subdivisions, 1.0);
  std::vector<Vec3> v;
  for (const Vec3& p : sphere.vertices)
    v.emplace_back(pbd::Real(kRadiusMm * p.x()), pbd::Real(kLengthMm * p.z()), pbd::Real(kRadiusMm * p.y()));
  std::vector<Index> lower;
  for (Index f = 0; f < sphere.triangles.size(); ++f) {
    const auto& t = sphere.triangles[f];
    if (v[t[0]].y() + v[t[1]].y() + v[t[2]].y() < 0) lower.push_back(f);
  }
  // (x, y, z) -> (x, z, y) mirrors: reverse the triangles to face outward again.
  auto sub = pbd::extractSubSurface(v, sphere.triangles, lower);
  for (auto& t : sub.triangles) std::swap(t[1], t[2]);
  return {sub.vertices, sub.triangles};
}

// The cup with its base closed flat and the two orifices cut in it (mitral at -x, radius
// 0.375 a; aortic at +x, 0.275 a): a ventricle with two annuli.
inline Surface twoAnnuliVentricle() {
  const Surface cup = spheroidCup();
  const auto loops = pbd::boundaryLoopVertices(cup.triangles);
  return detail::openFlatBase(cup, loops.at(0), 2.5, "two-annuli").surface;
}

// The scanner frame: file = Q heart + t.
inline Eigen::Matrix3d scannerRotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
}
inline Eigen::Vector3d scannerOffset() { return {-40, 120, 310}; }

inline Surface inScannerFrame(const Surface& s) {
  Surface out = s;
  for (Vec3& p : out.vertices) p = (scannerRotation() * p.cast<double>() + scannerOffset()).cast<pbd::Real>();
  return out;
}

// V = (2/3) pi a^2 c, in mL.
inline double halfSpheroidMl() {
  return 2.0 / 3.0 * std::numbers::pi * kRadiusMm * kRadiusMm * kLengthMm * 1e-3;
}

}  // namespace hs::cardiac::testing
