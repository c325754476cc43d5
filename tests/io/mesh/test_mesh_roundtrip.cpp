// Round trips of the mesh readers: one marked tetrahedral box written in every volume format
// reads back with the same vertices, tets, triangles and markers; heartsim's own .vtu writer
// reads back through the import path; surfaces written as OBJ, STL (ASCII and binary), PLY and
// OFF give the same triangles, their shared vertices merged.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "io/mesh/mesh_import.h"
#include "io/output/vtk_writer.h"
#include "mesh_writers.h"

namespace hs::testing {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("heartsim_mesh_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// marker number -> the set of its triangles, as sorted vertex triples.
std::map<int, std::set<std::array<pbd::Index, 3>>> markerTriangles(const std::vector<pbd::Triangle>& triangles,
                                                                  const std::vector<int>& marker) {
  std::map<int, std::set<std::array<pbd::Index, 3>>> out;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    std::array<pbd::Index, 3> sorted = triangles[t];
    std::sort(sorted.begin(), sorted.end());
    out[marker[t]].insert(sorted);
  }
  return out;
}

void expectSameMesh(const io::ImportedMesh& read, const MarkedTetMesh& written, bool names) {
  ASSERT_EQ(read.vertices.size(), written.vertices.size());
  for (std::size_t i = 0; i < read.vertices.size(); ++i) EXPECT_EQ(read.vertices[i], written.vertices[i]) << "vertex " << i;
  EXPECT_EQ(read.tets, written.tets);
  // The same oriented triangles; .msh 4.1 lists them by surface entity, so in another order.
  std::vector<pbd::Triangle> readTriangles = read.triangles, writtenTriangles = written.triangles;
  std::sort(readTriangles.begin(), readTriangles.end());
  std::sort(writtenTriangles.begin(), writtenTriangles.end());
  EXPECT_EQ(readTriangles, writtenTriangles);
  std::vector<int> readMarker(read.triangles.size(), 0);
  ASSERT_EQ(read.markers.size(), 3u);
  for (const io::SurfaceMarker& m : read.markers) {
    for (pbd::Index t : m.triangles) readMarker[t] = m.number;
    EXPECT_EQ(m.name, names ? written.names.at(m.number) : std::string()) << m.number;
  }
  EXPECT_EQ(markerTriangles(read.triangles, readMarker), markerTriangles(written.triangles, written.triangleMarker));
}

TEST(MeshRoundTrip, BoxIsSixPositiveTetsWithTwelveMarkedFaces) {
  const MarkedTetMesh box = boxMesh();
  EXPECT_EQ(box.tets.size(), 6u);
  EXPECT_EQ(box.triangles.size(), 12u);
  double volume = 0;
  for (const pbd::Tet& t : box.tets) volume += double(pbd::signedTetVolume(box.vertices[t[0]], box.vertices[t[1]], box.vertices[t[2]], box.vertices[t[3]]));
  EXPECT_NEAR(volume, 0.03 * 0.02 * 0.01, 1e-10);
  EXPECT_EQ(std::count(box.triangleMarker.begin(), box.triangleMarker.end(), 1), 2);
  EXPECT_EQ(std::count(box.triangleMarker.begin(), box.triangleMarker.end(), 2), 2);
}

TEST(MeshRoundTrip, SameBoxFromEveryVolumeFormat) {
  const MarkedTetMesh box = boxMesh();
  const fs::path dir = scratch("formats");
  writeMsh22(dir / "box22.msh", box);
  writeMsh41(dir / "box41.msh", box);
  writeVtuFile(dir / "ascii.vtu", box, false);
  writeVtuFile(dir / "binary.VTU", box, true);  // the extension in any case
  writeLegacyVtk(dir / "classic.vtk", box, false);
  writeLegacyVtk(dir / "v5.vtk", box, true);
  writeTetgen(dir / "box", box);
  const std::vector<std::pair<std::string, std::string>> files = {
      {"box22.msh", "gmsh 2.2 ascii"}, {"box41.msh", "gmsh 4.1 ascii"}, {"ascii.vtu", "vtu ascii"},
      {"binary.VTU", "vtu binary"},    {"classic.vtk", "vtk legacy ascii"}, {"v5.vtk", "vtk legacy ascii"},
      {"box.node", "tetgen"},          {"box.ele", "tetgen"},               {"box.face", "tetgen"}};
  for (const auto& [file, format] : files) {
    SCOPED_TRACE(file);
    const io::ImportedMesh mesh = io::readMesh(dir / file);
    EXPECT_EQ(mesh.format, format);
    expectSameMesh(mesh, box, file.ends_with(".msh"));
  }
}

TEST(MeshRoundTrip, TetgenWithoutFaceFileHasNoTriangles) {
  const MarkedTetMesh box = boxMesh();
  const fs::path dir = scratch("noface");
  writeTetgen(dir / "box", box);
  fs::remove(dir / "box.face");
  const io::ImportedMesh mesh = io::readMesh(dir / "box.node");
  EXPECT_EQ(mesh.tets, box.tets);
  EXPECT_TRUE(mesh.triangles.empty());
  EXPECT_TRUE(mesh.markers.empty());
}

TEST(MeshRoundTrip, HeartsimVtuWriterReadsBack) {
  io::VtuFrame frame;
  const MarkedTetMesh box = boxMesh();
  frame.points = box.vertices;
  frame.tets = box.tets;
  frame.intArrays.emplace_back("region", std::vector<int>(box.vertices.size(), 4));
  const fs::path file = scratch("writer") / "frame.vtu";
  io::writeVtu(file, frame);
  const io::ImportedMesh mesh = io::readMesh(file);
  EXPECT_EQ(mesh.tets, box.tets);
  ASSERT_EQ(mesh.vertices.size(), box.vertices.size());
  for (std::size_t i = 0; i < box.vertices.size(); ++i) EXPECT_EQ(mesh.vertices[i], box.vertices[i]);
  EXPECT_TRUE(mesh.triangles.empty());
}

// The box's closed surface (12 triangles, 8 shared vertices) in each surface format.
void writeSurfaces(const fs::path& dir, const MarkedTetMesh& box) {
  std::ofstream obj = openText(dir / "box.obj");
  for (const pbd::Vec3& v : box.vertices) obj << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (int group = 1; group <= 3; ++group) {
    obj << "g " << box.names.at(group) << '\n';
    for (std::size_t t = 0; t < box.triangles.size(); ++t)
      if (box.triangleMarker[t] == group)
        obj << "f " << box.triangles[t][0] + 1 << ' ' << box.triangles[t][1] + 1 << ' ' << box.triangles[t][2] + 1 << '\n';
  }
  std::ofstream off = openText(dir / "box.off");
  off << "OFF\n" << box.vertices.size() << ' ' << box.triangles.size() << " 0\n";
  for (const pbd::Vec3& v : box.vertices) off << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const pbd::Triangle& t : box.triangles) off << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  std::ofstream ply = openText(dir / "box.ply");
  ply << "ply\nformat ascii 1.0\nelement vertex " << box.vertices.size() << "\nproperty float x\nproperty float y\n"
      << "property float z\nelement face " << box.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const pbd::Vec3& v : box.vertices) ply << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const pbd::Triangle& t : box.triangles) ply << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  // STL: every triangle with its own three corners, in ASCII and in binary (80-byte header,
  // count, then normal, corners and attribute per triangle).
  std::ofstream stl = openText(dir / "ascii.stl");
  stl << "solid box\n";
  for (const pbd::Triangle& t : box.triangles) {
    stl << "facet normal 0 0 0\nouter loop\n";
    for (pbd::Index i : t) stl << "vertex " << box.vertices[i].x() << ' ' << box.vertices[i].y() << ' ' << box.vertices[i].z() << '\n';
    stl << "endloop\nendfacet\n";
  }
  stl << "endsolid box\n";
  std::ofstream binary(dir / "binary.stl", std::ios::binary);
  const std::string header(80, ' ');
  binary.write(header.data(), 80);
  const auto count = std::uint32_t(box.triangles.size());
  binary.write(reinterpret_cast<const char*>(&count), 4);
  for (const pbd::Triangle& t : box.triangles) {
    float values[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) values[3 + 3 * k + c] = float(box.vertices[t[std::size_t(k)]][c]);
    binary.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attribute = 0;
    binary.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

// The same triangles as positions: the readers may number the vertices in another order.
std::multiset<std::array<float, 9>> trianglePositions(const std::vector<pbd::Vec3>& v, const std::vector<pbd::Triangle>& triangles) {
  std::multiset<std::array<float, 9>> out;
  for (const pbd::Triangle& t : triangles) {
    // Rotated so the smallest corner comes first: the same cycle (same orientation) compares equal.
    std::array<std::array<float, 3>, 3> corners;
    for (int k = 0; k < 3; ++k) corners[std::size_t(k)] = {float(v[t[std::size_t(k)]].x()), float(v[t[std::size_t(k)]].y()), float(v[t[std::size_t(k)]].z())};
    const auto first = std::min_element(corners.begin(), corners.end()) - corners.begin();
    std::array<float, 9> key;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) key[std::size_t(3 * k + c)] = corners[std::size_t((first + k) % 3)][std::size_t(c)];
    out.insert(key);
  }
  return out;
}

