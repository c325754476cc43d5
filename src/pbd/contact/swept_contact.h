#pragma once
// Continuous contact of particles against a moving closed surface (the boundary of a
// tetrahedral solid): a particle cannot cross the surface into the solid within a step,
// whatever its speed or the solid's thickness.
//
// Why. The particle-in-tet contact (particle_tet_collision.h, thesis eq. 4.12-4.20) sees a
// particle only where its step ENDS: inside a tet. A particle that moves farther in one step
// than the wall is thick ends on the far side, where no tet holds it (tunnelling). Here the
// whole step is checked: the particle's centre moves linearly from a0 to a1 while each
// surface triangle's vertices move linearly from their start to their end positions, and the
// first time the centre meets a triangle moving against its outward normal is found exactly.
//
// Narrow phase: the vertex-face test of continuous collision detection (Provot 1997,
// "Collision and self-collision handling in cloth model dedicated to design garments";
// Bridson, Fedkiw & Anderson 2002, "Robust treatment of collisions, contact and friction for
// cloth animation", section 4). With p(t) = a0 + t (a1 - a0) and x_i(t) likewise, the point
// is in the triangle's plane when
//   f(t) = (p(t) - x_0(t)) . ((x_1(t) - x_0(t)) x (x_2(t) - x_0(t))) = 0,
// a cubic in t. f > 0 on the outward side (the normal is that of the winding: boundaryFaces
// winds each face outward, tet_mesh.h), so the particle enters the solid where f falls
// through 0. The roots come from [0, 1] split at f's turning points (f' = 0, a quadratic)
// into pieces on which f is monotone: a piece with f > 0 at its start and f <= 0 at its end
// holds exactly one entry, found by bisection. Degenerate cubics (a quadratic, a line, or f
// identically 0 for motion within the plane) need no special case: they only have fewer
// turning points; motion within the plane never enters. The point must then lie on the
// triangle at that time: barycentric coordinates >= -kBarycentricTolerance, so a path through
// a shared edge or vertex is caught by at least one of its triangles. Exits (f rising through
// 0) are free. All of it in double (positions are float): f is a sum of products of
// differences, whose rounding would otherwise decide near-misses.
//
// A path that starts exactly on the face (a particle left there by an earlier contact) may be
// put a hair behind it by rounding and then never "enter": the entry level is a distance
// delta = kPlaneSlack x (the triangle's size) inside the face instead of the face itself, so
// such a path still enters and a path starting deeper than delta inside is leaving.
//
// Broad phase: a BVH over the surface, refitted every step with each triangle's swept box
// (triangle_bvh.h); a particle's path asks only the triangles whose box it touches.
//
// Response. At the first entry (time t, on triangle T at barycentric b), the contact point is
// carried with T to the end of the step, q1 = sum_i b_i x_i(1), and the particle ends radius
// beyond it along T's end normal n1 (the fluid side): a1' = q1 + radius n1. With slip (as
// ParticleTetSettings::slip) it keeps the tangential part of its remaining motion relative to
// the wall, r = (a1 - p(t)) - (q1 - q(t)): a1' = q1 + radius n1 + (r - (r . n1) n1). The
// corrected path a0 -> a1' is checked again (it may cross a neighbouring face of a concave
// corner): up to maxPasses rounds. If it still crosses, the last resort stops the particle at
// the first contact without slip, then (if that crosses too, e.g. a particle pinched between
// two walls) carries its start with the wall point it hit, a0 + q1 - q(0), where it keeps its
// place relative to the wall.
//
// Parallelism: one particle per loop iteration, reading the surface and writing only its own
// position: bitwise the same for any thread count.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "pbd/core/particles.h"
#include "pbd/grid/triangle_bvh.h"

namespace hs::pbd {

// Barycentric slack of "the point lies on the triangle" (fractions of the triangle's heights).
inline constexpr double kBarycentricTolerance = 1e-6;
// The entry level's depth behind the face (above), as a fraction of the triangle's longest edge.
inline constexpr double kPlaneSlack = 1e-6;

// The first entry of a point into one moving triangle.
struct SweptHit {
  double t = 0;                    // time in [0, 1] of the step
  std::array<double, 3> weights{};  // barycentric weights on the triangle at t (sum 1, clamped to >= 0)
};

// The point moves a0 -> a1, the triangle's vertices x0[i] -> x1[i], all linearly over t in
// [0, 1]; the triangle's outward normal is (x_1 - x_0) x (x_2 - x_0). The earliest t at which
// the point lies on the triangle while moving against that normal (above); nullopt if none.
std::optional<SweptHit> firstEntry(const Vec3& a0, const Vec3& a1, const std::array<Vec3, 3>& x0,
                                   const std::array<Vec3, 3>& x1);

struct SweptContactSettings {
  Real radius = Real(0.08);  // m: the particle ends this far beyond the face it hit
  bool slip = false;         // keep the tangential part of the remaining motion (above)
  int maxPasses = 4;         // rounds of "respond, check the corrected path again"
  int threads = 1;
};

// A surface hit: the triangle (index into the surface) and the entry.
struct SurfaceHit {
  std::size_t triangle = 0;
  SweptHit hit;
};

class SweptContact {
 public:
  // surface: triangles wound outward (boundaryFaces), as particle ids; `positions` (any of the
  // surface's configurations) shape the BVH, which stays for the collider's life.
  SweptContact(std::vector<Triangle> surface, const std::vector<Vec3>& positions);

  // The surface moves from `start` to `end` over this step: refits the BVH (every triangle's
  // swept box, grown by margin). Call before firstSurfaceEntry / resolvePath.
  void update(const std::vector<Vec3>& start, const std::vector<Vec3>& end, Real margin, int threads = 1);

  // The earliest entry of the path a0 -> a1 over all triangles of the surface moving from
  // start to end (those of the last update); the lowest triangle index on equal times.
  std::optional<SurfaceHit> firstSurfaceEntry(const std::vector<Vec3>& start, const std::vector<Vec3>& end,
                                              const Vec3& a0, const Vec3& a1) const;

  // Where a particle moving a0 -> a1 ends after the response (above). `unresolved` is set when
  // even the last resort's path crosses the surface.
  Vec3 resolvePath(const std::vector<Vec3>& start, const std::vector<Vec3>& end, const Vec3& a0, const Vec3& a1,
                   const SweptContactSettings& settings, bool* unresolved = nullptr) const;

  // The particles [first, end) move from particles.position to particles.predicted, the surface
  // (its vertices are particles too, outside [first, end)) the same: every dynamic particle's
  // prediction is corrected in place. Returns the number of particles moved.
  std::size_t resolve(Particles& particles, Index first, Index end, const SweptContactSettings& settings);

  [[nodiscard]] const std::vector<Triangle>& surface() const { return m_bvh.triangles(); }
  [[nodiscard]] const TriangleBvh& bvh() const { return m_bvh; }
  // Particles of the last resolve() whose last-resort path still crossed the surface.
  [[nodiscard]] std::size_t lastUnresolved() const { return m_lastUnresolved; }

 private:
  TriangleBvh m_bvh;
  Real m_margin = 0;
  std::size_t m_lastUnresolved = 0;
};

}  // namespace hs::pbd
