#include "cardiac/motion/recorded_beat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesh/surface_mesh.h"
#include "pbd/core/closest_point.h"

namespace hs::cardiac {
namespace {

// Where a wall vertex sits on the recorded surface: a triangle's corners and their weights.
struct SurfacePoint {
  pbd::Triangle corners{};
  std::array<double, 3> weight{};
};

// Barycentric weights of q in triangle abc (q in its plane; Ericson 2005, 3.4).
std::array<double, 3> barycentric(const Vec3d& q, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d e0 = b - a, e1 = c - a, r = q - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = r.dot(e0), d21 = r.dot(e1);
  const double denominator = d00 * d11 - d01 * d01;
  const double v = (d11 * d20 - d01 * d21) / denominator;
  const double w = (d00 * d21 - d01 * d20) / denominator;
  return {1 - v - w, v, w};
}

// The point of `surface` (heart frame) closest to p, by brute force over its triangles (a few
// thousand, once at start-up); degenerate triangles hold no point of their own.
SurfacePoint closestSurfacePoint(const Vec3d& p, const std::vector<Vec3d>& x, const std::vector<pbd::Triangle>& triangles) {
  SurfacePoint best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const pbd::Triangle& t : triangles) {
    const Vec3d &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    if (!((b - a).cross(c - a).squaredNorm() > 0)) continue;
    const Vec3d q = pbd::closestPointOnTriangleOf(p, a, b, c);
    const double d = (q - p).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best.corners = t;
      best.weight = barycentric(q, a, b, c);
    }
  }
  return best;
}

// Per vertex of `triangles`: the sum of the triangles' cross products (twice the
// area-weighted normal) and a third of their areas, at positions x[firstParticle + vertex].
void accumulateNormalsAndAreas(const std::vector<pbd::Triangle>& triangles, const std::vector<Vec3>& x,
                               Index firstParticle, std::vector<Vec3d>& normal, std::vector<double>& area) {
  std::fill(normal.begin(), normal.end(), Vec3d::Zero());
  std::fill(area.begin(), area.end(), 0.0);
  for (const pbd::Triangle& t : triangles) {
    const Vec3d a = x[firstParticle + t[0]].cast<double>();
    const Vec3d cross = (x[firstParticle + t[1]].cast<double>() - a).cross(x[firstParticle + t[2]].cast<double>() - a);
    const double third = cross.norm() / 6;
    for (Index v : t) {
      normal[v] += cross;
      area[v] += third;
    }
  }
}

// Edges from an annulus within which the epicardium is left to the wall's constraints (see the
// header): two rings of cavity vertices around each annulus.
constexpr int kAnnulusReach = 2;

// Per model vertex: an endocardial vertex within `reach` edges of the cavity surface from a
// vertex of the mitral or aortic ring.
std::vector<std::uint8_t> nearAnnuli(const LvModel& model, int reach) {
  const std::vector<std::vector<Index>> neighbours = pbd::vertexNeighbours(model.mesh.vertices.size(), model.cavitySurface);
  std::vector<std::uint8_t> near(model.mesh.vertices.size(), 0);
  std::vector<Index> front(model.mitralRing);
  front.insert(front.end(), model.aorticRing.begin(), model.aorticRing.end());
  for (Index v : front) near[v] = 1;
  for (int step = 0; step < reach; ++step) {
    std::vector<Index> next;
    for (Index v : front)
      for (Index w : neighbours[v])
        if (!near[w]) {
          near[w] = 1;
          next.push_back(w);
        }
    front = std::move(next);
  }
  return near;
}

void checkFrames(const std::vector<Surface>& frames, double period) {
  if (frames.size() < 2)
    throw std::invalid_argument("motion.count: a recorded beat needs at least 2 frames, got " +
                                std::to_string(frames.size()));
  if (!(period > 0) || !std::isfinite(period))
    throw std::invalid_argument("motion.period: expected a positive beat length in s, got " + std::to_string(period));
  for (std::size_t f = 1; f < frames.size(); ++f)
    if (frames[f].vertices.size() != frames[0].vertices.size() || frames[f].triangles != frames[0].triangles)
      throw std::invalid_argument("motion.frames: frame " + std::to_string(f) +
                                  " has other vertices or triangles than frame 0; expected the same mesh moved");
}

}  // namespace

