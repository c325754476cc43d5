#include "io/mesh/patient_surfaces.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "mesh/surface_mesh.h"

namespace hs::io {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A chosen marker: its name (any case), or its number when `chosen` is a whole number.
const SurfaceMarker* findChosenMarker(const ImportedMesh& mesh, const std::string& chosen, const std::string& file,
                                      const std::string& role) {
  for (const SurfaceMarker& m : mesh.markers)
    if (!m.name.empty() && lower(m.name) == lower(chosen)) return &m;
  const bool whole = !chosen.empty() && std::all_of(chosen.begin(), chosen.end(), [](unsigned char c) {
    return std::isdigit(c) != 0;
  }) && chosen.size() < 10;
  if (whole)
    for (const SurfaceMarker& m : mesh.markers)
      if (m.number == std::stoi(chosen)) return &m;
  std::string found;
  for (const SurfaceMarker& m : mesh.markers)
    found += (found.empty() ? "" : ", ") + (m.name.empty() ? std::to_string(m.number) : m.name);
  throw std::invalid_argument(file + ": no surface group '" + chosen + "' for the " + role + "; expected one of " +
                              (found.empty() ? std::string("(the file has none)") : found));
}

const SurfaceMarker* findMarker(const ImportedMesh& mesh, const std::string& shortName,
                                const std::string& longName, int number) {
  for (const SurfaceMarker& m : mesh.markers)
    if (lower(m.name) == shortName || lower(m.name) == longName) return &m;
  for (const SurfaceMarker& m : mesh.markers)
    if (m.name.empty() && m.number == number) return &m;
  return nullptr;
}

cardiac::Surface surfaceOf(const ImportedMesh& mesh, const std::vector<pbd::Index>& triangles) {
  const pbd::SubSurface sub = pbd::extractSubSurface(mesh.vertices, mesh.triangles, triangles);
  return {sub.vertices, sub.triangles};
}

}  // namespace

PatientSurfaces patientSurfaces(const ImportedMesh& mesh, const std::string& file, const PatientMarkers& markers) {
  PatientSurfaces out;
  if (mesh.tets.empty() && mesh.markers.empty()) {
    if (mesh.triangles.empty())
      throw std::invalid_argument(file + ": no triangles; expected an endocardial surface");
    out.endocardium = {mesh.vertices, mesh.triangles};
    return out;
  }
  const SurfaceMarker* endo = markers.endocardium.empty()
                                  ? findMarker(mesh, "endo", "endocardium", 1)
                                  : findChosenMarker(mesh, markers.endocardium, file, "endocardium");
  if (!endo || endo->triangles.empty())
    throw std::invalid_argument(file +
                                ": no endocardium marker; expected a surface group named ENDO or numbered 1");
  out.endocardium = surfaceOf(mesh, endo->triangles);
  const SurfaceMarker* epi = markers.epicardium.empty()
                                 ? findMarker(mesh, "epi", "epicardium", 2)
                                 : findChosenMarker(mesh, markers.epicardium, file, "epicardium");
  if (epi && !epi->triangles.empty())
    out.epicardium = surfaceOf(mesh, epi->triangles);
  return out;
}

void readPatientModelFiles(cardiac::PatientModelSettings& patient) {
  const PatientMarkers markers{patient.markerEndocardium, patient.markerEpicardium};
  const std::string& file = patient.volumeMesh.empty() ? patient.endocardium : patient.volumeMesh;
  PatientSurfaces surfaces = patientSurfaces(readMesh(file), file, markers);
  if (!patient.epicardium.empty()) {
    const ImportedMesh epi = readMesh(patient.epicardium);
    if (epi.triangles.empty())
      throw std::invalid_argument(patient.epicardium + ": no triangles; expected an epicardial surface");
    // An epicardium file is taken whole: all its triangles.
    std::vector<pbd::Index> all(epi.triangles.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = pbd::Index(i);
    surfaces.epicardium = surfaceOf(epi, all);
  }
  patient.endocardiumSurface = std::move(surfaces.endocardium);
  patient.epicardiumSurface = std::move(surfaces.epicardium);
}

}  // namespace hs::io
