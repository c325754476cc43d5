#pragma once
// ParaView output: one VTK XML UnstructuredGrid (.vtu, ASCII) per frame, tied into a time
// series by a .pvd collection. readVtu reads back what writeVtu writes (round-trip tests).
#include <filesystem>
#include <string>
#include <vector>

#include "pbd/core/tet_mesh.h"

namespace hs::io {

using pbd::Real;
using pbd::Vec3;

struct VtuFrame {
  std::vector<Vec3> points;
  std::vector<pbd::Tet> tets;
  // Point data arrays: scalar ints and 3-vectors, by name.
  std::vector<std::pair<std::string, std::vector<int>>> intArrays;
  std::vector<std::pair<std::string, std::vector<Vec3>>> vectorArrays;
};

// Throws std::runtime_error("FILE: ...") when the file cannot be written or read.
void writeVtu(const std::filesystem::path& file, const VtuFrame& frame);
VtuFrame readVtu(const std::filesystem::path& file);

// Collects (time, file) pairs and writes the .pvd that ParaView opens as one animation.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvdFile) : m_file(std::move(pvdFile)) {}
  void add(double time, const std::string& relativeFile) { m_entries.emplace_back(time, relativeFile); }
  void write() const;

 private:
  std::filesystem::path m_file;
  std::vector<std::pair<double, std::string>> m_entries;
};

}  // namespace hs::io