SplineWeights periodicCatmullRom(double time, double period, int count) {
  double phase = std::fmod(time / period, 1.0);
  if (phase < 0) phase += 1;
  const double position = phase * count;
  const int i = std::min(int(position), count - 1);
  const double u = position - i, u2 = u * u, u3 = u2 * u;
  SplineWeights s;
  for (int k = 0; k < 4; ++k) s.knot[k] = ((i + k - 1) % count + count) % count;
  // The uniform Catmull-Rom basis: p(u) = sum_k weight_k p_(i-1+k).
  s.weight[0] = 0.5 * (-u3 + 2 * u2 - u);
  s.weight[1] = 0.5 * (3 * u3 - 5 * u2 + 2);
  s.weight[2] = 0.5 * (-3 * u3 + 4 * u2 + u);
  s.weight[3] = 0.5 * (u3 - u2);
  return s;
}

RecordedBeat::RecordedBeat(const LvModel& model, const PatientWall& wall, const std::vector<Surface>& frames,
                           double period, Index firstParticle)
    : m_model(&model), m_period(period), m_firstParticle(firstParticle) {
  checkFrames(frames, period);
  std::vector<std::vector<Vec3d>> placed(frames.size());
  const double cube = std::pow(wall.frame.metresPerUnit, 3);  // file volume units -> m^3
  for (std::size_t f = 0; f < frames.size(); ++f) {
    for (const Vec3& v : frames[f].vertices) placed[f].push_back(wall.frame.toHeart(v.cast<double>()));
    m_frameVolume.push_back(std::abs(pbd::cappedSignedVolume(frames[f].vertices, frames[f].triangles)) * cube);
  }
  m_offset.resize(frames.size());
  for (Index i = 0; i < Index(wall.endoVertices); ++i) {
    if (wall.basePlate[i]) continue;
    const Index vertex = 2 * i;  // lvModelFromPatientWall's pairing
    const Vec3& rest = model.mesh.vertices[vertex];
    const SurfacePoint tie = closestSurfacePoint(rest.cast<double>(), placed[0], frames[0].triangles);
    m_endocardial.push_back(vertex);
    m_rest.push_back(rest);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      Vec3d offset = Vec3d::Zero();
      for (int c = 0; c < 3; ++c) offset += tie.weight[c] * (placed[f][tie.corners[c]] - placed[0][tie.corners[c]]);
      m_offset[f].push_back(offset.cast<Real>());
    }
  }
  // The epicardial patches at rest: the endocardium's normals and areas (its cavity triangles
  // face into the wall), the epicardium's areas (the outer faces, all of odd vertices).
  const std::size_t n = model.mesh.vertices.size();
  std::vector<Vec3d> normal(n), unusedNormal(n);
  std::vector<double> endoArea(n), epiArea(n);
  accumulateNormalsAndAreas(model.cavitySurface, model.mesh.vertices, 0, normal, endoArea);
  std::vector<pbd::Triangle> outer;
  for (const pbd::Triangle& t : model.surface)
    if (t[0] % 2 == 1 && t[1] % 2 == 1 && t[2] % 2 == 1) outer.push_back(t);
  accumulateNormalsAndAreas(outer, model.mesh.vertices, 0, unusedNormal, epiArea);
  const std::vector<std::uint8_t> nearAnnulus = nearAnnuli(model, kAnnulusReach);
  for (Index vertex : m_endocardial) {
    if (nearAnnulus[vertex]) continue;
    const Vec3d normalAtRest = normal[vertex].normalized();
    const Vec3d offset = (model.mesh.vertices[vertex + 1] - model.mesh.vertices[vertex]).cast<double>();
    EpicardialPatch patch{};
    patch.vertex = vertex + 1;
    patch.restThickness = std::max(offset.dot(normalAtRest), 0.0);
    patch.across = offset - patch.restThickness * normalAtRest;
    patch.restArea = endoArea[vertex];
    const double widening = std::sqrt(epiArea[vertex + 1] / endoArea[vertex]);  // 1 + h0 / r0
    patch.restRadius = widening > 1 + 1e-6 ? patch.restThickness / (widening - 1) : 0.0;
    m_epicardium.push_back(patch);
  }
  std::vector<std::uint8_t> driven(n, 0);
  for (Index vertex : m_endocardial) driven[vertex] = 1;
  for (const VesselFollower& f : model.vesselFollowers)
    if (driven[f.root]) m_vessels.push_back(f);
  m_driven = m_endocardial;
  for (const EpicardialPatch& patch : m_epicardium) m_driven.push_back(patch.vertex);
  for (const VesselFollower& f : m_vessels) m_driven.push_back(f.vertex);
  m_normal.resize(n);
  m_area.resize(n);
}

