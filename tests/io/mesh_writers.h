#pragma once
// Small writers of the mesh formats heartsim reads, for round trips: one tetrahedral mesh with
// marked boundary triangles written as .msh 2.2 and 4.1, .vtu (ascii and base64 binary),
// legacy .vtk (classic and version 5 cells) and TetGen .node/.ele/.face.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/mesh/mesh_import.h"
#include "pbd/core/tet_mesh.h"

namespace hs::testing {

struct MarkedTetMesh {
  std::vector<pbd::Vec3> vertices;
  std::vector<pbd::Tet> tets;
  std::vector<pbd::Triangle> triangles;
  std::vector<int> triangleMarker;  // one per triangle, >= 1
  std::map<int, std::string> names;
};

// A box [0, 0.03] x [0, 0.02] x [0, 0.01] offset by (0.1, -0.2, 0.3), cut into 6 tets around the
// diagonal 0-7 (Kuhn), its 12 boundary triangles marked 1 (z = min), 2 (z = max), 3 (sides).
inline MarkedTetMesh boxMesh() {
  MarkedTetMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(pbd::Real(0.1 + 0.03 * (i & 1)), pbd::Real(-0.2 + 0.02 * ((i >> 1) & 1)),
                            pbd::Real(0.3 + 0.01 * ((i >> 2) & 1)));
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& a : axes) {
    pbd::Tet t{0, pbd::Index(1 << a[0]), pbd::Index((1 << a[0]) | (1 << a[1])), 7};
    if (pbd::signedTetVolume(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]) < 0) std::swap(t[1], t[2]);
    m.tets.push_back(t);
  }
  m.triangles = pbd::boundaryFaces(m.tets);
  for (const pbd::Triangle& f : m.triangles) {
    const bool bottom = ((f[0] | f[1] | f[2]) & 4) == 0, top = (f[0] & f[1] & f[2] & 4) != 0;
    m.triangleMarker.push_back(bottom ? 1 : top ? 2 : 3);
  }
  m.names = {{1, "BASE"}, {2, "TOP"}, {3, "SIDE"}};
  return m;
}

inline std::ofstream openText(const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  out << std::setprecision(9);
  return out;
}

inline void writeMsh22(const std::filesystem::path& file, const MarkedTetMesh& m) {
  std::ofstream out = openText(file);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" << m.names.size() << '\n';
  for (const auto& [tag, name] : m.names) out << "2 " << tag << " \"" << name << "\"\n";
  out << "$EndPhysicalNames\n$Nodes\n" << m.vertices.size() << '\n';
  for (std::size_t i = 0; i < m.vertices.size(); ++i)  // node tags from 101: not the indices
    out << 101 + i << ' ' << m.vertices[i].x() << ' ' << m.vertices[i].y() << ' ' << m.vertices[i].z() << '\n';
  out << "$EndNodes\n$Elements\n" << m.triangles.size() + m.tets.size() << '\n';
  int number = 1;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    out << number++ << " 2 2 " << m.triangleMarker[t] << ' ' << m.triangleMarker[t] << ' ' << 101 + m.triangles[t][0] << ' '
        << 101 + m.triangles[t][1] << ' ' << 101 + m.triangles[t][2] << '\n';
  for (const pbd::Tet& t : m.tets)
    out << number++ << " 4 2 0 1 " << 101 + t[0] << ' ' << 101 + t[1] << ' ' << 101 + t[2] << ' ' << 101 + t[3] << '\n';
  out << "$EndElements\n";
}

inline void writeMsh41(const std::filesystem::path& file, const MarkedTetMesh& m) {
  std::ofstream out = openText(file);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << m.names.size() << '\n';
  for (const auto& [tag, name] : m.names) out << "2 " << tag << " \"" << name << "\"\n";
  // Surface entity s carries physical group s; the volume entity 1 none.
  out << "$EndPhysicalNames\n$Entities\n0 0 3 1\n";
  for (int s = 1; s <= 3; ++s) out << s << " 0 0 0 1 1 1 1 " << s << " 0\n";
  out << "1 0 0 0 1 1 1 0 3 1 2 3\n$EndEntities\n$Nodes\n1 " << m.vertices.size() << " 101 " << 100 + m.vertices.size()
      << "\n3 1 0 " << m.vertices.size() << '\n';
  for (std::size_t i = 0; i < m.vertices.size(); ++i) out << 101 + i << '\n';
  for (const pbd::Vec3& v : m.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  out << "$EndNodes\n$Elements\n4 " << m.triangles.size() + m.tets.size() << " 1 " << m.triangles.size() + m.tets.size() << '\n';
  int number = 1;
  for (int s = 1; s <= 3; ++s) {
    std::vector<std::size_t> mine;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if (m.triangleMarker[t] == s) mine.push_back(t);
    out << "2 " << s << " 2 " << mine.size() << '\n';
    for (std::size_t t : mine)
      out << number++ << ' ' << 101 + m.triangles[t][0] << ' ' << 101 + m.triangles[t][1] << ' ' << 101 + m.triangles[t][2] << '\n';
  }
  out << "3 1 4 " << m.tets.size() << '\n';
  for (const pbd::Tet& t : m.tets)
    out << number++ << ' ' << 101 + t[0] << ' ' << 101 + t[1] << ' ' << 101 + t[2] << ' ' << 101 + t[3] << '\n';
  out << "$EndElements\n";
}

// Cells: the triangles first (type 5, their marker), then the tets (type 10, marker 0).
struct CellLists {
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  std::vector<std::int32_t> markers;
};

inline CellLists cellLists(const MarkedTetMesh& m) {
  CellLists c;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    c.connectivity.insert(c.connectivity.end(), m.triangles[t].begin(), m.triangles[t].end());
    c.offsets.push_back(std::int64_t(c.connectivity.size()));
    c.types.push_back(5);
    c.markers.push_back(m.triangleMarker[t]);
  }
  for (const pbd::Tet& t : m.tets) {
    c.connectivity.insert(c.connectivity.end(), t.begin(), t.end());
    c.offsets.push_back(std::int64_t(c.connectivity.size()));
    c.types.push_back(10);
    c.markers.push_back(0);
  }
  return c;
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) | (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0u) |
                            (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0u);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

