#pragma once
// `heartsim mesh FILE --wall`: the wall cardiac::buildPatientWall makes of the file's
// endocardium (and epicardium), as text and JSON.
#include <nlohmann/json.hpp>
#include <string>

#include "cardiac/patient/patient_wall.h"
#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "mesh_command.h"

namespace hs::app {

struct WallReport {
  cardiac::PatientWall wall;
  cardiac::PatientWallSettings settings;
  bool fromEpicardium = false;
  double seconds = 0;  // wall-clock time of buildPatientWall
};

// Throws std::invalid_argument (one line naming the file) for bad options or a surface that
// makes no wall.
WallReport buildWallReport(const io::ImportedMesh& mesh, const io::MeshSummary& summary,
                           const MeshOptions& options);
void printWall(const WallReport& report);
nlohmann::json wallJson(const WallReport& report);

}  // namespace hs::app