double RecordedBeat::thicknessAt(const EpicardialPatch& patch, double area) const {
  const double stretch = area / patch.restArea;  // a / a0
  if (patch.restRadius == 0) return patch.restThickness / stretch;
  const double r0 = patch.restRadius, h0 = patch.restThickness;
  const double r = r0 * std::sqrt(stretch);
  return std::cbrt(std::pow(r0 + h0, 3) - std::pow(r0, 3) + std::pow(r, 3)) - r;
}

void RecordedBeat::placeEpicardium(std::vector<Vec3>& predicted) const {
  accumulateNormalsAndAreas(m_model->cavitySurface, predicted, m_firstParticle, m_normal, m_area);
  for (const EpicardialPatch& patch : m_epicardium) {
    const Index vertex = patch.vertex - 1;
    const Vec3d x = predicted[m_firstParticle + vertex].cast<double>();
    const Vec3d epicardium = x + thicknessAt(patch, m_area[vertex]) * m_normal[vertex].normalized() + patch.across;
    predicted[m_firstParticle + patch.vertex] = epicardium.cast<Real>();
  }
}

void RecordedBeat::carryVessels(std::vector<Vec3>& predicted) const {
  const std::vector<Vec3>& rest = m_model->mesh.vertices;
  const auto at = [&](Index v) -> Vec3& { return predicted[m_firstParticle + v]; };
  for (const VesselFollower& f : m_vessels) at(f.vertex) = rest[f.vertex] + f.share * (at(f.root) - rest[f.root]);
}

void RecordedBeat::drive(double time, std::vector<Vec3>& predicted) const {
  const SplineWeights s = periodicCatmullRom(time, m_period, frameCount());
  for (std::size_t k = 0; k < m_endocardial.size(); ++k) {
    Vec3d x = m_rest[k].cast<double>();
    for (int j = 0; j < 4; ++j) x += s.weight[j] * m_offset[s.knot[j]][k].cast<double>();
    predicted[m_firstParticle + m_endocardial[k]] = x.cast<Real>();
  }
  placeEpicardium(predicted);
  carryVessels(predicted);
}

double RecordedBeat::recordedVolume(double time) const {
  const SplineWeights s = periodicCatmullRom(time, m_period, frameCount());
  double volume = 0;
  for (int j = 0; j < 4; ++j) volume += s.weight[j] * m_frameVolume[s.knot[j]];
  return volume;
}

void RecordedBeat::observe(double time, double cavityVolume) {
  const double recorded = recordedVolume(time);
  m_volumeErrorMax = std::max(m_volumeErrorMax, std::abs(cavityVolume - recorded) / recorded);
}

double RecordedBeat::systolicFraction() const {
  std::size_t smallest = 0;
  for (std::size_t f = 1; f < m_frameVolume.size(); ++f)
    if (m_frameVolume[f] < m_frameVolume[smallest]) smallest = f;
  return double(smallest) / double(m_frameVolume.size());
}

void RecordedBeat::save(pbd::StateWriter& w) const { w.put(m_volumeErrorMax); }

void RecordedBeat::load(pbd::StateReader& r) { r.get(m_volumeErrorMax); }

}  // namespace hs::cardiac
