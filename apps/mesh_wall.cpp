#include "mesh_wall.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cardiac/anatomy/aha_segments.h"
#include "io/mesh/patient_surfaces.h"

namespace hs::app {
namespace {

[[noreturn]] void bad(const std::string& file, const std::string& what) {
  throw std::invalid_argument(file + ": " + what);
}

double parseNumber(const std::string& text, const std::string& file, const std::string& what) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(v)) bad(file, what + ", got '" + text + "'");
  return v;
}

Eigen::Vector3d parseDirection(const std::string& text, const std::string& file) {
  Eigen::Vector3d d;
  std::istringstream in(text);
  std::string part;
  int k = 0;
  while (std::getline(in, part, ',')) {
    if (k == 3) bad(file, "--septum '" + text + "': expected three numbers x,y,z");
    d[k++] = parseNumber(part, file, "--septum '" + text + "': expected three numbers x,y,z");
  }
  if (k != 3 || d.norm() == 0)
    bad(file, "--septum '" + text + "': expected three numbers x,y,z, not all zero");
  return d;
}

double mm(double metres) { return metres * 1e3; }

}  // namespace

WallReport buildWallReport(const io::ImportedMesh& mesh, const io::MeshSummary& summary,
                           const MeshOptions& options) {
  const std::string& file = options.file;
  WallReport r;
  cardiac::PatientWallSettings& s = r.settings;
  s.file = file;
  const std::string unit = options.units.empty() ? summary.unitGuess : options.units;
  if (unit == "mm")
    s.units = cardiac::LengthUnit::Millimetre;
  else if (unit == "m")
    s.units = cardiac::LengthUnit::Metre;
  else if (options.units.empty()) {
    std::ostringstream size;
    size << summary.size;
    bad(file, "cannot guess the units from the size " + size.str() + "; expected --units mm or --units m");
  } else
    bad(file, "--units '" + options.units + "': expected mm or m");
  if (!options.thickness.empty()) {
    s.wallThickness =
        parseNumber(options.thickness, file, "--thickness: expected a wall thickness in m, e.g. 0.010");
    if (!(s.wallThickness >= 0.002 && s.wallThickness <= 0.03))
      bad(file, "--thickness " + options.thickness + ": expected a wall thickness in m within [0.002, 0.03]");
  }
  try {
    s.resolution = cardiac::wallResolution(options.resolution);
  } catch (const std::invalid_argument& e) {
    bad(file, std::string("--") + e.what());
  }
  if (!options.septum.empty()) s.septum = parseDirection(options.septum, file);
  s.mitralLoop = options.mitralLoop;
  s.aorticLoop = options.aorticLoop;
  const io::PatientSurfaces surfaces = io::patientSurfaces(mesh, file);
  std::optional<cardiac::Surface> epicardium = surfaces.epicardium;
  if (!options.epicardium.empty()) {
    const io::ImportedMesh epiMesh = io::readMesh(options.epicardium);
    epicardium = cardiac::Surface{epiMesh.vertices, epiMesh.triangles};
  }
  const auto start = std::chrono::steady_clock::now();
  r.wall = cardiac::buildPatientWall(surfaces.endocardium, epicardium ? &*epicardium : nullptr, s);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.fromEpicardium = r.wall.thicknessFromEpicardium;
  return r;
}

void printWall(const WallReport& r) {
  const cardiac::PatientWall& w = r.wall;
  const cardiac::WallResolution& res = r.settings.resolution;
  const Eigen::Vector3d septum = w.frame.rotation.transpose() * cardiac::kSeptal;  // in the file's frame
  std::cout << std::setprecision(6) << "  wall: " << mm(res.edgeLength) << " mm edges, " << res.layers
            << " layer" << (res.layers == 1 ? "" : "s") << ", "
            << (r.fromEpicardium ? std::string("up to the epicardium")
                                 : "thickness " + std::to_string(mm(r.settings.wallThickness)) + " mm")
            << '\n'
            << "    vertices " << w.mesh.vertices.size() << " (endocardium " << w.endoVertices
            << "), tetrahedra " << w.mesh.tets.size() << '\n'
            << "    worst tetrahedron: smallest dihedral angle " << w.quality.minDihedralDeg
            << " deg, largest aspect ratio " << w.quality.maxAspectRatio << ", inverted "
            << w.quality.invertedTets << '\n';
  if (w.shrunkVertices > 0)
    std::cout << "    thinner at " << w.shrunkVertices << " vertices (the wall would have crossed itself)\n";
  std::cout << "    annuli: " << (w.baseOpened ? "opened in the flat base: " : "") << "mitral "
            << w.mitralRing.size() << " vertices, aortic " << w.aorticRing.size() << " vertices\n"
            << "    cavity: length " << mm(w.cavityLength) << " mm (base plane to apex), volume "
            << w.cavityVolume * 1e6 << " mL with the annuli closed flat\n"
            << "    long axis (file frame, base-ward) (" << w.frame.rotation(1, 0) << ", "
            << w.frame.rotation(1, 1) << ", " << w.frame.rotation(1, 2) << "), septum toward ("
            << septum.x() << ", " << septum.y() << ", " << septum.z() << ") from the " << w.septumFrom << '\n'
            << "    built in " << std::setprecision(3) << r.seconds << " s\n";
}

nlohmann::json wallJson(const WallReport& r) {
  const cardiac::PatientWall& w = r.wall;
  nlohmann::json j;
  j["edge_length"] = r.settings.resolution.edgeLength;
  j["layers"] = r.settings.resolution.layers;
  j["thickness"] = r.fromEpicardium ? nlohmann::json("epicardium") : nlohmann::json(r.settings.wallThickness);
  j["vertices"] = w.mesh.vertices.size();
  j["endocardial_vertices"] = w.endoVertices;
  j["tets"] = w.mesh.tets.size();
  j["min_dihedral_deg"] = w.quality.minDihedralDeg;
  j["max_aspect_ratio"] = w.quality.maxAspectRatio;
  j["inverted_tets"] = w.quality.invertedTets;
  j["thinned_vertices"] = w.shrunkVertices;
  j["base_opened"] = w.baseOpened;
  j["mitral_ring_vertices"] = w.mitralRing.size();
  j["aortic_ring_vertices"] = w.aorticRing.size();
  j["cavity_length"] = w.cavityLength;
  j["cavity_volume_ml"] = w.cavityVolume * 1e6;
  const Eigen::Matrix3d& R = w.frame.rotation;
  j["long_axis"] = {R(1, 0), R(1, 1), R(1, 2)};
  const Eigen::Vector3d septum = R.transpose() * cardiac::kSeptal;  // the frame's septal axis in the file
  j["septum"] = {septum.x(), septum.y(), septum.z()};
  j["septum_from"] = w.septumFrom;
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace hs::app
