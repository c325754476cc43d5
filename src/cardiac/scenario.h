#pragma once
// Everything a run needs, as plain data with physical (SI) units. Scenario files (src/io)
// fill it; the defaults here are the thesis-scale heart-only case.
#include <optional>
#include <string>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/blood_settings.h"
#include "cardiac/circulation/clinical_units.h"
#include "cardiac/circulation/lumped_circulation.h"
#include "cardiac/circulation/valves.h"
#include "cardiac/motion/cycle_settings.h"
#include "cardiac/motion/volume_driven_wall.h"
#include "cardiac/patient/patient_settings.h"
#include "cardiac/patient/patient_wall.h"

namespace hs::cardiac {

struct SimulationSettings {
  Real dt = Real(0.005);        // s (thesis section 5.1)
  Real duration = Real(2.0);    // s (thesis Table 5.5 runs)
  int iterations = 3;     // solver iterations per step (thesis Algorithm 1, solverIterations)
  int volumePasses = 3;   // extra sweeps of the wall's volume constraints after the iterations
  Vec3 gravity = Vec3(0, Real(-9.81), 0);  // m/s^2 (thesis Table 5.3)
};

struct TissueSettings {
  // PBD stiffness k in [0, 1] of the wall's area and edge constraints (thesis Table 5.3: 0.5).
  Real stiffness = Real(0.5);
  // PBD stiffness of the tet volume constraints. Myocardium is nearly incompressible, so
  // volume is held fully (1) while the shape constraints use the thesis's k.
  Real volumeStiffness = Real(1.0);
  // XPBD compliances alpha (inverse stiffness, units C^2/J): volume m^3/Pa, area m^3/N,
  // edge m/N. 0 = plain PBD (thesis), where the stiffness k alone sets the response.
  Real volumeCompliance = 0;
  Real areaCompliance = 0;
  Real edgeCompliance = 0;
  bool edges = true;       // edge distance constraints (volume and area alone do not hold a shape)
  bool areas = true;       // surface triangle area constraints (thesis 4.1.2)
  // Whether gravity acts on the wall. In the body the heart's weight is carried by the
  // pericardium and the great vessels, so by default only the blood feels gravity.
  bool gravity = false;
  // 1/s, velocity damping of the wall: myocardium is viscoelastic, and without it the
  // released wall would ring around its rest shape instead of settling (cardiac-cycle.md).
  Real damping = Real(20);
  Real density = 1060;     // kg/m^3, gives vertex masses from tet volumes
};

// The blood's path through the heart (circulation.h): valves, filling pressure, closed loop.
struct CirculationSettings {
  ValveMode valveMode = ValveMode::Timing;
  bool loop = true;               // blood leaving a vessel's far end re-enters the inflow vessel
  Real atrialPressureMmHg = 0;    // filling pressure driving the inflow vessel (mmHg)
  bool twoWay = false;            // blood pushes the wall back (two-way coupling)
  bool wallSlip = false;          // blood slides along the wall (push-out along the face normal)
  // The lumped circulation (lumped_circulation.h) drives the wall: the cavity follows its
  // ventricle's volume, the valves its valves, and it gives the pressures. Physiological
  // cycles only. The atrial pressure above is its preload (the pulmonary veins' pressure);
  // the orifice areas come from the model (mitral and aortic radius) unless the aortic valve's
  // own area is set (stenosis).
  bool lumped = false;
  LumpedParameters lumpedParameters;
  Real aorticValveArea = 0;       // m^2, 0 = the aortic vessel's lumen
  bool atrialContraction = true;  // false: no A wave (atrial fibrillation)
  WallMotionSettings wallMotion;
};

// A recorded beat ([motion], issue 16 item 5): a sequence of endocardial surfaces over one beat,
// each with the vertices and triangles of the model's endocardium file (cine MRI, e.g. 25
// frames), replayed periodically: the wall's inner surface follows them (recorded_beat.h).
struct MotionSettings {
  std::string frames;  // path pattern with {frame} or {frame:0Nd}; "" = no recorded beat
  int count = 0;       // frames in the beat, frame 0 at end-diastole
  Real period = 0;     // s, the beat's length
  // Read by the scenario reader, in the file's frame and units, frame 0 first.
  std::vector<Surface> frameSurfaces;
};

struct OutputSettings {
  bool vtk = false;
  int vtkEvery = 10;  // steps between VTK frames
};

struct Scenario {
  std::string name = "heart-only";
  std::string description;
  SimulationSettings simulation;
  bool heart = true;  // model.enabled: the LV wall exists (false: blood in a container only)
  LvGeometryParams geometry;
  PatientModelSettings patient;
  MotionSettings motion;
  TissueSettings tissue;
  CycleSettings cycle;
  BloodSettings blood;
  ContainerSettings container;
  CirculationSettings circulation;
  OutputSettings output;
};

}  // namespace hs::cardiac
