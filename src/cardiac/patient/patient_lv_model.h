#pragma once
// A patient's ventricle (cardiac/patient/patient_wall.h) as the simulation's heart (cardiac/anatomy/lv_model.h),
// for [model] kind = "mesh" (issue 16, items 6-7).
//
// The rest of the simulation reads the procedural heart's conventions, so the patient's wall is
// given them: a shell one tet thick (one extrusion layer, whatever the resolution's own layer
// count), its vertices in pairs, endocardial vertex i -> 2i (the cavity side) and its epicardial
// partner -> 2i + 1; the cavity surface the endocardium (facing into the wall) with the two
// annuli's rings ordered so that a fan from a ring's centroid faces out of the cavity, toward
// the base (+y); both layers of a vertex take its AHA segment; the base plate made in a
// truncated ventricle is Region::BasePlate. Nothing is pinned: there are no vessels yet, and
// the wall floats as the contraction pulls it toward its centre.
#include "cardiac/anatomy/lv_model.h"
#include "cardiac/patient/patient_settings.h"
#include "cardiac/patient/patient_wall.h"

namespace hs::cardiac {

// `wall` must have been extruded in one layer (2 endoVertices vertices); std::invalid_argument
// otherwise.
LvModel lvModelFromPatientWall(const PatientWall& wall);

// The wall from the surfaces the scenario reader read (PatientModelSettings), at the
// resolution's edge length in one layer, then lvModelFromPatientWall. `wallThickness` (m) is
// used where no epicardium gives it. Errors are buildPatientWall's one-line
// std::invalid_argument, naming `patient`'s file.
LvModel buildPatientLvModel(const PatientModelSettings& patient, Real wallThickness);
// The one-layer wall buildPatientLvModel turns into the model (its placement ties a recorded
// beat to the wall, recorded_beat.h).
PatientWall buildPatientShell(const PatientModelSettings& patient, Real wallThickness);

// The file that names a patient heart in errors: the endocardium's or the volume mesh's.
const std::string& patientModelFile(const PatientModelSettings& patient);

}  // namespace hs::cardiac
