#pragma once
// Everything a run needs, as plain data with physical (SI) units. Scenario files (src/io)
// fill it; the defaults here are the thesis-scale heart-only case.
#include <optional>
#include <string>
#include <vector>

#include "cardiac/clinical_units.h"
#include "cardiac/lumped_circulation.h"
#include "cardiac/lv_model.h"
#include "cardiac/patient_wall.h"
#include "cardiac/volume_driven_wall.h"

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
  Real relaxationFraction = Real(0.8); // share of a regular diastole spent returning to rest (0 = released at once)
  bool baseHeld = false;  // sections shrink about the long axis, none at the base (base_taper.h; cardiac_cycle.cpp)
  // Which vertices beat: the union of these selections. Empty everything = all myocardium.
  std::vector<int> segments;        // AHA segments 1..17
  std::vector<Index> vertices;      // vertex ids
  bool sphereEnabled = false;
  Vec3 sphereCentre = Vec3::Zero();  // m
  Real sphereRadius = 0;             // m
  // Irregular pattern: each diastole is shortened by a random share in [0, irregularity).
  Real irregularity = Real(0.6);
  bool irregularBothWays = false;  // set with the lumped circulation (beat_clock.h), not a key
  unsigned seed = 1;
  // Inconsistent pattern: these segments beat with their own rate and phase.
  std::vector<int> inconsistentSegments = {7, 13, 17};
  Real inconsistentRateFactor = Real(0.5);    // beat rate relative to the rest
  Real inconsistentPhaseOffset = Real(0.5);   // fraction of a cycle
};

// Blood as Position Based Fluid particles (thesis 4.2, Table 5.2). Defaults: the thesis's
// values, except the particle mass, which follows from the rest density and the spacing
// (docs/thesis-deviations.md).
struct BloodSettings {
  bool enabled = false;
  // Particle count; 0 = one particle per lattice site of the start block. When > 0, the block's
  // sites are filled bottom layer first (lowest y) and the block must hold that many.
  int particles = 1000;
  Real radius = Real(0.08);         // m, kept from walls and other particles (thesis: 0.08 m)
  Real spacing = Real(0.16);        // m, lattice spacing at rest = 2 radii; mass = rho0 spacing^3
  Real supportRadius = Real(0.32);  // m, SPH kernel support h (thesis: 0.32 m)
  Real restDensity = 1000;          // kg/m^3 (thesis: 1000; blood: 1060)
  Real viscosity = Real(0.04);      // Pa s, dynamic (thesis: 0.04; blood: 0.0035)
  // gamma of thesis eq. 4.11, dimensionless XSPH smoothing: c = gamma m / rho0 (fluid.h).
  Real xsph = Real(0.5);
  int iterations = 4;               // density solver iterations per step
  // PBF eps (eq. 11) relative to sum |grad C|^2 of a particle at rest in the lattice, so the
  // same value works at any spacing.
  Real relaxation = Real(0.1);
  // Thesis eq. 4.6 between blood particles. Off by default: with 2 radii = spacing it fights the
  // density constraint (fluid-at-rest: density error 3.6% with it, 0.27% without).
  bool particleCollision = false;
  // The heart wall lends density to the blood beside it (pbd/wall_density.h): without it blood
  // packs about a fifth tighter along walls than inside, so a contracting cavity holds more
  // particles per volume at end-systole than at end-diastole.
  bool wallDensity = false;
  // How blood is kept out of the heart wall after the wall's constraints (docs/heart-blood.md):
  // Thesis: the push-out of particles found inside a tet at the end of the step (thesis eq.
  // 4.12-4.20, pbd/particle_tet_collision.h) alone. Continuous: that push-out, then the swept
  // check of each particle's whole step against the moving wall surface (pbd/swept_contact.h),
  // so no step, however fast, crosses a wall however thin.
  enum class WallContact { Continuous, Thesis } wallContact = WallContact::Continuous;
  bool tensileCorrection = false;   // PBF s_corr (eq. 13-14)
  Real tensileK = Real(0.1);
  int tensileN = 4;
  Real tensileDeltaQ = Real(0.2);   // deltaQ / h
  Real vorticity = 0;               // m/s, PBF eq. 16 epsilon; 0 = off
  // Where the particles start: a lattice block (blockMin..blockMax), or the heart's chamber
  // (the LV cavity, at least one spacing from its wall).
  // "heart": the cavity and both vessels full (a particle radius from their walls), for the
  // lumped circulation, which needs the heart full from the first step.
  enum class Start { Block, Chamber, Vessel, Heart } start = Start::Block;
  Vec3 blockMin = Vec3(Real(-0.8), Real(-2.4), Real(-0.8));  // m, the block the particles start in
  Vec3 blockMax = Vec3(Real(0.8), Real(-0.8), Real(0.8));
  // Particles that may leave the domain before a run fails (exit 3): 0, any loss is a failure;
  // a scenario whose blood is meant to spill says how much it expects.
  int lossAllowed = 0;
};

// A closed box the blood cannot leave (dam break, column at rest). Its walls are planes
// (thesis eq. 4.5) or, with `mesh`, the same box as a static triangle mesh.
struct ContainerSettings {
  bool enabled = false;
  Vec3 min = Vec3(-1, -1, -1);  // m
  Vec3 max = Vec3(1, 1, 1);     // m
  bool mesh = false;
};


// The blood's path through the heart (circulation.h): valves, filling pressure, closed loop.
enum class ValveMode { Timing, Pressure, Open };
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

// [model] kind = "mesh": a patient's ventricle from CT/MRI meshes instead of the procedural one
// (docs/patient-meshes.md). The scenario reader resolves the paths against the scenario file's
// folder and reads the surfaces into `endocardiumSurface` / `epicardiumSurface`; the heart is
// built from them (cardiac/patient_lv_model.h). The wall thickness without an epicardium is
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
