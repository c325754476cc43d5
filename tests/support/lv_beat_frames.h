#pragma once
// A recorded beat that moves as a left ventricle does, made from one endocardial surface (frame
// 0, end-diastole) for the [motion] tests: heartsim ships only frame 0 of the biv-me patient's
// cine MRI, so the tests make the other frames from it. Where scaledFrames (recorded_beat_frames.h)
// shrinks the surface about its centroid, this moves each point as the ventricle's wall does
// in systole, at a healthy adult's figures:
//  - the long axis shortens toward a nearly fixed apex: a point at height s above the apex
//    (s along the long axis, 0 at the apex, L at the annuli's centroid) descends by D s / L, so
//    the base descends D (12-15 mm in a healthy adult);
//  - the wall moves toward the long axis: the distance from the axis shrinks by the share
//    c(p) = c_ring + (c_body - c_ring) smoothstep(d(p) / reach), d(p) the distance to the nearest
//    annulus vertex, so the annuli narrow by c_ring (about a tenth) and the body by c_body,
//    which sets the ejection fraction (found by bisection on the frames' capped volumes);
//  - the ventricle twists: a point at height s turns about the axis by
//    theta(s) = theta_apex + (theta_base - theta_apex) s / L, the apex and the base opposite ways.
// Each of the three scales with the activation a(phase) in [0, 1] (0 at end-diastole, 1 at
// end-systole at phase `systole`, a half cosine each way: volumeRatio's fall).
//
// The apex is the vertex farthest from the annuli's centroid; the long axis runs from it to that
// centroid. Lengths in the surface's own units (mm for biv-me).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "cardiac/patient/patient_wall.h"
#include "mesh/surface_mesh.h"
#include "recorded_beat_frames.h"

namespace hs::testing {

struct LvBeat {
  int count = 25;
  double systole = 0.36;           // end-systole's share of the beat
  double ejection = 0.60;          // the frames' EF, of their surfaces closed flat over the annuli
  double baseDescent = 13;         // D, the surface's units
  double annulusNarrowing = 0.10;  // c_ring
  double narrowingReach = 20;      // the surface's units: from c_ring at an annulus to c_body
  double apexTwistDeg = 6;         // counter-clockwise seen from the apex
  double baseTwistDeg = -3;
};

// The long axis of a ventricle: the apex and the unit direction from it to the annuli.
struct LongAxis {
  pbd::Vec3d apex = pbd::Vec3d::Zero(), toBase = pbd::Vec3d::UnitY();
  double length = 0;
};

inline LongAxis findLongAxis(const cardiac::Surface& s) {
  pbd::Vec3d centre = pbd::Vec3d::Zero();
  std::size_t n = 0;
  for (const auto& loop : pbd::boundaryLoopVertices(s.triangles))
    for (pbd::Index v : loop) {
      centre += s.vertices[v].cast<double>();
      ++n;
    }
  if (n == 0) throw std::invalid_argument("findLongAxis: a surface without annuli");
  centre /= double(n);
  LongAxis axis;
  double farthest = -1;
  for (const pbd::Vec3& v : s.vertices)
    if ((v.cast<double>() - centre).norm() > farthest) {
      farthest = (v.cast<double>() - centre).norm();
      axis.apex = v.cast<double>();
    }
  axis.length = farthest;
  axis.toBase = (centre - axis.apex) / farthest;
  return axis;
}

// Per vertex: the distance to the nearest vertex of a boundary loop (an annulus).
inline std::vector<double> distanceToAnnuli(const cardiac::Surface& s) {
  std::vector<pbd::Vec3d> ring;
  for (const auto& loop : pbd::boundaryLoopVertices(s.triangles))
    for (pbd::Index v : loop) ring.push_back(s.vertices[v].cast<double>());
  std::vector<double> d;
  for (const pbd::Vec3& v : s.vertices) {
    double best = INFINITY;
    for (const pbd::Vec3d& r : ring) best = std::min(best, (v.cast<double>() - r).norm());
    d.push_back(best);
  }
  return d;
}

// The surface at activation a with the body's radial share cBody (see the header).
inline cardiac::Surface lvBeatShape(const cardiac::Surface& s, const LongAxis& axis, const std::vector<double>& toRing,
                                    const LvBeat& beat, double a, double cBody) {
  const double degree = std::numbers::pi / 180;
  cardiac::Surface out = s;
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const pbd::Vec3d q = s.vertices[i].cast<double>() - axis.apex;
    const double height = q.dot(axis.toBase);
    pbd::Vec3d radial = q - height * axis.toBase;
    const double x = std::clamp(toRing[i] / beat.narrowingReach, 0.0, 1.0);
    const double c = beat.annulusNarrowing + (cBody - beat.annulusNarrowing) * x * x * (3 - 2 * x);
    radial *= 1 - c * a;
    const double share = height / axis.length;
    const double theta = a * degree * (beat.apexTwistDeg + (beat.baseTwistDeg - beat.apexTwistDeg) * share);
    // Rodrigues' rotation of a vector across the axis: r cos(theta) + (k x r) sin(theta).
    radial = radial * std::cos(theta) + axis.toBase.cross(radial) * std::sin(theta);
    const double lowered = height - beat.baseDescent * a * share;
    out.vertices[i] = (axis.apex + lowered * axis.toBase + radial).cast<pbd::Real>();
  }
  return out;
}

