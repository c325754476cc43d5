#pragma once
// Everything a run needs, as plain data with physical (SI) units. Scenario files (src/io)
// fill it; the defaults here are the thesis-scale heart-only case.
#include <string>
#include <vector>

#include "cardiac/lv_model.h"

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

enum class TimingMode { Thesis, Physiological };
enum class BeatPattern { Normal, Irregular, Inconsistent };

struct CycleSettings {
  bool enabled = true;
  TimingMode mode = TimingMode::Thesis;
  BeatPattern pattern = BeatPattern::Normal;
  int beats = 0;  // number of beats, then the wall relaxes; 0 = no limit
  // Thesis mode (Algorithms 2-3, Table 5.4).
  int beatingDuration = 8;       // steps per phase
  Real beatingDisplace = Real(0.08);   // m per systolic step
  // Physiological mode.
  Real heartRateBpm = 72;
  Real systolicFraction = Real(0.35);  // share of the cycle spent in systole
  Real contraction = Real(0.3);        // m, total inward displacement of a beating vertex per systole
  // Which vertices beat: the union of these selections. Empty everything = all myocardium.
  std::vector<int> segments;        // AHA segments 1..17
  std::vector<Index> vertices;      // vertex ids
  bool sphereEnabled = false;
  Vec3 sphereCentre = Vec3::Zero();  // m
  Real sphereRadius = 0;             // m
  // Irregular pattern: each diastole is shortened by a random share in [0, irregularity).
  Real irregularity = Real(0.6);
  unsigned seed = 1;
  // Inconsistent pattern: these segments beat with their own rate and phase.
  std::vector<int> inconsistentSegments = {7, 13, 17};
  Real inconsistentRateFactor = Real(0.5);    // beat rate relative to the rest
  Real inconsistentPhaseOffset = Real(0.5);   // fraction of a cycle
};

struct BloodSettings {
  bool enabled = false;
  int particles = 1000;
};

struct OutputSettings {
  bool vtk = false;
  int vtkEvery = 10;  // steps between VTK frames
};

struct Scenario {
  std::string name = "heart-only";
  std::string description;
  SimulationSettings simulation;
  LvGeometryParams geometry;
  TissueSettings tissue;
  CycleSettings cycle;
  BloodSettings blood;
  OutputSettings output;
};

}  // namespace hs::cardiac
