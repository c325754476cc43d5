#pragma once
// A patient's heart from files ([model] kind = "mesh" of a scenario): what the scenario reader
// reads and patient_lv_model.h builds the wall from.
#include <cstdint>
#include <optional>
#include <string>

#include "cardiac/patient/patient_wall.h"

namespace hs::cardiac {

// [model] kind = "mesh": a patient's ventricle from CT/MRI meshes instead of the procedural one
// (docs/patient-meshes.md). The scenario reader resolves the paths against the scenario file's
// folder and reads the surfaces into `endocardiumSurface` / `epicardiumSurface`; the heart is
// built from them (cardiac/patient/patient_lv_model.h). The wall thickness without an epicardium is
// model.wall_thickness (LvGeometryParams::wallThickness).
enum class ModelKind : std::uint8_t { Procedural, Mesh };
struct PatientModelSettings {
  ModelKind kind = ModelKind::Procedural;
  std::string endocardium, epicardium, volumeMesh;  // file paths ("" = not given)
  LengthUnit units = LengthUnit::Millimetre;
  // The file's surface groups, by name or number ("" = the recognised ENDO/EPI/BASE or 1/2/3).
  std::string markerEndocardium, markerEpicardium, markerBase;
  std::string resolution = "default";  // cardiac::wallResolution's names: the edge length
  Vec3 septum = Vec3::Zero();          // toward the septum in the file's frame; zero = found
  int mitralLoop = 0, aorticLoop = 0;  // boundary loop numbers of the annuli; 0 = by size
  // Read from the files by the scenario reader.
  Surface endocardiumSurface;
  std::optional<Surface> epicardiumSurface;
};

}  // namespace hs::cardiac
