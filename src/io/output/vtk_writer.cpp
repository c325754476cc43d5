#include "io/output/vtk_writer.h"

#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hs::io {
namespace {

std::ofstream openForWrite(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file.string() + ": cannot open for writing");
  out << std::setprecision(9);
  return out;
}

void checkWritten(std::ofstream& out, const std::filesystem::path& file) {
  out.flush();
  if (!out) throw std::runtime_error(file.string() + ": write failed (disk full?)");
}

// Reads the whitespace-separated numbers between the next "<DataArray ... Name=\"name\"" tag
// (or the next DataArray when name is empty) and its closing tag.
std::istringstream dataArrayBody(const std::string& text, std::size_t& cursor,
                                 std::string& nameOut, const std::filesystem::path& file) {
  const std::size_t tag = text.find("<DataArray", cursor);
  if (tag == std::string::npos) throw std::runtime_error(file.string() + ": missing DataArray");
  const std::size_t tagEnd = text.find('>', tag);
  const std::size_t close = text.find("</DataArray>", tagEnd);
  if (tagEnd == std::string::npos || close == std::string::npos)
    throw std::runtime_error(file.string() + ": unterminated DataArray");
  const std::string header = text.substr(tag, tagEnd - tag);
  const std::size_t namePos = header.find("Name=\"");
  nameOut = namePos == std::string::npos
                ? std::string()
                : header.substr(namePos + 6, header.find('"', namePos + 6) - namePos - 6);
  cursor = close + 12;
  return std::istringstream(text.substr(tagEnd + 1, close - tagEnd - 1));
}

}  // namespace

void writeVtu(const std::filesystem::path& file, const VtuFrame& frame) {
  std::ofstream out = openForWrite(file);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << frame.points.size()
      << "\" NumberOfCells=\"" << frame.tets.size() << "\">\n<PointData>\n";
  for (const auto& [name, values] : frame.intArrays) {
    out << "<DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (int v : values) out << v << '\n';
    out << "</DataArray>\n";
  }
  for (const auto& [name, values] : frame.vectorArrays) {
    out << "<DataArray type=\"Float64\" Name=\"" << name
        << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Vec3& v : values) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    out << "</DataArray>\n";
  }
  out << "</PointData>\n<Points>\n"
      << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : frame.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const pbd::Tet& t : frame.tets) out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < frame.tets.size(); ++i) out << 4 * (i + 1) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < frame.tets.size(); ++i) out << "10\n";  // VTK_TETRA
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  checkWritten(out, file);
}

VtuFrame readVtu(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open for reading");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  VtuFrame frame;
  std::size_t cursor = text.find("<PointData>");
  const std::size_t pointsTag = text.find("<Points>");
  if (cursor == std::string::npos || pointsTag == std::string::npos)
    throw std::runtime_error(file.string() + ": not a heartsim .vtu file");
  std::string name;
  while (true) {
    const std::size_t next = text.find("<DataArray", cursor);
    if (next == std::string::npos || next > pointsTag) break;
    const bool isVector = text.substr(next, text.find('>', next) - next).find("NumberOfComponents") != std::string::npos;
    std::istringstream body = dataArrayBody(text, cursor, name, file);
    if (isVector) {
      std::vector<Vec3> values;
      double x, y, z;
      while (body >> x >> y >> z) values.emplace_back(Real(x), Real(y), Real(z));
      frame.vectorArrays.emplace_back(name, std::move(values));
    } else {
      std::vector<int> values;
      int v;
      while (body >> v) values.push_back(v);
      frame.intArrays.emplace_back(name, std::move(values));
    }
  }
  cursor = pointsTag;
  {
    std::istringstream body = dataArrayBody(text, cursor, name, file);
    double x, y, z;
    while (body >> x >> y >> z) frame.points.emplace_back(Real(x), Real(y), Real(z));
  }
  {
    std::istringstream body = dataArrayBody(text, cursor, name, file);
    pbd::Index a, b, c, d;
    while (body >> a >> b >> c >> d) frame.tets.push_back({a, b, c, d});
  }
  return frame;
}

void PvdSeries::write() const {
  std::ofstream out = openForWrite(m_file);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [time, name] : m_entries)
    out << "<DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << name << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  checkWritten(out, m_file);
}

}  // namespace hs::io
