// Over 400 lines on purpose: one test file per module, its cases sharing the file's set-up helpers.
// Scenario files: built-ins, every key through --set, and one-line errors that name the file,
// the line and the key.
#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "io/scenario/scenario_file.h"

namespace hs::io {
namespace {

using cardiac::BeatPattern;
using cardiac::Scenario;
using cardiac::TimingMode;
using pbd::Real;
using pbd::Vec3;

std::string writeTemp(const std::string& fileName, const std::string& text) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / fileName;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

const std::string kBivmeEndocardium =
    std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj";

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The ScenarioError message of f(), or fails the test.
std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ScenarioError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ScenarioError";
  return "";
}

// parseScenario(text) must fail with a one-line message containing every piece.
void expectParseError(const std::string& text, const std::vector<std::string>& pieces,
                      const std::vector<std::string>& overrides = {}) {
  const std::string msg = errorOf([&] { parseScenario(text, "lesson.toml", overrides); });
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\r'), std::string::npos) << msg;
  for (const std::string& p : pieces)
    EXPECT_NE(msg.find(p), std::string::npos) << "missing '" << p << "' in: " << msg;
}

TEST(ScenarioFile, HeartOnlyBuiltinHasTheThesisValues) {
  const Scenario s = loadScenario("heart-only");
  EXPECT_EQ(s.name, "heart-only");
  EXPECT_FALSE(s.description.empty());
  EXPECT_EQ(s.simulation.dt, Real(0.005));
  EXPECT_EQ(s.simulation.duration, Real(2.0));
  EXPECT_EQ(s.simulation.iterations, 3);
  EXPECT_EQ(s.simulation.volumePasses, 3);
  EXPECT_EQ(s.simulation.gravity, Vec3(0, Real(-9.81), 0));
  EXPECT_TRUE(s.cycle.enabled);
  EXPECT_EQ(s.cycle.mode, TimingMode::Thesis);
  EXPECT_EQ(s.cycle.pattern, BeatPattern::Normal);
  EXPECT_EQ(s.cycle.beatingDuration, 8);
  EXPECT_EQ(s.cycle.beatingDisplace, Real(0.08));
  EXPECT_EQ(s.cycle.beats, 0);
  EXPECT_FALSE(s.cycle.sphereEnabled);
  EXPECT_FALSE(s.blood.enabled);
  EXPECT_EQ(s.blood.particles, 1000);
  // Everything else is at the struct defaults: the file writes the defaults out.
  Scenario withoutDescription = s;
  withoutDescription.description.clear();
  EXPECT_EQ(scenarioToToml(withoutDescription), scenarioToToml(Scenario{}));
}

TEST(ScenarioFile, BuiltinMatchesTheSourceFile) {
  ASSERT_EQ(builtinScenarioText("heart-only"),
            readFile(std::string(HS_SOURCE_DIR) + "/scenarios/heart-only.toml"));
}

TEST(ScenarioFile, EveryBuiltinParsesAndEveryScenarioFileIsBuiltIn) {
  const std::vector<std::string> names = builtinScenarioNames();
  std::set<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(HS_SOURCE_DIR) + "/scenarios"))
    if (e.path().extension() == ".toml") files.insert(e.path().stem().string());
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()), files);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(loadScenario(name));
  }
}

TEST(ScenarioFile, UnknownBuiltinNameThrows) {
  const std::string msg = errorOf([] { builtinScenarioText("nope"); });
  EXPECT_NE(msg.find("nope"), std::string::npos) << msg;
}

// Keys of a TOML file written as "key = value" lines under [table] headers (no inline tables).
std::set<std::string> keysWrittenIn(const std::string& text) {
  std::set<std::string> keys;
  std::istringstream in(text);
  std::string line, table;
  while (std::getline(in, line)) {
    const auto b = line.find_first_not_of(" \t");
    if (b == std::string::npos || line[b] == '#') continue;
    if (line[b] == '[') {
      table = line.substr(b + 1, line.find(']') - b - 1);
    } else if (const auto eq = line.find('='); eq != std::string::npos) {
      std::string key = line.substr(b, eq - b);
      key.erase(key.find_last_not_of(" \t") + 1);
      keys.insert(table + "." + key);
    }
  }
  return keys;
}