// The frames of one beat: frame f at phase f / count, activation 1 - volumeRatio's share
// left. c_body is bisected so that end-systole (activation 1) ejects `beat.ejection`.
inline std::vector<cardiac::Surface> lvBeatFrames(const cardiac::Surface& endocardium, const LvBeat& beat = {}) {
  const LongAxis axis = findLongAxis(endocardium);
  const std::vector<double> toRing = distanceToAnnuli(endocardium);
  const double edv = std::abs(pbd::cappedSignedVolume(endocardium.vertices, endocardium.triangles));
  const auto ejects = [&](double cBody) {
    const cardiac::Surface es = lvBeatShape(endocardium, axis, toRing, beat, 1, cBody);
    return 1 - std::abs(pbd::cappedSignedVolume(es.vertices, es.triangles)) / edv;
  };
  double low = 0, high = 0.6;
  for (int k = 0; k < 50; ++k) (ejects(0.5 * (low + high)) < beat.ejection ? low : high) = 0.5 * (low + high);
  const double cBody = 0.5 * (low + high);
  std::vector<cardiac::Surface> frames;
  for (int f = 0; f < beat.count; ++f) {
    const double activation = 1 - volumeRatio(double(f) / beat.count, 1, beat.systole);
    frames.push_back(lvBeatShape(endocardium, axis, toRing, beat, activation, cBody));
  }
  return frames;
}

// One frame of `frames` with a patch of the wall folded through the cavity: the vertices within
// `radius` of the vertex farthest from the long axis at mid-height (of `frames[0]`) are pushed
// across the axis, each by its share w = 1 - (d / radius)^2 of 1.4 times its distance from the
// axis, so the patch's centre passes 40% beyond the axis toward the opposite wall and the band
// around it turns over. No wall can follow such a frame.
inline std::vector<cardiac::Surface> foldedFrames(std::vector<cardiac::Surface> frames, int frame, double radius) {
  const LongAxis axis = findLongAxis(frames[0]);
  const auto radialOf = [&](const pbd::Vec3d& p) {
    const pbd::Vec3d q = p - axis.apex;
    return pbd::Vec3d(q - q.dot(axis.toBase) * axis.toBase);
  };
  std::size_t centre = 0;
  double widest = -1;
  for (std::size_t i = 0; i < frames[0].vertices.size(); ++i) {
    const pbd::Vec3d p = frames[0].vertices[i].cast<double>();
    const double share = (p - axis.apex).dot(axis.toBase) / axis.length;
    if (std::abs(share - 0.5) < 0.1 && radialOf(p).norm() > widest) {
      widest = radialOf(p).norm();
      centre = i;
    }
  }
  cardiac::Surface& s = frames.at(std::size_t(frame));
  const pbd::Vec3d middle = s.vertices[centre].cast<double>();
  for (pbd::Vec3& v : s.vertices) {
    const double d = (v.cast<double>() - middle).norm() / radius;
    if (d >= 1) continue;
    v = (v.cast<double>() - 1.4 * (1 - d * d) * radialOf(v.cast<double>())).cast<pbd::Real>();
  }
  return frames;
}

}  // namespace hs::testing
