#include "mesh/surface_inside.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hs::pbd {
namespace {

struct Point2 {
  double x, z;
};

// Twice the signed area of (u, v, p) in the xz plane: > 0 when p lies left of u -> v.
double edgeFunction(const Point2& u, const Point2& v, const Point2& p) {
  return (v.x - u.x) * (p.z - u.z) - (v.z - u.z) * (p.x - u.x);
}

// The fill rule's tie-break: a point on the edge u -> v of a counter-clockwise triangle belongs
// to it when the edge runs "downward" in a fixed total order of directions. The same edge seen
// from the neighbour on its other side runs the opposite way, so exactly one of them takes it.
bool ownsEdge(const Point2& u, const Point2& v) { return v.z < u.z || (v.z == u.z && v.x < u.x); }

}  // namespace

bool crossesUpwardRay(const Vec3& a3, const Vec3& b3, const Vec3& c3, const Vec3& p3) {
  Point2 a{double(a3.x()), double(a3.z())}, b{double(b3.x()), double(b3.z())}, c{double(c3.x()), double(c3.z())};
  double ya = double(a3.y()), yb = double(b3.y());
  const double yc = double(c3.y());
  const Point2 p{double(p3.x()), double(p3.z())};
  double area = edgeFunction(a, b, c);
  if (area == 0 || !std::isfinite(area)) return false;  // seen edge-on
  if (area < 0) {  // counter-clockwise in xz
    std::swap(a, b);
    std::swap(ya, yb);
    area = -area;
  }
  const double wa = edgeFunction(b, c, p), wb = edgeFunction(c, a, p), wc = edgeFunction(a, b, p);
  auto covers = [](double w, const Point2& u, const Point2& v) { return w > 0 || (w == 0 && ownsEdge(u, v)); };
  if (!(covers(wa, b, c) && covers(wb, c, a) && covers(wc, a, b))) return false;
  // The surface's height over p: the barycentric blend of the corners' heights.
  const double y = (wa * ya + wb * yb + wc * yc) / area;
  return y > double(p3.y());
}

bool insideClosedSurface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, const Vec3& p) {
  bool inside = false;
  for (const Triangle& t : triangles)
    if (crossesUpwardRay(vertices[t[0]], vertices[t[1]], vertices[t[2]], p)) inside = !inside;
  return inside;
}