TEST(ScenarioFile, HeartOnlyWritesEveryKeyButTheOptionalSphere) {
  const std::set<std::string> written = keysWrittenIn(builtinScenarioText("heart-only"));
  for (const ScenarioKeyInfo& k : scenarioKeys()) {
    if (k.name.rfind("cycle.sphere.", 0) == 0) {
      EXPECT_EQ(written.count(k.name), 0u) << k.name;
    } else {
      EXPECT_EQ(written.count(k.name), 1u) << k.name << " missing from heart-only.toml";
    }
  }
}

TEST(ScenarioFile, DocsDescribeEveryKey) {
  const std::string docs = readFile(std::string(HS_SOURCE_DIR) + "/docs/scenarios.md");
  for (const ScenarioKeyInfo& k : scenarioKeys())
    EXPECT_NE(docs.find("`" + k.name + "`"), std::string::npos) << k.name << " missing from docs";
}

TEST(ScenarioFile, NameDefaultsToTheFileStem) {
  EXPECT_EQ(parseScenario("", "some/dir/my-lesson.toml").name, "my-lesson");
  EXPECT_EQ(parseScenario("[scenario]\nname = \"x\"\n", "my-lesson.toml").name, "x");
  const std::string path = writeTemp("stem-test.toml", "[simulation]\ndt = 0.01\n");
  const Scenario s = loadScenario(path);
  EXPECT_EQ(s.name, "stem-test");
  EXPECT_EQ(s.simulation.dt, Real(0.01));
}

// One override per key and a check that it landed in the right field.
struct KeyCase {
  std::string key;
  std::string value;
  std::function<bool(const Scenario&)> check;
};

// A value read in clinical units and kept in SI, to the float precision of the file reader.
bool near(double actual, double expected) { return std::abs(actual - expected) <= 1e-6 * std::abs(expected); }

// Two frames of a recorded beat (biv-me's endocardium twice) for the motion.frames case; the
// pattern naming them.
std::string keyCaseFrames() {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "heartsim_key_frames";
  std::filesystem::create_directories(dir);
  for (const char* name : {"endo_0.obj", "endo_1.obj"})
    std::filesystem::copy_file(kBivmeEndocardium, dir / name, std::filesystem::copy_options::overwrite_existing);
  return (dir / "endo_{frame}.obj").lexically_normal().string();
}

