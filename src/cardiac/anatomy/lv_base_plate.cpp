// The base plate: a flat disk closing the cup at y = 0 with the two orifices cut out,
// triangulated in 2D (Delaunay of boundary rings plus an interior triangular lattice).
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cardiac/anatomy/lv_mid_surface.h"
#include "mesh/planar_delaunay.h"

namespace hs::cardiac::detail {

namespace {

constexpr double kRowHeight = 0.8660254037844386;  // sqrt(3) / 2
// Lattice points closer than kKeepAway * h to a boundary circle are dropped, so boundary
// chords stay Delaunay edges and no sliver forms next to the boundary.
constexpr double kKeepAway = 0.6;
// Jacobi sweeps of Laplacian smoothing of the lattice points next to the boundary rings.
constexpr int kSmoothingIterations = 4;

Vec2d planar(const Vec3d& p) { return {p.x(), p.z()}; }

double cross2(const Vec2d& u, const Vec2d& v) { return u.x() * v.y() - u.y() * v.x(); }

struct Hole {
  Vec2d centre;
  double radius;
};

// Delaunay triangulation of `pts` without the triangles that touch the first `helpers`
// points (hole centres, there only to keep the holes' cocircular rings well conditioned) or
// that lie inside a hole or outside the rim circle.
std::vector<pbd::Triangle> plateTriangles(const std::vector<Vec2d>& pts, std::size_t helpers,
                                          const std::vector<Hole>& holes, double rimRadius) {
  std::vector<pbd::Triangle> kept;
  for (const pbd::Triangle& t : pbd::delaunayTriangulation(pts)) {
    if (t[0] < helpers || t[1] < helpers || t[2] < helpers) continue;
    const Vec2d centroid = (pts[t[0]] + pts[t[1]] + pts[t[2]]) / 3.0;
    bool inside = centroid.norm() < rimRadius;
    for (const Hole& h : holes) inside = inside && (centroid - h.centre).norm() > h.radius;
    if (inside) kept.push_back(t);
  }
  return kept;
}

bool hasEdge(const std::vector<pbd::Edge>& edges, Index a, Index b) {
  return std::binary_search(edges.begin(), edges.end(), pbd::Edge{std::min(a, b), std::max(a, b)});
}

}  // namespace

void addBasePlate(MidSurface& s, const ShellDims& d, const Ring& rim, const Ring& mitral,
                  const Ring& aortic) {
  const std::vector<Hole> holes = {{d.mitral.centre, d.mitral.radius}, {d.aortic.centre, d.aortic.radius}};
  const double h = d.plateH;
  const double keep = kKeepAway * h;
  // Points: hole centres (helpers), interior lattice, then the boundary rings, whose ids exist.
  std::vector<Vec2d> pts = {holes[0].centre, holes[1].centre};
  const std::size_t helpers = pts.size();
  const auto rows = static_cast<long>(std::ceil(d.a / (kRowHeight * h)));
  for (long r = -rows; r <= rows; ++r) {
    const double z = double(r) * kRowHeight * h;
    const double rowOffset = (r % 2 == 0) ? 0.0 : 0.5;
    const auto cols = static_cast<long>(std::ceil(d.a / h)) + 1;
    for (long k = -cols; k <= cols; ++k) {
      const Vec2d p((double(k) + rowOffset) * h, z);
      bool ok = p.norm() <= d.a - keep;
      for (const Hole& hole : holes) ok = ok && (p - hole.centre).norm() >= hole.radius + keep;
      if (ok) pts.push_back(p);
    }
  }
  const std::size_t interiorEnd = pts.size();
  std::vector<Index> ids(pts.size(), 0);                // mid-surface id per point (interior: assigned below)
  std::vector<Vec2d> shift(pts.size(), Vec2d::Zero());  // outer-layer in-plane displacement
  for (const Ring* ring : {&mitral, &aortic, &rim}) {
    for (Index id : ring->ids) {
      pts.push_back(planar(s.inner[id]));
      ids.push_back(id);
      shift.push_back(planar(s.outer[id]) - planar(s.inner[id]));
    }
  }

  // Laplacian smoothing of the lattice points (each moves to the mean of its neighbours),
  // then a fresh Delaunay triangulation of the smoothed points.
  std::vector<pbd::Triangle> tris = plateTriangles(pts, helpers, holes, d.a);
  for (int iter = 0; iter < kSmoothingIterations; ++iter) {
    std::vector<Vec2d> sum(pts.size(), Vec2d::Zero());
    std::vector<int> count(pts.size(), 0);
    for (const pbd::Triangle& t : tris) {
      for (int k = 0; k < 3; ++k) {
        sum[t[k]] += pts[t[(k + 1) % 3]] + pts[t[(k + 2) % 3]];
        count[t[k]] += 2;
      }
    }
    for (std::size_t i = helpers; i < interiorEnd; ++i) {
      if (count[i] > 0) pts[i] = sum[i] / double(count[i]);
    }
  }
  tris = plateTriangles(pts, helpers, holes, d.a);

  // Checks: every boundary chord is an edge, every interior point is used, and the triangles
  // tile the rim polygon minus the hole polygons exactly (no overlaps, no gaps).
  std::vector<pbd::Edge> edges;
  std::vector<int> used(pts.size(), 0);
  double area = 0;
  for (const pbd::Triangle& t : tris) {
    area += 0.5 * cross2(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]);
    for (int k = 0; k < 3; ++k) {
      edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
      used[t[k]] = 1;
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double expectedArea = 0;
  auto first = static_cast<Index>(interiorEnd);
  for (const Ring* ring : {&mitral, &aortic, &rim}) {
    const auto n = static_cast<Index>(ring->ids.size());
    double polygon = 0;
    for (Index k = 0; k < n; ++k) {
      const Index a = first + k;
      const Index b = first + (k + 1) % n;
      if (!hasEdge(edges, a, b))
        throw std::logic_error("buildLvModel: base plate triangulation misses a boundary chord");
      polygon += 0.5 * cross2(pts[a], pts[b]);
    }
    expectedArea += ring == &rim ? std::abs(polygon) : -std::abs(polygon);
    first += n;
  }
  const bool allUsed =
      std::all_of(used.begin() + static_cast<long>(helpers), used.end(), [](int u) { return u; });
  if (!allUsed || std::abs(area - expectedArea) > 1e-9 * expectedArea) {
    throw std::logic_error("buildLvModel: base plate triangulation does not tile the plate");
  }

  // Outer layer: the plate's top (y = baseThickness), shifted in-plane so it meets the cup's
  // outer rim and the vessels' outer walls. The shift is harmonic (graph Laplacian = 0 at
  // interior points, boundary points fixed at their rings' shifts): the smoothest field, so
  // neighbouring shifts differ little and no prism is crushed (a prism's side tets stay
  // positive while the relative shift of two vertices is smaller than the triangle's height).
  const auto interior = static_cast<Index>(interiorEnd - helpers);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(interior, 2);
  for (const pbd::Edge& e : edges) {
    for (int k = 0; k < 2; ++k) {
      const Index i = e[k];
      const Index j = e[1 - k];
      if (i < helpers || i >= interiorEnd) continue;
      const auto row = static_cast<int>(i - helpers);
      entries.emplace_back(row, row, 1.0);
      if (j < interiorEnd) {
        entries.emplace_back(row, static_cast<int>(j - helpers), -1.0);
      } else {
        rhs.row(row) += shift[j].transpose();
      }
    }
  }
  Eigen::MatrixX2d solved = rhs;
  if (interior > 0) {
    Eigen::SparseMatrix<double> laplacian(interior, interior);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
    solved = solver.solve(rhs);
    if (solver.info() != Eigen::Success)
      throw std::logic_error("buildLvModel: base plate shift solve failed");
  }
  for (std::size_t i = helpers; i < interiorEnd; ++i) {
    const Vec2d out = pts[i] + solved.row(static_cast<int>(i - helpers)).transpose();
    ids[i] = s.addVertex(Vec3d(pts[i].x(), 0, pts[i].y()), Vec3d(out.x(), d.baseThickness, out.y()),
                         Region::BasePlate, kRankPlate);
  }
  for (const pbd::Triangle& t : tris) s.addTriangle(ids[t[0]], ids[t[1]], ids[t[2]], true);
}

}  // namespace hs::cardiac::detail
