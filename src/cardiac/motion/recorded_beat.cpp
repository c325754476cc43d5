#include "cardiac/motion/recorded_beat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesh/surface_mesh.h"
#include "mesh/wall_extrusion.h"
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

// Sweeps of smoothing of the endocardium's normals: the wall's extrusion's (wall_extrusion.h),
// so that d_i(0) are the directions the epicardium was placed along.
const int kDirectionSweeps = pbd::ExtrusionSettings{}.normalSmoothing;

// The smallest rotation taking unit d0 to unit d, applied to s (Rodrigues' formula with
// v = d0 x d, c = d0 . d: R s = c s + v x s + v (v . s) / (1 + c)); s unchanged where d turned
// fully round (c = -1), which findFold then reports.
Vec3d turned(const Vec3d& s, const Vec3d& d0, const Vec3d& d) {
  const double c = d0.dot(d);
  if (!(1 + c > 1e-12)) return s;
  const Vec3d v = d0.cross(d);
  return c * s + v.cross(s) + v * (v.dot(s) / (1 + c));
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
  // The epicardial patches at rest: the endocardium's directions and areas (its cavity
  // triangles face into the wall), the epicardium's areas (the outer faces, all of odd vertices).
  const std::size_t n = model.mesh.vertices.size();
  m_neighbours = pbd::vertexNeighbours(n, model.cavitySurface);
  m_direction.resize(n);
  m_area.resize(n);
  findDirections(model.mesh.vertices, 0);
  m_restDirection = m_direction;
  const std::vector<double> endoArea = m_area;
  std::vector<Vec3d> unusedNormal(n);
  std::vector<double> epiArea(n);
  std::vector<pbd::Triangle> outer;
  for (const pbd::Triangle& t : model.surface)
    if (t[0] % 2 == 1 && t[1] % 2 == 1 && t[2] % 2 == 1) outer.push_back(t);
  accumulateNormalsAndAreas(outer, model.mesh.vertices, 0, unusedNormal, epiArea);
  for (Index vertex : m_endocardial) {
    const Vec3d d0 = m_restDirection[vertex];
    const Vec3d offset = (model.mesh.vertices[vertex + 1] - model.mesh.vertices[vertex]).cast<double>();
    EpicardialPatch patch{};
    patch.vertex = vertex + 1;
    patch.restThickness = std::max(offset.dot(d0), 0.0);
    patch.across = offset - patch.restThickness * d0;
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
}

double RecordedBeat::thicknessAt(const EpicardialPatch& patch, double area) const {
  const double stretch = area / patch.restArea;  // a / a0
  if (patch.restRadius == 0) return patch.restThickness / stretch;
  const double r0 = patch.restRadius, h0 = patch.restThickness;
  const double r = r0 * std::sqrt(stretch);
  return std::cbrt(std::pow(r0 + h0, 3) - std::pow(r0, 3) + std::pow(r, 3)) - r;
}

void RecordedBeat::findDirections(const std::vector<Vec3>& x, Index first) const {
  accumulateNormalsAndAreas(m_model->cavitySurface, x, first, m_direction, m_area);
  for (Vec3d& d : m_direction)
    if (d.norm() > 0) d.normalize();
  m_direction = pbd::smoothNormals(std::move(m_direction), m_neighbours, kDirectionSweeps);
}

void RecordedBeat::placeEpicardium(std::vector<Vec3>& x, Index first) const {
  findDirections(x, first);
  for (const EpicardialPatch& patch : m_epicardium) {
    const Index vertex = patch.vertex - 1;
    const Vec3d d = m_direction[vertex];
    const double area = m_area[vertex];
    const Vec3d across = std::sqrt(area / patch.restArea) * turned(patch.across, m_restDirection[vertex], d);
    const Vec3d epicardium = x[first + vertex].cast<double>() + thicknessAt(patch, area) * d + across;
    x[first + patch.vertex] = epicardium.cast<Real>();
  }
}

void RecordedBeat::carryVessels(std::vector<Vec3>& x, Index first) const {
  const std::vector<Vec3>& rest = m_model->mesh.vertices;
  const auto at = [&](Index v) -> Vec3& { return x[first + v]; };
  for (const VesselFollower& f : m_vessels) at(f.vertex) = rest[f.vertex] + f.share * (at(f.root) - rest[f.root]);
}

void RecordedBeat::drive(double time, std::vector<Vec3>& predicted) const { driveAt(time, predicted, m_firstParticle); }

void RecordedBeat::driveAt(double time, std::vector<Vec3>& x, Index first) const {
  const SplineWeights s = periodicCatmullRom(time, m_period, frameCount());
  for (std::size_t k = 0; k < m_endocardial.size(); ++k) {
    Vec3d p = m_rest[k].cast<double>();
    for (int j = 0; j < 4; ++j) p += s.weight[j] * m_offset[s.knot[j]][k].cast<double>();
    x[first + m_endocardial[k]] = p.cast<Real>();
  }
  placeEpicardium(x, first);
  carryVessels(x, first);
}

RecordedFold RecordedBeat::findFold(double dt) const {
  const pbd::TetMesh& mesh = m_model->mesh;
  std::vector<std::uint8_t> driven(mesh.vertices.size(), 0);
  for (Index v : m_driven) driven[v] = 1;
  const auto allDriven = [&](const auto& corners) {
    return std::all_of(corners.begin(), corners.end(), [&](Index v) { return driven[v] != 0; });
  };
  const auto volume = [](const std::vector<Vec3>& x, const pbd::Tet& t) {
    return pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
  };
  const auto normal = [](const std::vector<Vec3>& x, const pbd::Triangle& t) {
    return Vec3d((x[t[1]] - x[t[0]]).cast<double>().cross((x[t[2]] - x[t[0]]).cast<double>()));
  };
  std::vector<Index> tets, triangles;
  std::vector<Real> restVolume;
  std::vector<Vec3d> restNormal;
  for (Index t = 0; t < Index(mesh.tets.size()); ++t)
    if (allDriven(mesh.tets[t])) {
      tets.push_back(t);
      restVolume.push_back(volume(mesh.vertices, mesh.tets[t]));
    }
  for (Index t = 0; t < Index(m_model->cavitySurface.size()); ++t)
    if (allDriven(m_model->cavitySurface[t])) {
      triangles.push_back(t);
      restNormal.push_back(normal(mesh.vertices, m_model->cavitySurface[t]));
    }
  RecordedFold fold;
  std::vector<std::uint8_t> tetFolded(mesh.tets.size(), 0), triangleTurned(m_model->cavitySurface.size(), 0);
  const auto mark = [&](std::vector<std::uint8_t>& seen, Index id, int& count, Index vertex) {
    if (seen[id]) return;
    seen[id] = 1;
    ++count;
    fold.segments.push_back(m_model->segment[vertex]);
  };
  std::vector<Vec3> x = mesh.vertices;
  const long steps = std::lround(std::ceil(m_period / dt));
  for (long k = 0; k < steps; ++k) {
    const double time = double(k + 1) * dt;  // RecordedBeatMotion's time at the end of step k
    driveAt(time, x, 0);
    bool any = false;
    for (std::size_t j = 0; j < tets.size(); ++j) {
      const pbd::Tet& tet = mesh.tets[tets[j]];
      const Real v = volume(x, tet);  // as HeartSimulation::tissueStats counts an inverted tet
      fold.smallestShare = std::min(fold.smallestShare, double(v) / double(restVolume[j]));
      if (v > Real(0)) continue;
      any = true;
      mark(tetFolded, tets[j], fold.tets, tet[0]);
    }
    for (std::size_t j = 0; j < triangles.size(); ++j) {
      const pbd::Triangle& t = m_model->cavitySurface[triangles[j]];
      if (normal(x, t).dot(restNormal[j]) > 0) continue;
      any = true;
      mark(triangleTurned, triangles[j], fold.triangles, t[0]);
    }
    if (!any) continue;
    const int frame = int(std::lround(std::fmod(time / m_period, 1.0) * frameCount())) % frameCount();
    if (fold.firstTime < 0) {
      fold.firstTime = time;
      fold.firstFrame = fold.lastFrame = frame;
    }
    fold.firstFrame = std::min(fold.firstFrame, frame);
    fold.lastFrame = std::max(fold.lastFrame, frame);
  }
  std::sort(fold.segments.begin(), fold.segments.end());
  fold.segments.erase(std::unique(fold.segments.begin(), fold.segments.end()), fold.segments.end());
  return fold;
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
