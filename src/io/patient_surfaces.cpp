#include "io/patient_surfaces.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "pbd/surface_mesh.h"

namespace hs::io {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
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

PatientSurfaces patientSurfaces(const ImportedMesh& mesh, const std::string& file) {
  PatientSurfaces out;
  if (mesh.tets.empty() && mesh.markers.empty()) {
    if (mesh.triangles.empty())
      throw std::invalid_argument(file + ": no triangles; expected an endocardial surface");
    out.endocardium = {mesh.vertices, mesh.triangles};
    return out;
  }
  const SurfaceMarker* endo = findMarker(mesh, "endo", "endocardium", 1);
  if (!endo || endo->triangles.empty())
    throw std::invalid_argument(file +
                                ": no endocardium marker; expected a surface group named ENDO or numbered 1");
  out.endocardium = surfaceOf(mesh, endo->triangles);
  if (const SurfaceMarker* epi = findMarker(mesh, "epi", "epicardium", 2); epi && !epi->triangles.empty())
    out.epicardium = surfaceOf(mesh, epi->triangles);
  return out;
}

}  // namespace hs::io