TEST(MeshRoundTrip, SurfaceFormatsGiveTheSameTrianglesAndMergedVertices) {
  const MarkedTetMesh box = boxMesh();
  const fs::path dir = scratch("surfaces");
  writeSurfaces(dir, box);
  const auto expected = trianglePositions(box.vertices, box.triangles);
  for (const std::string file : {"box.obj", "box.off", "box.ply", "ascii.stl", "binary.stl"}) {
    SCOPED_TRACE(file);
    const io::ImportedMesh mesh = io::readMesh(dir / file);
    EXPECT_EQ(mesh.vertices.size(), 8u);  // an STL's 36 corners merged to the 8 shared ones
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_TRUE(mesh.tets.empty());
    EXPECT_EQ(trianglePositions(mesh.vertices, mesh.triangles), expected);
    EXPECT_TRUE(pbd::checkSurface(mesh.triangles).closed);
  }
}

TEST(MeshRoundTrip, ObjGroupsBecomeNamedMarkers) {
  const MarkedTetMesh box = boxMesh();
  const fs::path dir = scratch("groups");
  writeSurfaces(dir, box);
  const io::ImportedMesh mesh = io::readMesh(dir / "box.obj");
  ASSERT_EQ(mesh.markers.size(), 3u);
  std::map<std::string, std::size_t> counts;
  for (const io::SurfaceMarker& m : mesh.markers) {
    EXPECT_EQ(m.number, -1);
    counts[m.name] = m.triangles.size();
  }
  EXPECT_EQ(counts, (std::map<std::string, std::size_t>{{"BASE", 2}, {"SIDE", 8}, {"TOP", 2}}));
  // The OFF, PLY and STL files have no groups.
  EXPECT_TRUE(io::readMesh(dir / "box.off").markers.empty());
}

}  // namespace
}  // namespace hs::testing