SurfaceInside::SurfaceInside(std::vector<Vec3> vertices, std::vector<Triangle> triangles, Real columnSize)
    : m_vertices(std::move(vertices)), m_triangles(std::move(triangles)), m_columnSize(columnSize) {
  if (!(columnSize > 0) || m_vertices.empty())
    throw std::invalid_argument("SurfaceInside: expected vertices and a positive column size, got " +
                                std::to_string(m_vertices.size()) + " vertices and " + std::to_string(columnSize));
  Real maxX = m_vertices.front().x(), maxZ = m_vertices.front().z();
  m_minX = maxX;
  m_minZ = maxZ;
  for (const Vec3& v : m_vertices) {
    m_minX = std::min(m_minX, v.x());
    m_minZ = std::min(m_minZ, v.z());
    maxX = std::max(maxX, v.x());
    maxZ = std::max(maxZ, v.z());
  }
  m_columnsX = std::size_t(std::floor((maxX - m_minX) / columnSize)) + 1;
  m_columnsZ = std::size_t(std::floor((maxZ - m_minZ) / columnSize)) + 1;
  // Two passes over the triangles' footprints (their xz boxes): count, then fill.
  auto clampedColumn = [&](Real v, Real lo, std::size_t count) {
    return std::min(count - 1, std::size_t(std::max(Real(0), std::floor((v - lo) / columnSize))));
  };
  auto forEachColumn = [&](const Triangle& t, auto&& visit) {
    const Vec3& a = m_vertices[t[0]];
    const Vec3& b = m_vertices[t[1]];
    const Vec3& c = m_vertices[t[2]];
    const std::size_t x0 = clampedColumn(std::min({a.x(), b.x(), c.x()}), m_minX, m_columnsX);
    const std::size_t x1 = clampedColumn(std::max({a.x(), b.x(), c.x()}), m_minX, m_columnsX);
    const std::size_t z0 = clampedColumn(std::min({a.z(), b.z(), c.z()}), m_minZ, m_columnsZ);
    const std::size_t z1 = clampedColumn(std::max({a.z(), b.z(), c.z()}), m_minZ, m_columnsZ);
    for (std::size_t i = x0; i <= x1; ++i)
      for (std::size_t k = z0; k <= z1; ++k) visit(i * m_columnsZ + k);
  };
  m_columnStart.assign(m_columnsX * m_columnsZ + 1, 0);
  for (const Triangle& t : m_triangles) forEachColumn(t, [&](std::size_t column) { ++m_columnStart[column + 1]; });
  for (std::size_t k = 1; k < m_columnStart.size(); ++k) m_columnStart[k] += m_columnStart[k - 1];
  m_items.resize(m_columnStart.back());
  std::vector<Index> cursor(m_columnStart.begin(), m_columnStart.end() - 1);
  for (std::size_t t = 0; t < m_triangles.size(); ++t)
    forEachColumn(m_triangles[t], [&](std::size_t column) { m_items[cursor[column]++] = Index(t); });

  // The cubes: crossed where a triangle's box reaches (closed boxes, so a surface on a cube's
  // face crosses both cubes), the others answered at their centres.
  Real maxY = m_vertices.front().y();
  m_minY = maxY;
  for (const Vec3& v : m_vertices) {
    m_minY = std::min(m_minY, v.y());
    maxY = std::max(maxY, v.y());
  }
  m_cubesY = std::size_t(std::floor((maxY - m_minY) / columnSize)) + 1;
  std::vector<std::uint8_t> crossed(m_columnsX * m_columnsZ * m_cubesY, 0);
  for (const Triangle& t : m_triangles) {
    const Vec3& a = m_vertices[t[0]];
    const Vec3& b = m_vertices[t[1]];
    const Vec3& c = m_vertices[t[2]];
    const std::size_t y0 = clampedColumn(std::min({a.y(), b.y(), c.y()}), m_minY, m_cubesY);
    const std::size_t y1 = clampedColumn(std::max({a.y(), b.y(), c.y()}), m_minY, m_cubesY);
    forEachColumn(t, [&](std::size_t column) {
      for (std::size_t k = y0; k <= y1; ++k) crossed[column * m_cubesY + k] = 1;
    });
  }
  m_cubes.resize(crossed.size());
  for (std::size_t i = 0; i < m_columnsX; ++i)
    for (std::size_t k = 0; k < m_columnsZ; ++k)
      for (std::size_t j = 0; j < m_cubesY; ++j) {
        const std::size_t cube = (i * m_columnsZ + k) * m_cubesY + j;
        const Vec3 centre(m_minX + (Real(i) + Real(0.5)) * columnSize, m_minY + (Real(j) + Real(0.5)) * columnSize,
                          m_minZ + (Real(k) + Real(0.5)) * columnSize);
        m_cubes[cube] = crossed[cube]                          ? CubeState::Crossed
                        : columnTest(centre, i * m_columnsZ + k) ? CubeState::Inside
                                                                 : CubeState::Outside;
      }
}

bool SurfaceInside::columnOf(Real x, Real z, std::size_t& column) const {
  const Real fx = std::floor((x - m_minX) / m_columnSize), fz = std::floor((z - m_minZ) / m_columnSize);
  if (!(fx >= 0 && fz >= 0 && fx < Real(m_columnsX) && fz < Real(m_columnsZ))) return false;
  column = std::size_t(fx) * m_columnsZ + std::size_t(fz);
  return true;
}

bool SurfaceInside::contains(const Vec3& p) const {
  std::size_t column = 0;
  if (!columnOf(p.x(), p.z(), column)) return false;  // beyond the surface's footprint (or not finite)
  const Real layer = std::floor((p.y() - m_minY) / m_columnSize);
  if (!(layer >= 0)) return false;  // below the surface (or not finite)
  if (layer < Real(m_cubesY)) {
    const CubeState state = m_cubes[column * m_cubesY + std::size_t(layer)];
    if (state != CubeState::Crossed) return state == CubeState::Inside;
  }
  return columnTest(p, column);
}

bool SurfaceInside::columnTest(const Vec3& p, std::size_t column) const {
  bool inside = false;
  for (Index k = m_columnStart[column]; k < m_columnStart[column + 1]; ++k) {
    const Triangle& t = m_triangles[m_items[k]];
    if (crossesUpwardRay(m_vertices[t[0]], m_vertices[t[1]], m_vertices[t[2]], p)) inside = !inside;
  }
  return inside;
}

}  // namespace hs::pbd
