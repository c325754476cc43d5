#pragma once
// The endocardium (and epicardium, where the file has one) of an imported mesh, as the
// cardiac layer's surfaces (cardiac/patient/patient_wall.h).
//  * A surface file (no tets, no markers): all its triangles are the endocardium.
//  * Markers: the endocardium is the group named ENDO or ENDOCARDIUM (any case) or numbered 1,
//    the epicardium EPI or EPICARDIUM or 2 (issue 16's recognised markers; the base, BASE or 3,
//    is not needed: the wall is rebuilt from the surfaces).
// Throws std::invalid_argument with one line naming `file` when no endocardium is found.
#include <optional>
#include <string>

#include "cardiac/patient/patient_wall.h"
#include "cardiac/scenario.h"
#include "io/mesh/mesh_import.h"

namespace hs::io {

struct PatientSurfaces {
  cardiac::Surface endocardium;
  std::optional<cardiac::Surface> epicardium;
};

// Markers chosen by the scenario (model.markers): a group's name (any case) or number; ""
// keeps the recognised names and numbers above.
struct PatientMarkers {
  std::string endocardium, epicardium;
};

PatientSurfaces patientSurfaces(const ImportedMesh& mesh, const std::string& file,
                                const PatientMarkers& markers = {});

// The surfaces a scenario's [model] kind = "mesh" names (its endocardium and epicardium files,
// or its volume mesh), read into patient.endocardiumSurface and epicardiumSurface. Throws
// std::invalid_argument with one line naming the file.
void readPatientModelFiles(cardiac::PatientModelSettings& patient);

}  // namespace hs::io
