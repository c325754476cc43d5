#pragma once
// Particles against a moving tetrahedral solid (thesis section 4.4, Fig. 4.1's "heart-blood
// interaction"): after the solid has moved, every particle whose centre lies inside one of its
// tetrahedra (eq. 4.12-4.13) is moved back along its own motion of this step to its radius
// beyond the face it entered through (Plücker ray-tetrahedron test, eq. 4.14-4.19,
// Platis & Theoharis 2003; push-out eq. 4.20), or out through the nearest boundary face when
// the ray gives no usable answer (tet_geometry.h).
//
// Candidate tetrahedra come from a uniform grid over the tets' bounding boxes (tet_grid.h),
// rebuilt from the solid's positions on every call, so the cost per particle does not grow
// with the solid's size. A particle pushed out of one tet may land in a neighbour (by at most
// its radius, across a shared face): passes repeat, with the same start-of-step position,
// until no tet holds it (at most `maxPasses`); each pass moves it further back along its ray,
// one tet at a time. A particle still inside after that (no usable ray deep inside a thick
// solid, where per-tet exits cannot know the way out) goes to the nearest point of the
// solid's boundary surface and its radius beyond, along that face's outward normal.
//
// Two-way coupling (ParticleTetSettings::twoWay; Müller et al. 2007, "Position based
// dynamics", section 3.3). The one-way push-out above moves particle p (inverse mass w_p) by d,
// from where it is to the exit point. With twoWay, d instead becomes the PBD constraint
//   C = n . (x_p - sum_i b_i x_i) - (its current value + |d|),   n = d / |d|,
// between the particle and the wall point it is pushed away from: weights b_i (>= 0, sum 1)
// over the vertices of the face it finally leaves through (TetPushOut::faceWeights, or the
// boundary triangle of the last-resort exit). grad_p C = n, grad_i C = -b_i n, so
//   s = |d| / (w_p + sum_i b_i^2 w_i),   dx_p = w_p s n,   dx_i = -w_i b_i s n,
// computed as dx_p = w_p k d, dx_i = -w_i b_i k d with k = 1 / (w_p + sum_i b_i^2 w_i).
// Momentum: m_p dx_p + sum_i m_i dx_i = s n (1 - sum_{w_i > 0} b_i) = 0 when every face vertex
// is free. A pinned vertex (w_i = 0) does not move and absorbs its share of the momentum like
// a fixed wall. When sum_i b_i^2 w_i = 0 (the whole face pinned: infinite wall mass), the
// particle takes the one-way result bitwise.
// The passes above are a search for the exit point against the wall as it is at the start of
// the call; their steps add up to d, which is applied as one constraint per particle and call
// (splitting each pass against the frozen wall would find the particle inside again and count
// the wall's share twice). The wall's reaction is not felt by other particles in the same call:
// corrections of all particles pressing on a vertex add up (Jacobi), which conserves momentum
// but can over-push a light wall that many particles hit at once; the wall's own constraints
// and the next call settle that.
//
// Parallelism: one particle per loop iteration, reading the solid and writing only its own
// position, so results are bitwise identical for any thread count. Two-way wall corrections
// are recorded in a slot per particle in the loop and added to the wall afterwards by one
// thread, in particle order: no scatter races, and the same sums for any thread count.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "pbd/core/particles.h"
#include "pbd/core/tet_mesh.h"
#include "pbd/grid/tet_grid.h"

namespace hs::pbd {

struct ParticleTetSettings {
  Real radius = Real(0.08);  // m: the particle ends this far beyond the face (eq. 4.20)
  int maxPasses = 32;        // rounds of "find a containing tet, push out of it"
  int threads = 1;
  // resolve() only: the push-out is shared with the wall vertices by inverse mass (above).
  // false: only the particle moves (the wall as infinitely heavy), as before.
  bool twoWay = false;
  // What the push-out keeps of the motion. false (thesis eq. 4.20): back along the ray to
  // `radius` before the face it entered through, so the particle loses its motion along the
  // wall too (it ends where it was a radius before reaching the wall). true (free slip): out
  // of that same face (found by the ray) along the face's normal to `radius` beyond it, so
  // only the motion into the wall is undone and blood slides along the wall; docs/heart-blood.md.
  bool slip = false;
};

// The two-way split of one push-out (above): d = the particle's one-way displacement,
// weights b_i and inverse masses w_i of the three wall vertices. particle = w_p k d,
// wall[i] = -w_i b_i k d, k = 1 / (w_p + sum_i b_i^2 w_i). shared is false when the wall part
// sum_i b_i^2 w_i is zero (or w_p is not positive): then the caller keeps the one-way result,
// and particle = d, wall = 0.
struct TwoWayPushOut {
  Vec3 particle = Vec3::Zero();
  std::array<Vec3, 3> wall{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  bool shared = false;
};
TwoWayPushOut splitPushOut(const Vec3& d, Real particleInverseMass, const std::array<Real, 3>& weights,
                           const std::array<Real, 3>& wallInverseMass);

class ParticleTetCollider {
 public:
  // tets index the solid's vertices, which are particles firstVertex + v of the set passed to
  // resolve(); the topology is fixed (the boundary faces are computed once here).
  ParticleTetCollider(std::vector<Tet> tets, Index firstVertex);