// VTK's inline binary: base64 of the UInt32 byte count, then base64 of the values (separately).
template <typename T>
std::string binaryArray(const std::vector<T>& values) {
  const std::uint32_t bytes = std::uint32_t(values.size() * sizeof(T));
  std::vector<std::uint8_t> header(4), data(values.size() * sizeof(T));
  std::memcpy(header.data(), &bytes, 4);
  if (!values.empty()) std::memcpy(data.data(), values.data(), data.size());
  return base64(header) + base64(data);
}

template <typename T>
std::string asciiArray(const std::vector<T>& values) {
  std::ostringstream s;
  s << std::setprecision(9);
  for (const T& v : values) s << +v << ' ';
  return s.str();
}

inline void writeVtuFile(const std::filesystem::path& file, const MarkedTetMesh& m, bool binary) {
  const CellLists c = cellLists(m);
  std::vector<float> points;
  for (const pbd::Vec3& v : m.vertices) points.insert(points.end(), {float(v.x()), float(v.y()), float(v.z())});
  const char* format = binary ? "binary" : "ascii";
  auto array = [&](const auto& values) { return binary ? binaryArray(values) : asciiArray(values); };
  std::ofstream out = openText(file);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << m.vertices.size() << "\" NumberOfCells=\"" << c.types.size()
      << "\">\n      <Points>\n        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"" << format << "\">\n"
      << array(points) << "\n        </DataArray>\n      </Points>\n      <Cells>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"" << format << "\">" << array(c.connectivity)
      << "</DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"" << format << "\">" << array(c.offsets)
      << "</DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"" << format << "\">" << array(c.types)
      << "</DataArray>\n      </Cells>\n      <CellData>\n        <DataArray type=\"Int32\" Name=\"CellEntityIds\" format=\""
      << format << "\">" << array(c.markers) << "</DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

// Legacy ASCII; `version5`: the CELLS block as OFFSETS and CONNECTIVITY (VTK 9's writer).
inline void writeLegacyVtk(const std::filesystem::path& file, const MarkedTetMesh& m, bool version5) {
  const CellLists c = cellLists(m);
  std::ofstream out = openText(file);
  out << "# vtk DataFile Version " << (version5 ? "5.1" : "4.2") << "\nbox\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      << "FIELD FieldData 1\nTIME 1 1 double\n0\nPOINTS " << m.vertices.size() << " float\n";
  for (const pbd::Vec3& v : m.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  if (version5) {
    out << "CELLS " << c.types.size() + 1 << ' ' << c.connectivity.size() << "\nOFFSETS vtktypeint64\n0 "
        << asciiArray(c.offsets) << "\nCONNECTIVITY vtktypeint64\n" << asciiArray(c.connectivity) << '\n';
  } else {
    out << "CELLS " << c.types.size() << ' ' << c.connectivity.size() + c.types.size() << '\n';
    std::int64_t begin = 0;
    for (std::int64_t end : c.offsets) {
      out << end - begin;
      for (std::int64_t i = begin; i < end; ++i) out << ' ' << c.connectivity[std::size_t(i)];
      out << '\n';
      begin = end;
    }
  }
  out << "CELL_TYPES " << c.types.size() << '\n' << asciiArray(c.types) << "\nPOINT_DATA " << m.vertices.size()
      << "\nVECTORS velocity float\n";
  for (std::size_t i = 0; i < m.vertices.size(); ++i) out << "0 0 1\n";
  out << "CELL_DATA " << c.types.size() << "\nSCALARS quality float 1\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < c.types.size(); ++i) out << 0.5 + double(i) << '\n';  // not whole: no marker
  out << "SCALARS gmsh:physical int 1\nLOOKUP_TABLE default\n" << asciiArray(c.markers) << '\n';
}

// TetGen, 1-based, with comments.
inline void writeTetgen(const std::filesystem::path& stem, const MarkedTetMesh& m) {
  std::ofstream node = openText(std::filesystem::path(stem).concat(".node"));
  node << "# box\n" << m.vertices.size() << " 3 0 0\n";
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    node << i + 1 << "  " << m.vertices[i].x() << ' ' << m.vertices[i].y() << ' ' << m.vertices[i].z() << "  # point\n";
  std::ofstream ele = openText(std::filesystem::path(stem).concat(".ele"));
  ele << m.tets.size() << " 4 1\n";
  for (std::size_t i = 0; i < m.tets.size(); ++i)
    ele << i + 1 << ' ' << m.tets[i][0] + 1 << ' ' << m.tets[i][1] + 1 << ' ' << m.tets[i][2] + 1 << ' ' << m.tets[i][3] + 1 << " 7\n";
  std::ofstream face = openText(std::filesystem::path(stem).concat(".face"));
  face << m.triangles.size() << " 1\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    face << i + 1 << ' ' << m.triangles[i][0] + 1 << ' ' << m.triangles[i][1] + 1 << ' ' << m.triangles[i][2] + 1 << ' '
         << m.triangleMarker[i] << '\n';
}

}  // namespace hs::testing
