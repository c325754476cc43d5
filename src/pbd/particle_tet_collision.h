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
// Parallelism: one particle per loop iteration, reading the solid and writing only its own
// position, so results are bitwise identical for any thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "pbd/particles.h"
#include "pbd/tet_grid.h"
#include "pbd/tet_mesh.h"

namespace hs::pbd {

struct ParticleTetSettings {
  Real radius = Real(0.08);  // m: the particle ends this far beyond the face (eq. 4.20)
  int maxPasses = 32;        // rounds of "find a containing tet, push out of it"
  int threads = 1;
};

class ParticleTetCollider {
 public:
  // tets index the solid's vertices, which are particles firstVertex + v of the set passed to
  // resolve(); the topology is fixed (the boundary faces are computed once here).
  ParticleTetCollider(std::vector<Tet> tets, Index firstVertex);

  // Pushes the particles [first, end) out of the solid at its predicted positions. Each
  // particle's ray runs from its start-of-step position to its predicted one. Returns the
  // number of particles moved.
  std::size_t resolve(Particles& particles, Index first, Index end, const ParticleTetSettings& settings);

  // The same for points held outside the particle set (a solver's working copy): points[k] is
  // where particle ids[k] is now; the solid is at particles.predicted, and each point's ray
  // starts at particles.position[ids[k]].
  std::size_t resolvePoints(const Particles& particles, std::vector<Vec3>& points, std::span<const Index> ids,
                            const ParticleTetSettings& settings);

  // Particles of [first, end) whose centre lies deeper than minDepth inside some tet, at
  // `positions` (solid and particles from the same array).
  std::size_t countInside(const std::vector<Vec3>& positions, Index first, Index end, Real minDepth,
                          int threads = 1);

  const std::vector<Tet>& tets() const { return m_tets; }

 private:
  void rebuild(const std::vector<Vec3>& positions, Real padding);
  // Pushes x (a particle that started this step at `previous`) out of the solid at positions
  // p (start of step: `start`); true if it moved.
  bool pushOut(const std::vector<Vec3>& p, const std::vector<Vec3>& start, Vec3& x, const Vec3& previous,
               const ParticleTetSettings& settings) const;
  Vec3 nearestBoundaryExit(const std::vector<Vec3>& x, const Vec3& p, Real radius) const;

  std::vector<Tet> m_tets;                  // the solid's tets, vertex ids shifted to particle ids
  std::vector<std::uint8_t> m_exitFaces;    // boundary-face mask per tet (tet_geometry.h)
  std::vector<Triangle> m_boundary;         // the solid's boundary faces, outward (particle ids)
  TetGrid m_grid;
};

}  // namespace hs::pbd