  // Pushes the particles [first, end) out of the solid at its predicted positions. Each
  // particle's ray runs from its start-of-step position to its predicted one. Returns the
  // number of particles moved. With settings.twoWay the solid's vertices (particles.predicted,
  // weighted by particles.inverseMass) are pushed back as well, after all particles.
  std::size_t resolve(Particles& particles, Index first, Index end, const ParticleTetSettings& settings);

  // The same for points held outside the particle set (a solver's working copy): points[k] is
  // where particle ids[k] is now; the solid is at particles.predicted, and each point's ray
  // starts at particles.position[ids[k]]. Always one-way (settings.twoWay is ignored): the
  // solid is read-only here, and this runs inside the fluid solver's density iterations, where
  // the wall only has to keep the blood's working copy out; the step's final resolve() is
  // where blood pushes the wall back.
  std::size_t resolvePoints(const Particles& particles, std::vector<Vec3>& points, std::span<const Index> ids,
                            const ParticleTetSettings& settings);

  // Particles of [first, end) whose centre lies deeper than minDepth inside some tet, at
  // `positions` (solid and particles from the same array).
  std::size_t countInside(const std::vector<Vec3>& positions, Index first, Index end, Real minDepth,
                          int threads = 1);

  // The last resort's exit for a point p with the solid at `positions` (solid and points from
  // the same array): the nearest boundary face's closest point to p, plus radius along that
  // face's outward normal; of equally near faces the first. Public for its brute-force test.
  Vec3 nearestBoundaryExitAt(const std::vector<Vec3>& positions, const Vec3& p, Real radius);

  const std::vector<Tet>& tets() const { return m_tets; }

  // The particles live on one side of the solid (blood in a heart: the cavity and vessel
  // lumens). wetted[v] marks the solid's vertices on that side (v = vertex id, as in the
  // tets passed to the constructor); a boundary face is wetted when its three vertices are.
  // A particle that has no usable ray back (the wall moved onto it, or it sank deep within
  // one step) then leaves only through wetted faces: never out of the far side of a wall.
  void setWettedVertices(const std::vector<std::uint8_t>& wetted);

  // Two-way coupling: yielding[v] marks the solid's vertices that take a share of the push-out
  // (vertex ids as for setWettedVertices); the others act as pinned, however light they are.
  // Unset: every vertex with mass yields.
  void setYieldingVertices(std::vector<std::uint8_t> yielding) { m_yielding = std::move(yielding); }

 private:
  // The inverse mass particle `particle` (a solid vertex) has in the two-way split.
  [[nodiscard]] Real yieldingInverseMass(const std::vector<Real>& inverseMass, Index particle) const {
    const std::size_t v = std::size_t(particle - m_firstVertex);
    return m_yielding.empty() || (v < m_yielding.size() && m_yielding[v]) ? inverseMass[particle] : Real(0);
  }

  // The wall point a particle was last pushed away from: weights (sum 1) over three vertices.
  struct WallContact {
    Triangle vertices{};
    std::array<Real, 3> weights{};
  };
  // One particle's two-way reaction on the wall, applied after the parallel loop.
  struct WallCorrection {
    Triangle vertices{};
    std::array<Vec3, 3> delta{};
    bool active = false;
  };

  // The tet grid over `positions` (binned on `threads`; the same grid on any number).
  void rebuild(const std::vector<Vec3>& positions, Real padding, int threads);
  // Pushes x (a particle that started this step at `previous`) out of the solid at positions
  // p (start of step: `start`); true if it moved, and then `contact` is the wall point of the
  // last push.
  bool pushOut(const std::vector<Vec3>& p, const std::vector<Vec3>& start, Vec3& x, const Vec3& previous,
               const ParticleTetSettings& settings, WallContact& contact) const;
  bool insideAnyTet(const std::vector<Vec3>& p, const Vec3& x) const;
  Vec3 nearestBoundaryExit(const std::vector<Vec3>& x, const Vec3& p, Real radius,
                           WallContact& contact) const;
  // The nearest of the boundary exits (as above) that no tet holds; p unchanged if none.
  Vec3 nearestFreeBoundaryExit(const std::vector<Vec3>& x, const Vec3& p, Real radius,
                               WallContact& contact) const;

  std::vector<Tet> m_tets;                // the solid's tets, vertex ids shifted to particle ids
  std::vector<std::uint8_t> m_boundaryFaces;  // boundary-face mask per tet (tet_geometry.h)
  // Faces a particle without a usable ray may leave a tet through (pushOutOfTet's fallback):
  // the boundary faces, or after setWettedVertices the wetted ones (else the tet's inner
  // faces, toward its neighbours).
  std::vector<std::uint8_t> m_exitFaces;
  std::vector<Triangle> m_boundary;  // boundary faces a particle may be put beyond, outward (particle ids)
  std::vector<std::array<Vec3, 2>> m_boundaryBoxes;  // their boxes (lo, hi) at the last rebuild()
  std::vector<std::uint8_t> m_yielding;  // per solid vertex; empty: all yield
  Index m_firstVertex = 0;
  std::size_t m_vertexEnd = 0;  // one past the solid's last particle id
  // The solid's vertices and padding of the last grid build (rebuild() skips an identical one).
  std::vector<Vec3> m_built;
  Real m_builtPadding = 0;
  bool m_builtValid = false;
  TetGrid m_grid;
  std::vector<WallCorrection> m_wallCorrections;  // resolve() scratch, one slot per particle
};

}  // namespace hs::pbd
