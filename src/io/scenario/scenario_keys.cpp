// The scenario key table: one row per key. Adding a key is one row here (plus its line in
// docs/scenarios.md and, if it belongs in the lesson file, scenarios/*.toml).
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "io/scenario/scenario_internal.h"
#include "io/scenario/scenario_key_builders.h"

namespace hs::io::detail {
namespace {

using namespace builders;  // NOLINT(google-build-using-namespace): the row vocabulary
using cardiac::Scenario;

// The field accessor of a row: a captureless lambda Scenario& -> field&.
// clang-format off
#define HS_FIELD(expr) [](Scenario& s) -> auto& { return s.expr; }
// clang-format on

using cardiac::BeatPattern;
using cardiac::TimingMode;

constexpr const char* kMetres = "m";
// Every number key has finite bounds, and at each of them every built-in scenario either runs or
// is refused naming a key (tests/io/scenario/test_scenario_extremes.cpp): gravity up to about
// 10 g; positions within 100 m of the origin, fifty times the largest heart (the thesis's, 2 m
// across); the model's lengths from 0.5-5 mm, a mouse's heart, to 1-10 m, past the thesis's.
constexpr double kMaxGravity = 100;      // m/s^2
constexpr double kMaxCoordinate = 100;   // m

// [scenario]
std::vector<KeySpec> scenarioKeys() {
  return {
      stringKey("scenario.name", HS_FIELD(name), true,
                "Name shown in the output; defaults to the built-in name or the file name without .toml. "
                "The default output folder is results/<name> with every character other than letters, digits, - "
                "and _ made _."),
      stringKey("scenario.description", HS_FIELD(description), false, "Free text describing the lesson."),
  };
}

// [simulation]
std::vector<KeySpec> simulationKeys() {
  return {
      realKey("simulation.dt", HS_FIELD(simulation.dt), between(1e-6, 0.1), "s", "Time step."),
      realKey("simulation.duration", HS_FIELD(simulation.duration), between(0, 36000), "s",
              "Simulated time; the run takes round(duration / dt) steps."),
      intKey("simulation.iterations", HS_FIELD(simulation.iterations), 1, "",
             "Constraint solver iterations per step (more = stiffer, slower).", 1000),
      intKey("simulation.volume_passes", HS_FIELD(simulation.volumePasses), 0, "",
             "Extra sweeps of the wall's volume constraints after the iterations (incompressibility).", 1000),
      vec3Key("simulation.gravity", HS_FIELD(simulation.gravity), between(-kMaxGravity, kMaxGravity), "m/s^2",
              "Gravity [x, y, z]; y is the long axis (apex at -y, vessels at +y); each at most about 10 g, more "
              "than a body bears."),
  };
}

// [model]
std::vector<KeySpec> modelKeys() {
  return {
      boolKey("model.enabled", HS_FIELD(heart),
              "Whether the heart wall exists (false: blood in a container only, e.g. dam-break)."),
      realKey("model.endo_radius", HS_FIELD(geometry.endoRadius), between(0.005, 5), kMetres,
              "Short-axis radius of the cavity at the base plane."),
      realKey("model.endo_long_axis", HS_FIELD(geometry.endoLongAxis), between(0.005, 10), kMetres,
              "Cavity length from the base plane to the inner apex."),
      realKey("model.wall_thickness", HS_FIELD(geometry.wallThickness), between(0.001, 2), kMetres,
              "Myocardium thickness (also at the apex)."),
      realKey("model.base_thickness", HS_FIELD(geometry.baseThickness), between(0.001, 2), kMetres,
              "Thickness of the base plate that holds the valves."),
      realKey("model.mitral_radius", HS_FIELD(geometry.mitralRadius), between(0.001, 2), kMetres,
              "Inflow (mitral) orifice and vessel lumen radius."),
      realKey("model.aortic_radius", HS_FIELD(geometry.aorticRadius), between(0.001, 2), kMetres,
              "Outflow (aortic) orifice and vessel lumen radius."),
      realKey("model.vessel_wall_thickness", HS_FIELD(geometry.vesselWallThickness), between(0.0005, 1), kMetres,
              "Wall thickness of both vessels."),
      realKey("model.inflow_vessel_length", HS_FIELD(geometry.inflowVesselLength), between(0.001, 10), kMetres,
              "Inflow vessel length above the base plate."),
      realKey("model.outflow_vessel_length", HS_FIELD(geometry.outflowVesselLength), between(0.001, 10), kMetres,
              "Outflow vessel length above the base plate."),
      realKey("model.aortic_sinus_radius", HS_FIELD(geometry.aorticSinusRadius), between(0, 5), kMetres,
              "Lumen radius of the aortic root at its three sinuses of Valsalva (0: a straight root of the "
              "annulus's radius)."),
      realKey("model.atrium_radius", HS_FIELD(geometry.atriumRadius), between(0, 5), kMetres,
              "Lumen radius of the left atrium at its widest, over the mitral annulus (0: a straight inflow "
              "vessel)."),
      realKey("model.vessel_lean_deg", HS_FIELD(geometry.vesselLeanDeg), between(0, 40), "deg",
              "Steepest lean of each vessel away from the other over its lower half (0: vertical)."),
      realKey("model.mitral_leaflet_length", HS_FIELD(geometry.mitralLeafletLength), between(0, 5), kMetres,
              "How far the open mitral valve's leaflets hang into the cavity, a tube of the annulus's radius the "
              "inflow leaves at their tips (0: none, the open valve is a bare disc)."),
      realKey("model.resolution", HS_FIELD(geometry.resolution), between(0.25, 8), "",
              "Mesh refinement: 1 = thesis-like model (1,100 vertices, 3,237 tets); elements grow ~ "
              "resolution^2."),
  };
}

// [tissue]
std::vector<KeySpec> tissueKeys() {
  return {
      realKey("tissue.stiffness", HS_FIELD(tissue.stiffness), between(0, 1), "",
              "PBD stiffness k of the wall's area and edge constraints (0 = limp, 1 = rigid)."),
      realKey("tissue.volume_stiffness", HS_FIELD(tissue.volumeStiffness), between(0.25, 1), "",
              "PBD stiffness k of the tet volume constraints (1 = incompressible myocardium; at 0.1 the "
              "thesis's beat inverts paper-chamber-beating's tets within 20 steps)."),
      realKey("tissue.volume_compliance", HS_FIELD(tissue.volumeCompliance), between(0, 1e-9), "m^3/Pa",
              "XPBD compliance of the tet volume constraints (0 = plain PBD; at 1e-8 paper-chamber-beating's wall "
              "gives up its volume to the beat and its tets invert within 20 steps)."),
      realKey("tissue.area_compliance", HS_FIELD(tissue.areaCompliance), between(0, 1), "m^3/N",
              "XPBD compliance of the surface area constraints (0 = plain PBD; from 1e-3 on as good as off)."),
      realKey("tissue.edge_compliance", HS_FIELD(tissue.edgeCompliance), between(0, 1), "m/N",
              "XPBD compliance of the edge distance constraints (0 = plain PBD; from 1e-3 on as good as off)."),
      boolKey("tissue.areas", HS_FIELD(tissue.areas), "Surface triangle area constraints on (thesis 4.1.2)."),
      boolKey("tissue.edges", HS_FIELD(tissue.edges),
              "Edge distance constraints on (volume and area alone do not hold the shape)."),
      boolKey("tissue.gravity", HS_FIELD(tissue.gravity),
              "Gravity acts on the wall too (default false: the pericardium carries the heart's weight)."),
      realKey("tissue.damping", HS_FIELD(tissue.damping), between(0, 1000), "1/s",
              "Velocity damping of the wall (viscous tissue); 1000 takes a 1 ms step's whole velocity."),
      realKey("tissue.density", HS_FIELD(tissue.density), between(1, 100000), "kg/m^3",
              "Tissue density; vertex masses come from tet volumes."),
  };
}

// [cycle]
std::vector<KeySpec> cycleKeys() {
  const std::vector<std::pair<std::string, TimingMode>> modes = {
      {"thesis", TimingMode::Thesis}, {"physiological", TimingMode::Physiological}};
  const std::vector<std::pair<std::string, BeatPattern>> patterns = {
      {"normal", BeatPattern::Normal},
      {"irregular", BeatPattern::Irregular},
      {"inconsistent", BeatPattern::Inconsistent}};
  return {
      boolKey("cycle.enabled", HS_FIELD(cycle.enabled), "Whether the heart beats at all."),
      choiceKey("cycle.mode", HS_FIELD(cycle.mode), modes,
                "Timing: \"thesis\" (fixed steps per phase) or \"physiological\" (heart rate in bpm)."),
      choiceKey(
          "cycle.pattern", HS_FIELD(cycle.pattern), patterns,
          "Beat pattern: regular, irregular (random diastoles) or inconsistent (some segments out of step)."),
      intKey("cycle.beats", HS_FIELD(cycle.beats), 0, "",
             "Number of beats, then the wall relaxes; 0 = no limit."),
      intKey("cycle.beating_duration", HS_FIELD(cycle.beatingDuration), 1, "steps",
             "Thesis mode: time steps per phase (systole, diastole)."),
      realKey("cycle.beating_displace", HS_FIELD(cycle.beatingDisplace), between(0, 1), "m per step",
              "Thesis mode: inward displacement of a beating vertex per systolic step; at most 0.45 of the "
              "procedural wall's edge (0.21 model.endo_radius / model.resolution), beyond which tets invert."),
      realKey("cycle.heart_rate_bpm", HS_FIELD(cycle.heartRateBpm), between(20, 250), "1/min",
              "Physiological mode: beats per minute."),
      realKey("cycle.systolic_fraction", HS_FIELD(cycle.systolicFraction), between(0.05, 0.95), "",
              "Physiological mode: share of each cycle spent in systole."),
      realKey("cycle.contraction", HS_FIELD(cycle.contraction), between(0, 2), kMetres,
              "Physiological mode: total inward displacement of a beating vertex per systole."),
      realKey("cycle.relaxation_fraction", HS_FIELD(cycle.relaxationFraction), between(0, 1), "",
              "Physiological mode: share of a regular diastole the wall takes to return to rest "
              "(0 = released to its constraints at once)."),
      boolKey("cycle.base_held", HS_FIELD(cycle.baseHeld),
              "Physiological mode, a procedural heart: each section shrinks about the long axis, the "
              "wall thickening, and the base ring is held by the fibrous skeleton (the travel fades from "
              "the mid-ventricle to none at the base plane)."),
      intListKey("cycle.segments", HS_FIELD(cycle.segments), 1, 17, true,
                 "AHA segments (1..17) that beat; with vertices and sphere empty, all myocardium beats."),
      intListKey("cycle.vertices", HS_FIELD(cycle.vertices), 0, std::numeric_limits<std::int64_t>::max(),
                 false, "Vertex ids that beat (added to the segments)."),
      realKey("cycle.irregularity", HS_FIELD(cycle.irregularity), between(0, 1), "",
              "Irregular pattern: each diastole is shortened by a random share in [0, irregularity)."),
      intKey("cycle.seed", HS_FIELD(cycle.seed), 0, "",
             "Random seed of the irregular pattern (same seed = same run)."),
  };
}

// [cycle.sphere]: present = the vertices inside the sphere beat too
std::vector<KeySpec> cycleSphereKeys() {
  return {
      vec3Key("cycle.sphere.centre", HS_FIELD(cycle.sphereCentre), between(-kMaxCoordinate, kMaxCoordinate), kMetres,
              "Centre of a sphere whose vertices beat (the table's presence enables it)."),
      realKey("cycle.sphere.radius", HS_FIELD(cycle.sphereRadius), between(0.001, 100), kMetres,
              "Radius of that sphere; required when [cycle.sphere] is present."),
  };
}

// [cycle.inconsistent]
std::vector<KeySpec> cycleInconsistentKeys() {
  return {
      intListKey("cycle.inconsistent.segments", HS_FIELD(cycle.inconsistentSegments), 1, 17, true,
                 "Inconsistent pattern: segments that beat at their own rate and phase."),
      realKey("cycle.inconsistent.rate_factor", HS_FIELD(cycle.inconsistentRateFactor), between(0.1, 10), "",
              "Their beat rate relative to the rest of the heart."),
      realKey("cycle.inconsistent.phase_offset", HS_FIELD(cycle.inconsistentPhaseOffset), between(0, 1),
              "cycles", "Their phase lag, as a fraction of a cycle."),
  };
}

// [blood]
std::vector<KeySpec> bloodKeys() {
  const std::vector<std::pair<std::string, cardiac::BloodSettings::Start>> starts = {
      {"block", cardiac::BloodSettings::Start::Block},
      {"chamber", cardiac::BloodSettings::Start::Chamber},
      {"vessel", cardiac::BloodSettings::Start::Vessel},
      {"heart", cardiac::BloodSettings::Start::Heart}};
  const std::vector<std::pair<std::string, cardiac::BloodSettings::WallContact>> wallContacts = {
      {"continuous", cardiac::BloodSettings::WallContact::Continuous},
      {"thesis", cardiac::BloodSettings::WallContact::Thesis}};
  return {
      boolKey("blood.enabled", HS_FIELD(blood.enabled), "Whether blood particles are simulated."),
      intKey("blood.particles", HS_FIELD(blood.particles), 0, "",
             "Number of blood particles; 0 = fill the start block (lowest layers first otherwise). At most "
             "1,000,000, ten times a body's 5 L of blood at the real-size hearts' spacing (107,000).",
             1'000'000),
      realKey("blood.radius", HS_FIELD(blood.radius), between(1e-4, 1), kMetres,
              "Particle radius: distance kept from walls and between particles (thesis 0.08 m)."),
      realKey("blood.spacing", HS_FIELD(blood.spacing), between(1e-4, 1), kMetres,
              "Particle spacing at rest (normally 2 radii); particle mass = rest_density spacing^3."),
      realKey("blood.support_radius", HS_FIELD(blood.supportRadius), between(1e-4, 2), kMetres,
              "SPH kernel support radius h, larger than the spacing (thesis 0.32 m = 2 spacings)."),
      realKey("blood.rest_density", HS_FIELD(blood.restDensity), between(500, 100000), "kg/m^3",
              "Density at rest (thesis 1000; blood 1060); at least 500, the lightest liquids' (at 1 a real-size "
              "heart lost blood within 20 steps)."),
      realKey("blood.viscosity", HS_FIELD(blood.viscosity), between(0, 100), "Pa s",
              "Dynamic viscosity (thesis 0.04; blood 0.0035; water 0.001); at most 100 (at 1000 paper-chamber-beating "
              "lost blood within 15 steps)."),
      realKey("blood.xsph", HS_FIELD(blood.xsph), between(0, 0.95), "",
              "XSPH smoothing gamma of thesis eq. 4.11 (0 = off; below 1 for stability)."),
      intKey("blood.iterations", HS_FIELD(blood.iterations), 1, "", "Density solver iterations per step.",
             1000),
      realKey("blood.relaxation", HS_FIELD(blood.relaxation), between(1e-6, 1000), "",
              "Constraint-force mixing eps of PBF eq. 11, relative to a particle at rest."),
      boolKey("blood.particle_collision", HS_FIELD(blood.particleCollision),
              "Particles keep 2 radii apart (thesis eq. 4.6)."),
      boolKey("blood.wall_density", HS_FIELD(blood.wallDensity),
              "The heart wall lends density to the blood beside it, so blood does not pack tighter along walls."),
      choiceKey("blood.wall_contact", HS_FIELD(blood.wallContact), wallContacts,
                "How blood is kept out of the heart wall: \"continuous\" (the thesis's push-out, then each "
                "particle's whole step checked against the moving wall: no crossing at any speed) or \"thesis\" "
                "(the push-out of particles found inside the wall at the end of the step alone)."),
      boolKey("blood.tensile_correction", HS_FIELD(blood.tensileCorrection),
              "Artificial pressure s_corr against clumping (PBF eq. 13)."),
      realKey("blood.tensile_k", HS_FIELD(blood.tensileK), between(0, 1), "",
              "s_corr strength k (PBF: 0.1)."),
      intKey("blood.tensile_n", HS_FIELD(blood.tensileN), 1, "", "s_corr exponent n (PBF: 4).", 16),
      realKey("blood.tensile_dq", HS_FIELD(blood.tensileDeltaQ), between(0.01, 0.99), "",
              "s_corr reference distance, as a fraction of the support radius (PBF: 0.1-0.3)."),
      realKey("blood.vorticity", HS_FIELD(blood.vorticity), between(0, 1), "m/s",
              "Vorticity confinement epsilon (PBF eq. 16); 0 = off. At most 1: at 10 idealized-lv loses blood "
              "through the wall within 20 steps (3 runs), at 100 every real-size heart within 4."),
      choiceKey("blood.start", HS_FIELD(blood.start), starts,
                "Where the blood starts: \"block\" (block_min..block_max), \"chamber\" (the LV cavity) or "
                "\"vessel\" (the inflow vessel, then the cavity from the base down if it holds more)."),
      vec3Key("blood.block_min", HS_FIELD(blood.blockMin), between(-kMaxCoordinate, kMaxCoordinate), kMetres,
              "Lower corner of the block the blood starts in."),
      vec3Key("blood.block_max", HS_FIELD(blood.blockMax), between(-kMaxCoordinate, kMaxCoordinate), kMetres, "Upper corner of that block."),
      intKey("blood.loss_allowed", HS_FIELD(blood.lossAllowed), 0, "",
             "Blood particles that may leave the domain before `heartsim run` stops with exit 3, naming when "
             "and where; 0: any loss is a failure.",
             10'000'000),
  };
}

// [container]
std::vector<KeySpec> containerKeys() {
  return {
      boolKey("container.enabled", HS_FIELD(container.enabled), "A closed box the blood cannot leave."),
      vec3Key("container.min", HS_FIELD(container.min), between(-kMaxCoordinate, kMaxCoordinate), kMetres, "Lower corner of the box."),
      vec3Key("container.max", HS_FIELD(container.max), between(-kMaxCoordinate, kMaxCoordinate), kMetres, "Upper corner of the box."),
      boolKey("container.mesh", HS_FIELD(container.mesh),
              "Walls as a static triangle mesh instead of planes (same box)."),
  };
}

// [circulation]
std::vector<KeySpec> circulationKeys() {
  const std::vector<std::pair<std::string, cardiac::ValveMode>> valveModes = {
      {"timing", cardiac::ValveMode::Timing},
      {"pressure", cardiac::ValveMode::Pressure},
      {"open", cardiac::ValveMode::Open}};
  return {
      choiceKey("circulation.valves", HS_FIELD(circulation.valveMode), valveModes,
                "When the valves open: \"timing\" (mitral in diastole, aortic in systole), \"pressure\" "
                "(while the pressure before a valve exceeds the pressure after it) or \"open\" (always)."),
      boolKey("circulation.loop", HS_FIELD(circulation.loop),
              "Blood leaving a vessel's far end re-enters the inflow vessel (closed loop, nothing lost)."),
      realKey("circulation.atrial_pressure_mmhg", HS_FIELD(circulation.atrialPressureMmHg), between(0, 100),
              "mmHg", "Filling (atrial) pressure driving blood down the inflow vessel."),
      boolKey("circulation.two_way", HS_FIELD(circulation.twoWay),
              "Two-way coupling: blood pushes the wall back (off: the thesis's one-way push-out)."),
      boolKey("circulation.wall_slip", HS_FIELD(circulation.wallSlip),
              "Blood slides along the wall: pushed out of the face it entered through along that face's "
              "normal (off: back along its path, thesis eq. 4.20)."),
  };
}

// [circulation], the lumped circulation (cardiac/circulation/lumped_circulation.h, docs/physiology.md):
// clinical units in the file, SI inside.
std::vector<KeySpec> lumpedCirculationKeys() {
  using namespace cardiac;
  const double mmHg = kPascalPerMmHg, mL = kCubicMetresPerMl;
  const double elastance = elastanceFromClinical(1), resistance = resistanceFromClinical(1);
  const double compliance = complianceFromClinical(1), cm2 = 1e-4;
  return {
      boolKey("circulation.lumped", HS_FIELD(circulation.lumped),
              "A lumped circulation (elastance ventricle and atrium, three-element Windkessel) gives the "
              "pressures and drives the wall: the cavity follows its volume, the valves its valves. "
              "Needs cycle.mode = \"physiological\"."),
      clinicalKey("circulation.contractility_mmhg_per_ml", HS_FIELD(circulation.lumpedParameters.contractility),
                  elastance, between(0.05, 20), "mmHg/mL",
                  "End-systolic elastance Ees of the whole ventricle (scaled by the share of the wall that beats)."),
      clinicalKey("circulation.lv_v0_ml", HS_FIELD(circulation.lumpedParameters.unstressedVolume), mL,
                  between(0, 200), "mL", "Unstressed volume V0 of the pressure-volume relations."),
      clinicalKey("circulation.lv_stiffness_mmhg", HS_FIELD(circulation.lumpedParameters.diastolicScale), mmHg,
                  between(0.01, 20), "mmHg", "A of the end-diastolic relation P = A (exp(B (V - V0)) - 1)."),
      clinicalKey("circulation.lv_stiffness_per_ml", HS_FIELD(circulation.lumpedParameters.diastolicExponent),
                  1 / mL, between(0.001, 0.05), "1/mL",
                  "B of the end-diastolic relation: the ventricle's stiffness (beyond 0.05 the relaxed "
                  "ventricle's pressure at its rest volume is hundreds of mmHg and throws the blood about)."),
      clinicalKey("circulation.peripheral_resistance_mmhg_s_per_ml",
                  HS_FIELD(circulation.lumpedParameters.peripheralResistance), resistance, between(0.1, 20),
                  "mmHg s/mL", "Afterload: systemic peripheral resistance of the Windkessel."),
      clinicalKey("circulation.arterial_compliance_ml_per_mmhg",
                  HS_FIELD(circulation.lumpedParameters.arterialCompliance), compliance, between(0.1, 20), "mL/mmHg",
                  "Afterload: compliance of the systemic arteries."),
      clinicalKey("circulation.characteristic_impedance_mmhg_s_per_ml",
                  HS_FIELD(circulation.lumpedParameters.characteristicImpedance), resistance, between(0, 1),
                  "mmHg s/mL", "Characteristic impedance of the proximal aorta."),
      clinicalKey("circulation.venous_pressure_mmhg",
                  HS_FIELD(circulation.lumpedParameters.systemicVenousPressure), mmHg, between(0, 30), "mmHg",
                  "Systemic venous pressure the Windkessel drains into."),
      clinicalKey("circulation.aortic_valve_area_cm2", HS_FIELD(circulation.aorticValveArea), cm2, between(0, 20),
                  "cm^2", "Aortic valve orifice; smaller than the vessel's lumen is a stenosis (0: the lumen)."),
      clinicalKey("circulation.mitral_regurgitant_area_cm2",
                  HS_FIELD(circulation.lumpedParameters.mitralRegurgitantArea), cm2, between(0, 10), "cm^2",
                  "Orifice through which blood leaks back into the atrium in systole (0: a competent valve)."),
      boolKey("circulation.atrial_contraction", HS_FIELD(circulation.atrialContraction),
              "The atrium contracts before each beat (the A wave); false: atrial fibrillation."),
      realKey("circulation.base_descent", HS_FIELD(circulation.wallMotion.longitudinal), between(0, 0.4), "",
              "Wall motion: the base's descent toward the apex at full contraction, share of the long axis."),
      realKey("circulation.radial_shortening", HS_FIELD(circulation.wallMotion.radial), between(0, 0.3), "",
              "Wall motion: the epicardium's travel toward the long axis at full contraction, share of its "
              "radius (the endocardium moves in as far as the incompressible wall thickens)."),
  };
}

// [output]
std::vector<KeySpec> outputKeys() {
  return {
      boolKey("output.vtk", HS_FIELD(output.vtk), "Write VTK frames for ParaView."),
      intKey("output.vtk_every", HS_FIELD(output.vtkEvery), 1, "steps", "Time steps between VTK frames."),
  };
}

// The rows in the order of docs/scenarios.md and of a printed scenario: table by table.
std::vector<KeySpec> buildKeyTable() {
  using SectionKeys = std::vector<KeySpec> (*)();
  std::vector<KeySpec> table;
  for (const SectionKeys section :
       {&scenarioKeys, &simulationKeys, &modelKeys, &meshModelKeys, &tissueKeys, &cycleKeys, &cycleSphereKeys,
        &cycleInconsistentKeys, &bloodKeys, &containerKeys, &circulationKeys, &lumpedCirculationKeys, &motionKeys, &outputKeys}) {
    std::vector<KeySpec> rows = section();
    std::move(rows.begin(), rows.end(), std::back_inserter(table));
  }
  return table;
}

}  // namespace

const std::vector<KeySpec>& keyTable() {
  static const std::vector<KeySpec> table = buildKeyTable();
  return table;
}

const std::vector<TableSpec>& tableTable() {
  static const std::vector<TableSpec> tables = {
      {"scenario", nullptr, nullptr},
      {"simulation", nullptr, nullptr},
      {"model", nullptr, nullptr},
      {"model.markers", nullptr, nullptr},
      {"tissue", nullptr, nullptr},
      {"cycle", nullptr, nullptr},
      {"cycle.sphere", [](Scenario& s) { s.cycle.sphereEnabled = true; },
       [](const Scenario& s) { return s.cycle.sphereEnabled; }},
      {"cycle.inconsistent", nullptr, nullptr},
      {"blood", nullptr, nullptr},
      {"container", nullptr, nullptr},
      {"circulation", nullptr, nullptr},
      {"motion", nullptr, nullptr},
      {"output", nullptr, nullptr},
  };
  return tables;
}

const KeySpec* findKey(std::string_view dotted) {
  for (const KeySpec& k : keyTable())
    if (k.name == dotted) return &k;
  return nullptr;
}

const TableSpec* findTable(std::string_view dotted) {
  for (const TableSpec& t : tableTable())
    if (t.name == dotted) return &t;
  return nullptr;
}

}  // namespace hs::io::detail