std::vector<KeyCase> everyKeyCase() {
  const std::string frames = keyCaseFrames();
  return {
      {"scenario.name", "lesson one", [](const Scenario& s) { return s.name == "lesson one"; }},
      {"scenario.description", "\"a \\\"quoted\\\" text\"",
       [](const Scenario& s) { return s.description == "a \"quoted\" text"; }},
      {"simulation.dt", "0.001", [](const Scenario& s) { return s.simulation.dt == Real(0.001); }},
      {"simulation.duration", "7", [](const Scenario& s) { return s.simulation.duration == Real(7); }},
      {"simulation.iterations", "25", [](const Scenario& s) { return s.simulation.iterations == 25; }},
      {"simulation.gravity", "[1, 2.5, -3]",
       [](const Scenario& s) { return s.simulation.gravity == Vec3(1, Real(2.5), -3); }},
      {"model.endo_radius", "1.1", [](const Scenario& s) { return s.geometry.endoRadius == Real(1.1); }},
      {"model.endo_long_axis", "2.1", [](const Scenario& s) { return s.geometry.endoLongAxis == Real(2.1); }},
      {"model.wall_thickness", "0.31",
       [](const Scenario& s) { return s.geometry.wallThickness == Real(0.31); }},
      {"model.base_thickness", "0.16",
       [](const Scenario& s) { return s.geometry.baseThickness == Real(0.16); }},
      {"model.mitral_radius", "0.37",
       [](const Scenario& s) { return s.geometry.mitralRadius == Real(0.37); }},
      {"model.aortic_radius", "0.27",
       [](const Scenario& s) { return s.geometry.aorticRadius == Real(0.27); }},
      {"model.vessel_wall_thickness", "0.07",
       [](const Scenario& s) { return s.geometry.vesselWallThickness == Real(0.07); }},
      {"model.inflow_vessel_length", "1.2",
       [](const Scenario& s) { return s.geometry.inflowVesselLength == Real(1.2); }},
      {"model.outflow_vessel_length", "1.3",
       [](const Scenario& s) { return s.geometry.outflowVesselLength == Real(1.3); }},
      {"model.aortic_sinus_radius", "0.8",
       [](const Scenario& s) { return s.geometry.aorticSinusRadius == Real(0.8); }},
      {"model.atrium_radius", "1.1", [](const Scenario& s) { return s.geometry.atriumRadius == Real(1.1); }},
      {"model.vessel_lean_deg", "30", [](const Scenario& s) { return s.geometry.vesselLeanDeg == Real(30); }},
      {"model.mitral_leaflet_length", "0.9",
       [](const Scenario& s) { return s.geometry.mitralLeafletLength == Real(0.9); }},
      {"model.resolution", "2", [](const Scenario& s) { return s.geometry.resolution == Real(2); }},
      {"model.kind", "\"mesh\"", [](const Scenario& s) { return s.patient.kind == cardiac::ModelKind::Mesh; }},
      {"model.endocardium", "\"lv/endo.obj\"", [](const Scenario& s) { return s.patient.endocardium == "lv/endo.obj"; }},
      {"model.epicardium", "\"lv/epi.obj\"", [](const Scenario& s) { return s.patient.epicardium == "lv/epi.obj"; }},
      {"model.volume_mesh", "\"lv.msh\"", [](const Scenario& s) { return s.patient.volumeMesh == "lv.msh"; }},
      {"model.units", "\"m\"", [](const Scenario& s) { return s.patient.units == cardiac::LengthUnit::Metre; }},
      {"model.mesh_resolution", "\"fine\"", [](const Scenario& s) { return s.patient.resolution == "fine"; }},
      {"model.septum", "[1.0, 0.0, 0.5]",
       [](const Scenario& s) { return s.patient.septum == Vec3(1, 0, Real(0.5)); }},
      {"model.mitral_loop", "2", [](const Scenario& s) { return s.patient.mitralLoop == 2; }},
      {"model.aortic_loop", "1", [](const Scenario& s) { return s.patient.aorticLoop == 1; }},
      {"model.markers.endocardium", "\"LV_ENDO\"",
       [](const Scenario& s) { return s.patient.markerEndocardium == "LV_ENDO"; }},
      {"model.markers.epicardium", "7", [](const Scenario& s) { return s.patient.markerEpicardium == "7"; }},
      {"model.markers.base", "\"Base\"", [](const Scenario& s) { return s.patient.markerBase == "Base"; }},
      {"simulation.volume_passes", "5", [](const Scenario& s) { return s.simulation.volumePasses == 5; }},
      {"tissue.stiffness", "0.75", [](const Scenario& s) { return s.tissue.stiffness == Real(0.75); }},
      {"tissue.volume_stiffness", "0.25", [](const Scenario& s) { return s.tissue.volumeStiffness == Real(0.25); }},
      {"tissue.volume_compliance", "5e-10",
       [](const Scenario& s) { return s.tissue.volumeCompliance == Real(5e-10); }},
      {"tissue.area_compliance", "2e-6",
       [](const Scenario& s) { return s.tissue.areaCompliance == Real(2e-6); }},
      {"tissue.edge_compliance", "3e-6",
       [](const Scenario& s) { return s.tissue.edgeCompliance == Real(3e-6); }},
      {"tissue.areas", "false", [](const Scenario& s) { return !s.tissue.areas; }},
      {"tissue.edges", "false", [](const Scenario& s) { return !s.tissue.edges; }},
      {"tissue.gravity", "true", [](const Scenario& s) { return s.tissue.gravity; }},
      {"tissue.damping", "0.5", [](const Scenario& s) { return s.tissue.damping == Real(0.5); }},
      {"tissue.density", "1000", [](const Scenario& s) { return s.tissue.density == Real(1000); }},
      {"cycle.enabled", "false", [](const Scenario& s) { return !s.cycle.enabled; }},
      {"cycle.mode", "physiological",
       [](const Scenario& s) { return s.cycle.mode == TimingMode::Physiological; }},
      {"cycle.pattern", "\"irregular\"",
       [](const Scenario& s) { return s.cycle.pattern == BeatPattern::Irregular; }},
      {"cycle.beats", "3", [](const Scenario& s) { return s.cycle.beats == 3; }},
      {"cycle.beating_duration", "5", [](const Scenario& s) { return s.cycle.beatingDuration == 5; }},
      {"cycle.beating_displace", "0.05",
       [](const Scenario& s) { return s.cycle.beatingDisplace == Real(0.05); }},
      {"cycle.heart_rate_bpm", "60", [](const Scenario& s) { return s.cycle.heartRateBpm == Real(60); }},
      {"cycle.systolic_fraction", "0.4",
       [](const Scenario& s) { return s.cycle.systolicFraction == Real(0.4); }},
      {"cycle.contraction", "0.2", [](const Scenario& s) { return s.cycle.contraction == Real(0.2); }},
      {"cycle.relaxation_fraction", "0.25",
       [](const Scenario& s) { return s.cycle.relaxationFraction == Real(0.25); }},
      {"cycle.base_held", "true", [](const Scenario& s) { return s.cycle.baseHeld; }},
      {"cycle.segments", "[1,2,3]",
       [](const Scenario& s) {
         return s.cycle.segments == std::vector<int>{1, 2, 3};
       }},
      {"cycle.vertices", "[0, 5, 4000000000]",
       [](const Scenario& s) {
         return s.cycle.vertices == std::vector<pbd::Index>{0, 5, 4000000000u};
       }},
      {"cycle.irregularity", "0.25", [](const Scenario& s) { return s.cycle.irregularity == Real(0.25); }},
      {"cycle.seed", "4294967295", [](const Scenario& s) { return s.cycle.seed == 4294967295u; }},
      {"cycle.sphere.centre", "[0, -1.5, 0.25]",
       [](const Scenario& s) {
         return s.cycle.sphereEnabled && s.cycle.sphereCentre == Vec3(0, Real(-1.5), Real(0.25));
       }},
      {"cycle.sphere.radius", "0.5",
       [](const Scenario& s) { return s.cycle.sphereEnabled && s.cycle.sphereRadius == Real(0.5); }},
      {"cycle.inconsistent.segments", "[17]",
       [](const Scenario& s) { return s.cycle.inconsistentSegments == std::vector<int>{17}; }},
      {"cycle.inconsistent.rate_factor", "2",
       [](const Scenario& s) { return s.cycle.inconsistentRateFactor == Real(2); }},
      {"cycle.inconsistent.phase_offset", "0.25",
       [](const Scenario& s) { return s.cycle.inconsistentPhaseOffset == Real(0.25); }},
      {"blood.enabled", "true", [](const Scenario& s) { return s.blood.enabled; }},
      {"blood.particles", "5000", [](const Scenario& s) { return s.blood.particles == 5000; }},
      {"blood.radius", "0.09", [](const Scenario& s) { return s.blood.radius == Real(0.09); }},
      {"blood.spacing", "0.15", [](const Scenario& s) { return s.blood.spacing == Real(0.15); }},
      {"blood.support_radius", "0.4", [](const Scenario& s) { return s.blood.supportRadius == Real(0.4); }},
      {"blood.rest_density", "1060", [](const Scenario& s) { return s.blood.restDensity == Real(1060); }},
      {"blood.viscosity", "0.0035", [](const Scenario& s) { return s.blood.viscosity == Real(0.0035); }},
      {"blood.xsph", "0.2", [](const Scenario& s) { return s.blood.xsph == Real(0.2); }},
      {"blood.iterations", "6", [](const Scenario& s) { return s.blood.iterations == 6; }},
      {"blood.relaxation", "0.3", [](const Scenario& s) { return s.blood.relaxation == Real(0.3); }},
      {"blood.particle_collision", "true", [](const Scenario& s) { return s.blood.particleCollision; }},
      {"blood.wall_density", "true", [](const Scenario& s) { return s.blood.wallDensity; }},
      {"blood.wall_contact", "thesis",
       [](const Scenario& s) { return s.blood.wallContact == cardiac::BloodSettings::WallContact::Thesis; }},
      {"blood.tensile_correction", "true", [](const Scenario& s) { return s.blood.tensileCorrection; }},
      {"blood.tensile_k", "0.05", [](const Scenario& s) { return s.blood.tensileK == Real(0.05); }},
      {"blood.tensile_n", "3", [](const Scenario& s) { return s.blood.tensileN == 3; }},
      {"blood.tensile_dq", "0.3", [](const Scenario& s) { return s.blood.tensileDeltaQ == Real(0.3); }},
      {"blood.vorticity", "0.01", [](const Scenario& s) { return s.blood.vorticity == Real(0.01); }},
      {"blood.start", "chamber",
       [](const Scenario& s) { return s.blood.start == cardiac::BloodSettings::Start::Chamber; }},
      {"blood.block_min", "[-1.0, -3.0, -1.0]",
       [](const Scenario& s) { return s.blood.blockMin == Vec3(-1, -3, -1); }},
      {"blood.block_max", "[1.0, 0.0, 1.0]", [](const Scenario& s) { return s.blood.blockMax == Vec3(1, 0, 1); }},
      {"blood.loss_allowed", "12", [](const Scenario& s) { return s.blood.lossAllowed == 12; }},
      {"container.enabled", "true", [](const Scenario& s) { return s.container.enabled; }},
      {"container.min", "[-2.0, -4.0, -2.0]", [](const Scenario& s) { return s.container.min == Vec3(-2, -4, -2); }},
      {"container.max", "[2.0, 1.5, 2.0]", [](const Scenario& s) { return s.container.max == Vec3(2, 1.5, 2); }},
      {"container.mesh", "true", [](const Scenario& s) { return s.container.mesh; }},
      {"model.enabled", "false", [](const Scenario& s) { return !s.heart; }},
      {"circulation.valves", "pressure",
       [](const Scenario& s) { return s.circulation.valveMode == cardiac::ValveMode::Pressure; }},
      {"circulation.loop", "false", [](const Scenario& s) { return !s.circulation.loop; }},
      {"circulation.atrial_pressure_mmhg", "8",
       [](const Scenario& s) { return s.circulation.atrialPressureMmHg == Real(8); }},
      {"circulation.two_way", "true", [](const Scenario& s) { return s.circulation.twoWay; }},
      {"circulation.wall_slip", "true", [](const Scenario& s) { return s.circulation.wallSlip; }},
      {"circulation.lumped", "true", [](const Scenario& s) { return s.circulation.lumped; }},
      // Clinical units in the file, SI inside.
      {"circulation.contractility_mmhg_per_ml", "1.5",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.contractility, 1.5 * 133.322e6); }},
      {"circulation.lv_v0_ml", "20",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.unstressedVolume, 20e-6); }},
      {"circulation.lv_stiffness_mmhg", "0.7",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.diastolicScale, 0.7 * 133.322); }},
      {"circulation.lv_stiffness_per_ml", "0.05",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.diastolicExponent, 0.05e6); }},
      {"circulation.peripheral_resistance_mmhg_s_per_ml", "2",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.peripheralResistance, 2 * 133.322e6); }},
      {"circulation.arterial_compliance_ml_per_mmhg", "0.8",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.arterialCompliance, 0.8e-6 / 133.322); }},
      {"circulation.characteristic_impedance_mmhg_s_per_ml", "0.1",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.characteristicImpedance, 0.1 * 133.322e6); }},
      {"circulation.venous_pressure_mmhg", "3",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.systemicVenousPressure, 3 * 133.322); }},
      {"circulation.aortic_valve_area_cm2", "0.7",
       [](const Scenario& s) { return near(s.circulation.aorticValveArea, 0.7e-4); }},
      {"circulation.mitral_regurgitant_area_cm2", "0.3",
       [](const Scenario& s) { return near(s.circulation.lumpedParameters.mitralRegurgitantArea, 0.3e-4); }},
      {"circulation.atrial_contraction", "false", [](const Scenario& s) { return !s.circulation.atrialContraction; }},
      {"circulation.base_descent", "0.1",
       [](const Scenario& s) { return s.circulation.wallMotion.longitudinal == Real(0.1); }},
      {"circulation.radial_shortening", "0.2",
       [](const Scenario& s) { return s.circulation.wallMotion.radial == Real(0.2); }},
      {"motion.frames", "\"" + frames + "\"",
       [frames](const Scenario& s) { return s.motion.frames == frames && s.motion.frameSurfaces.size() == 2; }},
      {"motion.count", "3", [](const Scenario& s) { return s.motion.count == 3; }},
      {"motion.period", "0.9", [](const Scenario& s) { return s.motion.period == Real(0.9); }},
      {"output.vtk", "true", [](const Scenario& s) { return s.output.vtk; }},
      {"output.vtk_every", "3", [](const Scenario& s) { return s.output.vtkEvery == 3; }},
  };
}

