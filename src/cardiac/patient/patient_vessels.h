#pragma once
// The inflow and outflow vessels of a patient's ventricle (issue 16, item 2: "attach the inflow
// and outflow paths there as the procedural heart has them"), so blood can enter and leave it.
//
// Each vessel rises along +y from its annulus ring (the ring's endocardial vertices, shared, so
// the vessel moves with the wall): its lumen blends from the ring's own shape to a circle of the
// orifice's radius (the disc of the ring's cap area) over the first layers, then runs straight to
// its far end, whose ring is pinned as the procedural vessels' are. Its wall, `wallThickness`
// thick, grows from nothing at the annulus (a wedge on the ring's edge) to its full thickness at
// the first layer, so the lumen's surface continues the endocardium's without a step.
//
// Above the annuli the flow path is the procedural one's (vertical circular lumens, flow_path.h);
// below them the ventricle is the patient's cavity: FlowPath::cavity, inside the mid-wall surface
// (each endocardial vertex halfway to its epicardial partner), replaces the spheroid. The valves
// lie in the rings' own planes (FlowPath::mitralValve / aorticValve), not across the vessels: a
// ring may be tilted against the vertical vessel, and a horizontal valve would wall off part of
// the cavity under its high side and let blood by beside it.
#include "cardiac/anatomy/lv_model.h"

namespace hs::cardiac {

struct PatientVesselSizes {
  Real inflowLength = Real(0.03);    // (m) above the mitral annulus's mean height
  Real outflowLength = Real(0.03);   // (m) above the aortic annulus's mean height
  Real wallThickness = Real(0.002);  // (m) the vessels' walls
  Real edge = Real(0.005);           // (m) the layers' height: the wall's edge length
};

// Appends both vessels to `model` (a patient's, lvModelFromPatientWall), pins their far rings,
// lists their other vertices in model.vesselFollowers (layer k of K on ring vertex j: share 1 - k/K),
// labels their vertices Region::InflowVessel / OutflowVessel, recomputes model.surface and sets
// the flow path (far ends, valve discs, the patient cavity) and model.params' vessel sizes.
// std::invalid_argument with a one-line reason when the vessels would overlap each other or a
// tet comes out inverted.
void attachPatientVessels(LvModel& model, const PatientVesselSizes& sizes);

}  // namespace hs::cardiac
