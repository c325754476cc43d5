// Particles against a moving tetrahedral solid, see particle_tet_collision.h.
#include "pbd/contact/particle_tet_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "pbd/contact/mesh_collider.h"
#include "pbd/core/tet_geometry.h"

namespace hs::pbd {
namespace {

// Below this many particles a fork-join costs more than the loop saves.
constexpr std::ptrdiff_t kParallelThreshold = 256;
// The loops over particles hand out chunks of this many as threads free up (schedule dynamic):
// the particles at the wall, which cost the most, come in runs (cell order), and a static
// split gave one thread most of them. Each particle's result is its own, so the chunks change
// nothing but who computes what.

// Rounds of "out through the nearest boundary face" for a particle a push left inside
// another tet; two faces of a corner need one each, and a few more cover three-face corners.
constexpr int kSettleRounds = 4;

// Samples along a fast particle's path in the tunnelling test (a path of 32 half radii).
constexpr int kMaxPathSamples = 64;

std::vector<Tet> shifted(std::vector<Tet> tets, Index offset) {
  for (Tet& t : tets)
    for (Index& v : t) v += offset;
  return tets;
}

}  // namespace

TwoWayPushOut splitPushOut(const Vec3& d, Real particleInverseMass, const std::array<Real, 3>& weights,
                           const std::array<Real, 3>& wallInverseMass) {
  // C = n . (x_p - sum_i b_i x_i) - (C_0 + |d|) with n = d / |d|: grad_p C = n, grad_i C =
  // -b_i n, so the PBD step (Müller et al. 2007, eq. 9-10 with |grad C|^2 weighted by w)
  // s = |d| / (w_p + sum_i b_i^2 w_i) gives dx_p = w_p s n = w_p k d and
  // dx_i = -w_i b_i s n = -w_i b_i k d, k = 1 / (w_p + sum_i b_i^2 w_i); using d directly
  // avoids normalising it. The relative motion n . (dx_p - sum_i b_i dx_i) is |d|, as in the
  // one-way case; sum_i m_i dx_i = -(sum_{w_i>0} b_i) m_p dx_p.
  TwoWayPushOut out;
  out.particle = d;
  Real wall = 0;
  for (std::size_t k = 0; k < 3; ++k) wall += weights[k] * weights[k] * wallInverseMass[k];
  if (!(wall > Real(0)) || !(particleInverseMass > Real(0))) return out;
  const Real scale = Real(1) / (particleInverseMass + wall);
  out.particle = (particleInverseMass * scale) * d;
  for (std::size_t k = 0; k < 3; ++k) out.wall[k] = -(wallInverseMass[k] * weights[k] * scale) * d;
  out.shared = true;
  return out;
}

ParticleTetCollider::ParticleTetCollider(std::vector<Tet> tets, Index firstVertex)
    : m_tets(shifted(std::move(tets), firstVertex)),
      m_boundaryFaces(tetBoundaryFaceMasks(m_tets)),
      m_exitFaces(m_boundaryFaces),
      m_boundary(boundaryFaces(m_tets)),
      m_firstVertex(firstVertex) {
  for (const Tet& t : m_tets)
    for (Index v : t) m_vertexEnd = std::max<std::size_t>(m_vertexEnd, std::size_t(v) + 1);
}

void ParticleTetCollider::setWettedVertices(const std::vector<std::uint8_t>& wetted) {
  auto isWetted = [&](Index particle) {
    const Index v = particle - m_firstVertex;
    return v < wetted.size() && wetted[v] != 0;
  };
  for (std::size_t t = 0; t < m_tets.size(); ++t) {
    unsigned wettedMask = 0;
    for (unsigned f = 0; f < 4; ++f) {
      if (!((m_boundaryFaces[t] >> f) & 1u)) continue;
      const auto& face = kTetFaceVertices[f];
      bool all = true;
      for (int k : face) all = all && isWetted(m_tets[t][std::size_t(k)]);
      if (all) wettedMask |= 1u << f;
    }
    // No wetted face: leave toward the neighbours (through inner faces), whose passes
    // continue the way out; a tet without inner faces keeps its boundary faces.
    const unsigned inner = ~unsigned(m_boundaryFaces[t]) & 0xFu;
    m_exitFaces[t] = std::uint8_t(wettedMask != 0 ? wettedMask : (inner != 0 ? inner : m_boundaryFaces[t]));
  }
  std::vector<Triangle> kept;
  for (const Triangle& f : m_boundary)
    if (isWetted(f[0]) && isWetted(f[1]) && isWetted(f[2])) kept.push_back(f);
  if (!kept.empty()) m_boundary.swap(kept);
}

namespace {

// A boundary face's exit for p: the face's closest point q to p and p* = q + radius n, n the
// face's outward unit normal; nullopt for a degenerate face.
struct BoundaryExit {
  Real distance2;  // |q - p|^2
  Vec3 position;   // p*
  Vec3 closest;    // q
};
std::optional<BoundaryExit> boundaryExit(const std::vector<Vec3>& x, const Triangle& f, const Vec3& p, Real radius) {
  const Vec3 q = closestPointOnTriangle(p, x[f[0]], x[f[1]], x[f[2]]);
  const Vec3 n = (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
  const Real len = n.norm();
  if (!(len > Real(0))) return std::nullopt;
  return BoundaryExit{(q - p).squaredNorm(), q + (radius / len) * n, q};
}

}  // namespace

// Last resort for a particle no tet-by-tet push could free: the closest point q of the
// boundary surface, and p* = q + radius n with n that face's outward normal; of equally near
// faces the first. It runs only for such particles (corners and ridges), but a brute force over
// the boundary cost as much as all other pushes together. The face with the nearest box is
// tried first; its distance bounds the answer, and a face whose box is farther (a lower bound
// of its own distance) can be neither nearer nor equal, so it is skipped: the same face as the
// brute force. "Farther" with a margin of 1e-5 of the coordinates' size, far above the float
// rounding of the two distances, so that rounding cannot skip a face the brute force keeps.
// The wall point pushed away from is q.
Vec3 ParticleTetCollider::nearestBoundaryExit(const std::vector<Vec3>& x, const Vec3& p, Real radius,
                                              WallContact& contact) const {
  auto boxDistance2 = [&](std::size_t k) {
    const auto& [lo, hi] = m_boundaryBoxes[k];
    return (p - p.cwiseMax(lo).cwiseMin(hi)).squaredNorm();
  };
  const std::size_t faces = m_boundary.size();
  std::size_t first = faces;
  Real firstBox = std::numeric_limits<Real>::infinity();
  for (std::size_t k = 0; k < faces; ++k) {
    const Real d2 = boxDistance2(k);
    if (d2 < firstBox) firstBox = d2, first = k;
  }
  Real best = std::numeric_limits<Real>::infinity(), skipBeyond = best;
  std::size_t bestFace = faces;
  std::optional<BoundaryExit> bestExit;
  const Real scale = p.cwiseAbs().maxCoeff();
  auto offer = [&](std::size_t k) {
    const std::optional<BoundaryExit> exit = boundaryExit(x, m_boundary[k], p, radius);
    if (!exit || !(exit->distance2 < best || (exit->distance2 == best && k < bestFace))) return;
    best = exit->distance2;
    bestFace = k;
    bestExit = exit;
    const Real reach = std::sqrt(best) * (1 + Real(1e-5)) + Real(1e-5) * scale;
    skipBeyond = reach * reach;
  };
  if (first < faces) offer(first);
  for (std::size_t k = 0; k < faces; ++k)
    if (k != first && !(boxDistance2(k) > skipBeyond)) offer(k);
  if (!bestExit) return p;
  const Triangle& f = m_boundary[bestFace];
  contact.vertices = f;
  contact.weights = triangleWeights(bestExit->closest, x[f[0]], x[f[1]], x[f[2]]);
  return bestExit->position;
}

Vec3 ParticleTetCollider::nearestBoundaryExitAt(const std::vector<Vec3>& positions, const Vec3& p, Real radius) {
  rebuild(positions, m_builtValid ? m_builtPadding : Real(0), 1);
  WallContact contact;
  return nearestBoundaryExit(positions, p, radius, contact);
}

// Where the nearest exit lands in the solid again (a ridge between two lumens, where the
// nearest faces of both sides hand the particle back and forth), the next nearest, and so on:
// the exits in order of distance, the first that no tet holds. Brute force, and only for a
// particle that the settle rounds left inside and whose start is inside too (the wall moved
// onto it): a handful per second of a beating heart.
Vec3 ParticleTetCollider::nearestFreeBoundaryExit(const std::vector<Vec3>& x, const Vec3& p, Real radius,
                                                  WallContact& contact) const {
  std::vector<std::pair<Real, std::size_t>> order;
  order.reserve(m_boundary.size());
  for (std::size_t k = 0; k < m_boundary.size(); ++k)
    if (const std::optional<BoundaryExit> exit = boundaryExit(x, m_boundary[k], p, radius))
      order.emplace_back(exit->distance2, k);
  std::sort(order.begin(), order.end());  // by distance, then face index: deterministic
  for (const auto& [distance2, k] : order) {
    const Triangle& f = m_boundary[k];
    const BoundaryExit exit = *boundaryExit(x, f, p, radius);
    if (insideAnyTet(x, exit.position)) continue;
    contact.vertices = f;
    contact.weights = triangleWeights(exit.closest, x[f[0]], x[f[1]], x[f[2]]);
    return exit.position;
  }
  return p;
}

void ParticleTetCollider::rebuild(const std::vector<Vec3>& positions, Real padding, int threads) {
  // The solid does not move during a fluid solve's iterations: the grid of the last call is
  // still right when the solid's vertices and the padding are bitwise the same (a 12-byte
  // compare per vertex against a build over every tet).
  const auto begin = positions.begin() + std::ptrdiff_t(m_firstVertex);
  const auto end = positions.begin() + std::ptrdiff_t(std::min<std::size_t>(m_vertexEnd, positions.size()));
  const bool sameSolid = m_builtValid && padding == m_builtPadding && std::size_t(end - begin) == m_built.size();
  std::size_t moved = sameSolid ? 0 : m_built.size();
  if (sameSolid)
    for (auto v = begin; v != end; ++v) {
      const Vec3& b = m_built[std::size_t(v - begin)];
      moved += v->x() == b.x() && v->y() == b.y() && v->z() == b.z() ? 0 : 1;
    }
  if (sameSolid && moved == 0) return;
  // A few vertices moved (the wall's free vertices by its constraints, the rest held by a
  // recording): the grid's cells may still hold every box (TetGrid::refit). When most of the
  // solid moved (a new step's predictions) a refit would rarely hold and is not tried.
  const bool refittable = sameSolid && 2 * moved <= m_built.size();
  m_built.assign(begin, end);
  m_builtPadding = padding;
  m_builtValid = true;
  m_boundaryBoxes.resize(m_boundary.size());
  for (std::size_t k = 0; k < m_boundary.size(); ++k) {
    const Triangle& f = m_boundary[k];
    m_boundaryBoxes[k] = {positions[f[0]].cwiseMin(positions[f[1]]).cwiseMin(positions[f[2]]),
                          positions[f[0]].cwiseMax(positions[f[1]]).cwiseMax(positions[f[2]])};
  }
  // Points on a shared face count as inside both tets (kBarycentricSlack), so the boxes are
  // padded by a hair to keep such points among the candidates.
  TetGridSettings grid = m_grid.settings();
  grid.padding = padding;
  grid.threads = threads;
  // Cells of half a tet: the grid is built once or twice a step (twice when the wall's
  // constraints move it between the density solve and the contacts) but asked once per particle per
  // density iteration, and most of a query is the isPointInTet of each candidate. Halving the
  // cell edge cuts the candidates of a cell at the wall (each tet enters up to 27 cells
  // instead of 8): 3 s of `normal` on 1 thread step 139 -> 156 per second, the same state.
  // (Keeping the grid for several steps, built with a skin the wall may move within, was
  // slower: the apex moves half a millimetre a step in systole, and a wider skin means more
  // candidates.)
  grid.cellSizeFactor = Real(0.5);
  m_grid.setSettings(grid);
  if (refittable && m_grid.refit(positions, m_tets)) return;
  m_grid.build(positions, m_tets);
}

bool ParticleTetCollider::pushOut(const std::vector<Vec3>& p, const std::vector<Vec3>& start, Vec3& x,
                                  const Vec3& previous, const ParticleTetSettings& settings,
                                  WallContact& contact) const {
  bool changed = false;
  // Tunnelling: a particle that moved more than its radius this step may have crossed a wall
  // thinner than its step and end outside every tet. Its path is sampled at half-radius
  // steps; the first sample inside a tet becomes the point the push-out below starts from, so
  // the particle goes back along its ray to its radius before the face it entered through.
  // Only for a particle that started outside the solid (one the wall moved onto is the
  // passes' business, in the tet's frame).
  const Real moved2 = (x - previous).squaredNorm();
  if (moved2 > settings.radius * settings.radius && !insideAnyTet(p, x) && !insideAnyTet(p, previous)) {
    const Real length = std::sqrt(moved2);
    const int samples = std::min(kMaxPathSamples, int(std::ceil(length / (Real(0.5) * settings.radius))));
    for (int j = 1; j < samples; ++j) {
      const Vec3 point = previous + (Real(j) / Real(samples)) * (x - previous);
      if (insideAnyTet(p, point)) {
        x = point;
        break;
      }
    }
  }
  // While walking back along the ray through interior faces, the entry point of the last tet
  // and the ray's unit direction: the particle must end `radius` beyond the entry into the
  // solid, not into one of its inner tets.
  bool walking = false;
  Vec3 entry = Vec3::Zero(), ray = Vec3::Zero();
  const Vec3 penetrated = x;  // where the particle was found, before any push (free slip)
  int left = -1;  // while walking: the tet just left, which the point on its face is still in
  for (int pass = 0; pass < settings.maxPasses; ++pass) {
    // The lowest-numbered tet holding the particle (deterministic), then push out of it.
    int hit = -1;
    m_grid.forEachCandidate(x, [&](Index t) {
      if (hit < 0 && int(t) != left && isPointInTet(tetPoints(p, m_tets[t]), x, kBarycentricSlack)) hit = int(t);
    });
    if (hit < 0) break;
    const auto t = std::size_t(hit);
    const TetPoints now = tetPoints(p, m_tets[t]);
    // The ray in the tet's own frame: where the particle started, carried along by the
    // tet's motion this step (u = sum_k lambda_k (p_k - x_k) at the particle's barycentric
    // coordinates). A wall sweeping over a resting particle then pushes it out through the
    // face that swept over it, not the nearest one; for a resting tet this is eq. 4.20's ray.
    const TetPointQuery q = queryPointInTet(now, x);
    Vec3 sweep = Vec3::Zero();
    for (std::size_t k = 0; k < 4; ++k) sweep += q.barycentric[k] * (p[m_tets[t][k]] - start[m_tets[t][k]]);
    const Vec3 from = previous + sweep;
    const Vec3 before = x;
    const TetPushOut out = pushOutOfTet(now, x, from, settings.radius, m_exitFaces[t]);
    if (out.face < 0) break;  // degenerate tet: nothing it can say
    changed = true;
    walking = false;
    left = -1;
    x = out.position;
    const auto& face = kTetFaceVertices[std::size_t(out.face)];
    for (std::size_t k = 0; k < 3; ++k) contact.vertices[k] = m_tets[t][std::size_t(face[k])];
    contact.weights = out.faceWeights;
    if (out.alongRay && !(m_boundaryFaces[t] & (1u << out.face))) {
      // Entered through an inner face: step just across it into the tet the ray came from
      // and push again from there (eq. 4.20 measured from the solid's surface).
      ray = (before - from).normalized();
      entry = out.position + settings.radius * ray;
      x = entry - (Real(1e-3) * settings.radius) * ray;
      walking = true;
      // A step of 1e-3 radii can stay within the shared face's slack, where the tet just left
      // still holds the point and, being the lowest-numbered, would be found again.
      left = hit;
    } else if (settings.slip && (m_boundaryFaces[t] & (1u << out.face))) {
      // Free slip: the boundary face the particle entered the solid through (found by the ray,
      // or the nearest exit when the ray says nothing); the particle where it was found, p,
      // leaves along the face's outward normal n to `radius` beyond its plane,
      // p* = p + (n . (a - p) + radius) n (a a corner of the face), keeping the motion along it.
      const Vec3 n = tetFaceNormal(now, out.face);
      const Vec3& a = now[std::size_t(kTetFaceVertices[std::size_t(out.face)][0])];
      x = penetrated + (n.dot(a - penetrated) + settings.radius) * n;
    }
    if (pass + 1 == settings.maxPasses) {
      x = nearestBoundaryExit(p, x, settings.radius, contact);
      walking = false;
    }
  }
  // The step across an inner face found no tet (the faces did not quite meet): finish the
  // push from the last entry.
  if (walking) x = entry - settings.radius * ray;
  // A push out of one face can land in the tet behind another (a concave corner of the
  // surface, where the cavity meets the base plate): out through the nearest boundary face
  // again, as the static mesh collider repeats its contacts, until no tet holds the particle.
  if (changed) {
    bool inside = insideAnyTet(p, x);
    for (int round = 0; round < kSettleRounds && inside; ++round) {
      x = nearestBoundaryExit(p, x, settings.radius, contact);
      inside = insideAnyTet(p, x);
    }
    // Last resort: back where the step started, if the solid does not hold that point, else
    // the boundary exit nearest to where the particle was found that the solid does not hold.
    if (inside)
      x = !insideAnyTet(p, previous) ? previous : nearestFreeBoundaryExit(p, penetrated, settings.radius, contact);
  }
  return changed;
}

bool ParticleTetCollider::insideAnyTet(const std::vector<Vec3>& p, const Vec3& x) const {
  bool inside = false;
  m_grid.forEachCandidate(x, [&](Index t) {
    if (!inside && isPointInTet(tetPoints(p, m_tets[t]), x, kBarycentricSlack)) inside = true;
  });
  return inside;
}

std::size_t ParticleTetCollider::resolve(Particles& particles, Index first, Index end,
                                         const ParticleTetSettings& settings) {
  std::vector<Vec3>& p = particles.predicted;
  const std::vector<Real>& w = particles.inverseMass;
  rebuild(p, Real(1e-3) * settings.radius, settings.threads);
  const std::ptrdiff_t count = std::ptrdiff_t(end) - std::ptrdiff_t(first);
  // Two-way: each iteration fills only its own slot; the wall is read, never written, in the
  // parallel loop.
  if (settings.twoWay)
    m_wallCorrections.assign(std::size_t(std::max<std::ptrdiff_t>(count, 0)), WallCorrection{});
  std::size_t moved = 0;
#pragma omp parallel for schedule(dynamic, 64) num_threads(settings.threads) reduction(+ : moved) \
    if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = first + Index(s);
    if (!particles.dynamic(i)) continue;
    Vec3 x = p[i];
    WallContact contact;
    if (!pushOut(p, particles.position, x, particles.position[i], settings, contact)) continue;
    ++moved;
    if (settings.twoWay) {
      const std::array<Real, 3> wallW{yieldingInverseMass(w, contact.vertices[0]),
                                      yieldingInverseMass(w, contact.vertices[1]),
                                      yieldingInverseMass(w, contact.vertices[2])};
      const TwoWayPushOut split = splitPushOut(x - p[i], w[i], contact.weights, wallW);
      if (split.shared) {
        x = p[i] + split.particle;
        m_wallCorrections[std::size_t(s)] = {contact.vertices, split.wall, true};
      }
    }
    p[i] = x;
  }
  // The wall's reactions, by one thread in particle order: every vertex gets the same sum, in
  // the same order, for any thread count. Pinned vertices are skipped, not even given a zero.
  if (settings.twoWay)
    for (const WallCorrection& c : m_wallCorrections)
      if (c.active)
        for (std::size_t k = 0; k < 3; ++k)
          if (yieldingInverseMass(w, c.vertices[k]) > Real(0)) p[c.vertices[k]] += c.delta[k];
  return moved;
}

std::size_t ParticleTetCollider::resolvePoints(const Particles& particles, std::vector<Vec3>& points,
                                               std::span<const Index> ids,
                                               const ParticleTetSettings& settings) {
  rebuild(particles.predicted, Real(1e-3) * settings.radius, settings.threads);
  const auto count = std::ptrdiff_t(ids.size());
  std::size_t moved = 0;
#pragma omp parallel for schedule(dynamic, 64) num_threads(settings.threads) reduction(+ : moved) \
    if (count >= kParallelThreshold)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const Index i = ids[std::size_t(k)];
    if (!particles.dynamic(i)) continue;
    WallContact contact;  // unused: one-way
    moved += pushOut(particles.predicted, particles.position, points[std::size_t(k)], particles.position[i],
                     settings, contact);
  }
  return moved;
}

std::size_t ParticleTetCollider::countInside(const std::vector<Vec3>& positions, Index first, Index end,
                                             Real minDepth, int threads) {
  // A point deeper than minDepth inside a tet lies inside the tet's own box: any padding
  // will do, so the last build's is kept and an unmoved solid needs no rebuild.
  rebuild(positions, m_builtValid ? m_builtPadding : Real(0), threads);
  const std::ptrdiff_t count = std::ptrdiff_t(end) - std::ptrdiff_t(first);
  std::size_t inside = 0;
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) reduction(+ : inside) \
    if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Vec3& x = positions[first + Index(s)];
    bool deep = false;
    m_grid.forEachCandidate(x, [&](Index t) {
      if (deep) return;
      const TetPointQuery q = queryPointInTet(tetPoints(positions, m_tets[t]), x);
      deep = q.inside && q.depth > minDepth;
    });
    if (deep) ++inside;
  }
  return inside;
}

}  // namespace hs::pbd