TEST(ScenarioFile, EveryKeyRoundTripsThroughSet) {
  const std::vector<KeyCase> cases = everyKeyCase();
  std::set<std::string> covered;
  std::vector<std::string> all;
  for (const KeyCase& c : cases) {
    SCOPED_TRACE(c.key);
    covered.insert(c.key);
    std::vector<std::string> overrides = {c.key + "=" + c.value};
    if (c.key == "cycle.sphere.centre") overrides.push_back("cycle.sphere.radius=1");
    // A mesh heart needs its file (read as the scenario is) and beats without blood: its kind
    // round-trips here alone, with the biv-me endocardium, and stays out of the all-at-once set.
    // A recorded beat (motion.frames) needs such a heart, its frames and their count.
    const bool meshKind = c.key == "model.kind" || c.key == "motion.frames";
    if (meshKind) {
      if (c.key == "motion.frames") overrides.insert(overrides.end(), {"model.kind=\"mesh\"", "motion.count=2", "motion.period=0.8"});
      overrides.push_back("model.endocardium=" + kBivmeEndocardium);
      overrides.push_back("model.wall_thickness=0.01");  // heart-only's is the thesis's 0.5 m
    }
    const Scenario s = loadScenario("heart-only", overrides);
    EXPECT_TRUE(c.check(s));
    EXPECT_FALSE(c.check(loadScenario("heart-only"))) << "the case value equals the default";
    if (meshKind) {
      EXPECT_TRUE(c.check(parseScenario(scenarioToToml(s), "dump.toml")));
      continue;
    }
    all.push_back(overrides.front());
  }
  for (const ScenarioKeyInfo& k : scenarioKeys()) EXPECT_EQ(covered.count(k.name), 1u) << k.name;
  EXPECT_EQ(covered.size(), scenarioKeys().size());

  // All at once, then through scenarioToToml and back: nothing is lost.
  const Scenario s = loadScenario("heart-only", all);
  auto inAll = [](const KeyCase& c) { return c.key != "model.kind" && c.key != "motion.frames"; };
  for (const KeyCase& c : cases) EXPECT_TRUE(!inAll(c) || c.check(s)) << c.key;
  const std::string text = scenarioToToml(s);
  const Scenario back = parseScenario(text, "dump.toml");
  for (const KeyCase& c : cases) EXPECT_TRUE(!inAll(c) || c.check(back)) << c.key << "\n" << text;
  EXPECT_EQ(scenarioToToml(back), text);
}

