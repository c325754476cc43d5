// Extrusion of the mid-surface into a one-tet-thick shell: every triangle becomes a prism
// split into three tetrahedra.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cardiac/anatomy/lv_mid_surface.h"

namespace hs::cardiac::detail {

namespace {

// Splits the positive prism (bottom v1 v2 v3, top v4 v5 v6 with v4 over v1, ...) whose first
// vertex in the order `before` is v1. Dompierre et al. (1999): every quad face is cut by the
// diagonal through its first vertex, so two prisms sharing a quad cut it the same way
// (conforming). The quads through v1 are cut at v1-v5 and v1-v6; the quad (v2 v3 v6 v5) at
// v2-v6 when min(v2, v6) comes before min(v3, v5), else at v3-v5. All three tets keep the
// prism's orientation.
template <typename Before>
void splitPrism(const std::array<Index, 6>& v, const Before& before, std::vector<pbd::Tet>& tets) {
  const auto [v1, v2, v3, v4, v5, v6] = v;
  auto first = [&](Index a, Index b) { return before(a, b) ? a : b; };
  if (before(first(v2, v6), first(v3, v5))) {
    tets.push_back({v1, v2, v3, v6});
    tets.push_back({v1, v2, v6, v5});
  } else {
    tets.push_back({v1, v2, v3, v5});
    tets.push_back({v1, v5, v3, v6});
  }
  tets.push_back({v1, v5, v6, v4});
}

}  // namespace

pbd::TetMesh extrudeShell(const MidSurface& s) {
  std::vector<Vec3d> x(2 * s.inner.size());
  for (std::size_t i = 0; i < s.inner.size(); ++i) {
    x[2 * i] = s.inner[i];
    x[2 * i + 1] = s.outer[i];
  }
  std::vector<pbd::Tet> tets;
  tets.reserve(3 * s.triangles.size());
  // Total order on tet-mesh vertices: rank, then decreasing key inner . (outer - inner), then
  // mid-surface id and layer (inner 2i before outer 2i+1).
  std::vector<double> key(s.inner.size());
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = s.inner[i].dot(s.outer[i] - s.inner[i]);
  auto before = [&](Index p, Index q) {
    const Index mp = p / 2;
    const Index mq = q / 2;
    if (s.rank[mp] != s.rank[mq]) return s.rank[mp] < s.rank[mq];
    if (key[mp] != key[mq]) return key[mp] > key[mq];
    return p < q;
  };
  for (pbd::Triangle t : s.triangles) {
    // A vertex's inner copy precedes its outer one, so the prism's first vertex is an inner
    // one: rotate the triangle (keeping its winding) to put it first.
    std::rotate(t.begin(),
                std::min_element(t.begin(), t.end(), [&](Index p, Index q) { return before(2 * p, 2 * q); }),
                t.end());
    splitPrism({2 * t[0], 2 * t[1], 2 * t[2], 2 * t[0] + 1, 2 * t[1] + 1, 2 * t[2] + 1}, before, tets);
  }
  // The prism is positive because orientTriangles wound its bottom toward its top; check that
  // the geometry agrees. Normalised volume 6 sqrt(2) V / L^3 is 1 for a regular tet.
  for (const pbd::Tet& t : tets) {
    const double volume = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]) / 6.0;
    double longest = 0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (x[t[i]] - x[t[j]]).norm());
    }
    const double normalised = 6.0 * std::sqrt(2.0) * volume / (longest * longest * longest);
    if (!(normalised >= kMinNormalisedVolume)) {
      throw std::logic_error("buildLvModel: tet (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                             ", " + std::to_string(t[2]) + ", " + std::to_string(t[3]) +
                             ") is inverted or degenerate (normalised volume " + std::to_string(normalised) +
                             ")");
    }
  }
  pbd::TetMesh mesh;
  mesh.vertices.reserve(x.size());
  for (const Vec3d& p : x) mesh.vertices.push_back(p.cast<Real>());
  mesh.tets = std::move(tets);
  return mesh;
}

}  // namespace hs::cardiac::detail
