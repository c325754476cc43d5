#pragma once
// The endocardium (and epicardium, where the file has one) of an imported mesh, as the
// cardiac layer's surfaces (cardiac/patient_wall.h).
//  * A surface file (no tets, no markers): all its triangles are the endocardium.
//  * Markers: the endocardium is the group named ENDO or ENDOCARDIUM (any case) or numbered 1,
//    the epicardium EPI or EPICARDIUM or 2 (issue 16's recognised markers; the base, BASE or 3,
//    is not needed: the wall is rebuilt from the surfaces).
// Throws std::invalid_argument with one line naming `file` when no endocardium is found.
#include <optional>
#include <string>

#include "cardiac/patient_wall.h"
#include "io/mesh_import.h"

namespace hs::io {

struct PatientSurfaces {
  cardiac::Surface endocardium;
  std::optional<cardiac::Surface> epicardium;
};

PatientSurfaces patientSurfaces(const ImportedMesh& mesh, const std::string& file);

}  // namespace hs::io