TEST(ScenarioFile, SetAcceptsTablesAndSpacing) {
  const Scenario s =
      parseScenario("", "x.toml", {"cycle.sphere={centre=[1,2,3], radius=0.5}", " cycle.beats = 4 "});
  EXPECT_TRUE(s.cycle.sphereEnabled);
  EXPECT_EQ(s.cycle.sphereCentre, Vec3(1, 2, 3));
  EXPECT_EQ(s.cycle.sphereRadius, Real(0.5));
  EXPECT_EQ(s.cycle.beats, 4);
}

TEST(ScenarioFile, SphereTableEnablesTheSphereAndNeedsARadius) {
  const Scenario s = parseScenario("[cycle.sphere]\ncentre = [0, -1, 0]\nradius = 0.4\n", "x.toml");
  EXPECT_TRUE(s.cycle.sphereEnabled);
  EXPECT_EQ(s.cycle.sphereRadius, Real(0.4));
  expectParseError("[cycle.sphere]\ncentre = [0, -1, 0]\n", {"lesson.toml:1", "cycle.sphere.radius"});
}

TEST(ScenarioErrors, MissingFile) {
  const std::string msg = errorOf([] { loadScenario("no-such-lesson.toml"); });
  EXPECT_NE(msg.find("'no-such-lesson.toml'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("heart-only"), std::string::npos) << msg;  // lists the built-ins
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(ScenarioErrors, ErrorsInAFileNameTheFile) {
  const std::string path = writeTemp("bad-lesson.toml", "[simulation]\n\ndt = -1\n");
  const std::string msg = errorOf([&] { loadScenario(path); });
  EXPECT_NE(msg.find(path + ":3: simulation.dt:"), std::string::npos) << msg;
}

TEST(ScenarioErrors, MalformedToml) {
  expectParseError("[simulation]\ndt = 0.01\niterations = = 3\n", {"lesson.toml:3:", "TOML syntax error"});
}

TEST(ScenarioErrors, UnknownKey) {
  expectParseError("[cycle]\nmode = \"thesis\"\n\nbeat = 3\n",
                   {"lesson.toml:4: cycle.beat: unknown key", "did you mean cycle.beats?"});
  expectParseError("dt = 0.1\n", {"lesson.toml:1: dt: unknown key", "simulation.dt"});
  expectParseError("[simulation]\ndt = 0.01\n\"dt.x\" = 0.02\n",
                   {"lesson.toml:3: simulation.\"dt.x\": unknown key"});
  expectParseError("\"simulation.dt\" = 0.02\n", {"lesson.toml:1: \"simulation.dt\": unknown key"});
}

TEST(ScenarioErrors, UnknownTable) {
  expectParseError("[simulation]\ndt = 0.01\n[simulaton]\ndt = 0.01\n",
                   {"lesson.toml:3: simulaton: unknown table", "did you mean simulation?"});
  expectParseError("[cycle.sphere.inner]\nx = 1\n", {"lesson.toml:1", "cycle.sphere.inner"});
}

TEST(ScenarioErrors, KnownTableAsAValue) {
  expectParseError("cycle = 3\n", {"lesson.toml:1: cycle: expected a table"});
}

TEST(ScenarioErrors, WrongType) {
  expectParseError("[simulation]\niterations = 2.5\n",
                   {"lesson.toml:2: simulation.iterations: expected an integer", "got 2.5"});
  expectParseError("[blood]\nenabled = \"yes\"\n",
                   {"lesson.toml:2: blood.enabled: expected true or false, got \"yes\""});
  expectParseError("[simulation]\ngravity = [0, -9.81]\n", {"lesson.toml:2: simulation.gravity:"});
}

TEST(ScenarioErrors, NegativeNanAndInfiniteDt) {
  expectParseError("[simulation]\ndt = -0.01\n",
                   {"lesson.toml:2: simulation.dt: must be a finite number >= 1e-06 and <= 0.1", "(s), got -0.01"});
  expectParseError("[simulation]\ndt = 1e-45\n", {"lesson.toml:2: simulation.dt:", ">= 1e-06"});
  expectParseError("[simulation]\ndt = nan\n", {"lesson.toml:2: simulation.dt:", "got nan"});
  expectParseError("[simulation]\ndt = inf\n", {"lesson.toml:2: simulation.dt:", "got inf"});
  expectParseError("[simulation]\ndt = 0.2\n", {"lesson.toml:2: simulation.dt:", "<= 0.1"});
  expectParseError("[model]\nendo_radius = inf\n", {"lesson.toml:2: model.endo_radius:", "got inf"});
  expectParseError("[simulation]\ngravity = [0, nan, 0]\n", {"lesson.toml:2: simulation.gravity:", "nan"});
}

TEST(ScenarioErrors, ZeroIterations) {
  expectParseError("[simulation]\niterations = 0\n",
                   {"lesson.toml:2: simulation.iterations: must be an integer >= 1 and <= 1000, got 0"});
}

TEST(ScenarioErrors, SegmentOutOfRangeAndDuplicate) {
  expectParseError("[cycle]\nsegments = [18]\n", {"lesson.toml:2: cycle.segments:", "got 18"});
  expectParseError("[cycle]\nsegments = [\n  1,\n  7,\n  7,\n]\n",
                   {"lesson.toml:5: cycle.segments:", "duplicates", "7"});
  expectParseError("[cycle.inconsistent]\nsegments = [0]\n",
                   {"lesson.toml:2: cycle.inconsistent.segments:", "got 0"});
}

TEST(ScenarioErrors, BadModeString) {
  expectParseError("[cycle]\nmode = \"fast\"\n",
                   {"lesson.toml:2: cycle.mode: must be one of \"thesis\", \"physiological\", got \"fast\""});
}

TEST(ScenarioErrors, SetWithoutEquals) {
  expectParseError("", {"--set cycle.beats:", "KEY=VALUE"}, {"cycle.beats"});
  expectParseError("", {"--set =3:", "KEY=VALUE"}, {"=3"});
}

TEST(ScenarioErrors, SetUnknownKey) {
  expectParseError("", {"--set cycle.beat=3: cycle.beat: unknown key", "cycle.beats"}, {"cycle.beat=3"});
}

TEST(ScenarioErrors, SetBadValue) {
  expectParseError("", {"--set cycle.beats=abc: cycle.beats: expected an integer >= 0 and <= 2147483647, got 'abc'"},
                   {"cycle.beats=abc"});
  // An integer beyond its field's type names the real limit.
  expectParseError("", {"cycle.seed: must be an integer >= 0 and <= 4294967295, got 9223372036854775807"},
                   {"cycle.seed=9223372036854775807"});
  expectParseError("", {"--set simulation.dt=-1: simulation.dt: must be", "got -1"}, {"simulation.dt=-1"});
  expectParseError("", {"--set cycle.mode=fast: cycle.mode:", "got \"fast\""}, {"cycle.mode=fast"});
  expectParseError("", {"--set cycle.segments=[1,1]: cycle.segments:", "duplicates"},
                   {"cycle.segments=[1,1]"});
  // A second key smuggled into the value is not accepted.
  expectParseError("", {"--set cycle.beats=1", "cycle.beats: expected an integer"}, {"cycle.beats=1\ny = 2"});
}

TEST(ScenarioErrors, SetIsAppliedAfterTheFile) {
  const Scenario s = parseScenario("[cycle]\nbeats = 2\n", "x.toml", {"cycle.beats=5"});
  EXPECT_EQ(s.cycle.beats, 5);
}

// Settings under which the physics means nothing are refused before any work, naming the key
// and the bound.
TEST(ScenarioErrors, GravityTheBloodCannotHoldIsRefused) {
  expectParseError("", {"--set simulation.gravity=[0,-9.81,0]: simulation.gravity:", "expected |g| <= 0.1 spacing / dt^2"},
                   {"blood.enabled=true", "simulation.dt=0.1", "simulation.gravity=[0,-9.81,0]"});
  EXPECT_NO_THROW(loadScenario("normal", {"simulation.gravity=[0,-98.1,0]"}));  // 10 g still holds
}

// The thesis's beat moves a vertex cycle.beating_displace a step; past 0.45 of the wall's edge
// the tets invert, so a finer model (shorter edges) refuses heart-only's 0.08 m by name.
TEST(ScenarioErrors, ABeatStepLongerThanTheWallsEdgeIsRefused) {
  const std::string msg = errorOf([] { loadScenario("heart-only", {"model.resolution=8"}); });
  for (const char* piece : {"scenarios/heart-only.toml:", "cycle.beating_displace: 0.08 m per step",
                            "model.resolution", "= 0.0525 m"})
    EXPECT_NE(msg.find(piece), std::string::npos) << "missing '" << piece << "' in: " << msg;
  EXPECT_NO_THROW(loadScenario("heart-only", {"model.resolution=2"}));  // an edge of 0.21 m: up to 0.0945 m
  EXPECT_NO_THROW(loadScenario("heart-only", {"model.resolution=8", "cycle.beating_displace=0.023"}));
  // Another mode's beat does not use the key.
  EXPECT_NO_THROW(loadScenario("heart-only", {"model.resolution=8", "cycle.mode=physiological"}));
}

// Under half the spacing the wall holds particles closer than their lattice and blood leaks.
TEST(ScenarioErrors, ARadiusUnderHalfTheSpacingIsRefused) {
  expectParseError("", {"--set blood.radius=0.07: blood.radius: must be at least half blood.spacing (0.08 m)"},
                   {"blood.radius=0.07"});
  EXPECT_NO_THROW(parseScenario("", "lesson.toml", {"blood.radius=0.08"}));
}

TEST(ScenarioErrors, SupportRadiusBeyondTheBloodsRoomIsRefused) {
  expectParseError("", {"blood.support_radius: must not exceed the cavity's radius (model.endo_radius) (1 m)"},
                   {"blood.enabled=true", "model.endo_radius=1", "blood.support_radius=1.5"});
  expectParseError("", {"blood.support_radius: must not exceed the container's smallest side (1 m)"},
                   {"blood.enabled=true", "model.enabled=false", "container.enabled=true", "container.max=[1, 1, 0]",
                    "blood.support_radius=1.5"});
}

}  // namespace
}  // namespace hs::io
