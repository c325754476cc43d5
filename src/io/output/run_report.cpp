#include "io/output/run_report.h"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace hs::io {
namespace {

// mL and L/min (cardiac::VolumeScale's clinical units), whatever the model's size: the keys
// say so.
constexpr cardiac::VolumeScale kClinical{};

std::string hex(std::uint64_t value) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
  return buffer;
}

// The lumped circulation's figures in clinical units: means over the complete beats after the
// first (null without one, and e_to_a null where a beat had no A wave), and over the whole run
// how the 3D heart followed it.
void addCirculationReport(nlohmann::ordered_json& heart, const cardiac::CirculationRecorder& recorder) {
  const cardiac::CoupledMeans m = recorder.means();
  const bool measured = m.count > 0;
  auto figure = [measured](double value) { return measured ? nlohmann::ordered_json(value) : nlohmann::ordered_json(); };
  constexpr double mmHg = cardiac::kPascalPerMmHg;
  heart["aortic_systolic_mmhg"] = figure(m.aorticSystolic / mmHg);
  heart["aortic_diastolic_mmhg"] = figure(m.aorticDiastolic / mmHg);
  heart["lv_peak_mmhg"] = figure(m.lvPeak / mmHg);
  heart["lv_end_diastolic_mmhg"] = figure(m.lvEndDiastolic / mmHg);
  heart["isovolumic_contraction_ms"] = figure(m.isovolumicContraction * 1e3);
  heart["isovolumic_relaxation_ms"] = figure(m.isovolumicRelaxation * 1e3);
  heart["e_to_a"] = measured && m.eToA ? nlohmann::ordered_json(*m.eToA) : nlohmann::ordered_json();
  heart["regurgitant_fraction"] = figure(m.regurgitantFraction);
  heart["aortic_mean_gradient_mmhg"] = figure(m.aorticMeanGradient / mmHg);
  // The fastest single particle through the aortic disc (FlowStep::aorticJet): PBF's particle
  // noise rides on it, so it is not what echocardiography reads; aortic_peak_velocity_m_s is.
  heart["aortic_peak_jet_m_s"] = figure(m.aorticJet);
  heart["lumped_stroke_volume_ml"] = figure(m.strokeVolume * kClinical.volume);
  heart["both_valves_open_steps"] = recorder.bothValvesOpenSteps();
  heart["cavity_volume_error_max"] = recorder.cavityVolumeErrorMax();
  heart["cavity_volume_step_max_ml"] = recorder.cavityStepMax() * kClinical.volume;
  const std::optional<double> flowError = recorder.aorticFlowErrorMax();
  heart["aortic_flow_error_max"] = flowError ? nlohmann::ordered_json(*flowError) : nlohmann::ordered_json();
  heart["vessel_fill_min"] = recorder.vesselFillMin();
  // Beat by beat, so a rhythm's differences show (irregular intervals, inconsistent pressures).
  nlohmann::ordered_json beats = nlohmann::json::array();
  for (const cardiac::CoupledBeat& b : recorder.beats()) {
    beats.push_back({{"beat", b.index},
                     {"start_s", b.startTime},
                     {"duration_s", b.duration},
                     {"complete", b.complete},
                     {"aortic_systolic_mmhg", b.lumped.aorticSystolic / mmHg},
                     {"aortic_diastolic_mmhg", b.lumped.aorticDiastolic / mmHg},
                     {"lumped_stroke_volume_ml", b.lumped.forwardStrokeVolume * kClinical.volume},
                     {"aortic_3d_ml", b.aorticNet3d * kClinical.volume}});
  }
  heart["lumped_beats"] = beats;
}

// The blood's own figures, as 4D-flow MRI reads them (cardiac/blood/ventricle_blood.h): each
// beat's flow components (fractions of the blood in the ventricle at end-diastole) and each
// cycle's kinetic energy, and their means over the beats after the first two (null before).
void addVentricleBloodReport(nlohmann::ordered_json& heart, const cardiac::VentricleBlood& blood,
                             const cardiac::BeatTracker& wallBeats) {
  constexpr std::size_t kSkipped = 2;  // the first beats, while the blood settles into its path
  auto shares = [](const cardiac::FlowComponents& c) {
    return nlohmann::ordered_json{{"direct", c.direct},
                                  {"retained_inflow", c.retainedInflow},
                                  {"delayed_ejection", c.delayedEjection},
                                  {"residual", c.residual}};
  };
  nlohmann::ordered_json beats = nlohmann::json::array();
  for (const cardiac::BeatFlowComponents& b : blood.beats()) {
    nlohmann::ordered_json beat = shares(b.shares);
    beat["end_diastole_s"] = b.endDiastole;
    beat["mean_residence_beats"] = b.shares.meanResidenceBeats;
    beat["stayed_over_3_beats"] = b.shares.stayedOverThreeBeats;
    beats.push_back(beat);
  }
  nlohmann::ordered_json components = nullptr;
  if (const std::optional<cardiac::FlowComponents> mean = cardiac::meanFlowComponents(blood.beats(), kSkipped)) {
    components = shares(*mean);
    heart["mean_residence_beats"] = mean->meanResidenceBeats;
    heart["stayed_over_3_beats"] = mean->stayedOverThreeBeats;
  }
  heart["flow_components"] = components;
  heart["flow_component_beats"] = beats;
  // Kinetic energy per mL of end-diastolic volume: the cycles' time means over the mean EDV of
  // the wall's beats, both after the first two.
  double energy = 0, peak = 0, edv = 0;
  std::size_t cycles = 0, edvBeats = 0;
  for (std::size_t k = kSkipped; k < blood.cycles().size(); ++k, ++cycles) {
    energy += blood.cycles()[k].mean;
    peak += blood.cycles()[k].fillingPeak;
  }
  for (std::size_t k = kSkipped; k < wallBeats.beats().size(); ++k)
    if (wallBeats.beats()[k].complete) edv += wallBeats.beats()[k].edv, ++edvBeats;
  const bool measured = cycles > 0 && edvBeats > 0 && edv > 0;
  const double perMl = measured ? 1e6 / (edv / double(edvBeats) * kClinical.volume) : 0.0;
  heart["kinetic_energy_uj_per_ml"] = measured ? nlohmann::ordered_json(energy / double(cycles) * perMl) : nullptr;
  heart["kinetic_energy_filling_peak_uj_per_ml"] =
      measured ? nlohmann::ordered_json(peak / double(cycles) * perMl) : nullptr;
}

// The Doppler peaks in the orifices (cardiac/blood/echo_velocities.h), cycle by cycle (end-diastole
// to end-diastole) and their means over the cycles after the first two, in m/s: the aortic peak
// in ejection, the mitral E before the atrial kick and A during it (null in a cycle without one;
// the mean over the cycles with one, null if none had).
void addEchoReport(nlohmann::ordered_json& heart, const cardiac::EchoVelocities& echo) {
  constexpr std::size_t kSkipped = 2;  // as the flow components: the blood settles into its path
  nlohmann::ordered_json beats = nlohmann::json::array();
  double aortic = 0, e = 0, a = 0;
  std::size_t counted = 0, withA = 0;
  for (std::size_t k = 0; k < echo.cycles().size(); ++k) {
    const cardiac::CycleEcho& c = echo.cycles()[k];
    beats.push_back({{"start_s", c.start},
                     {"end_s", c.end},
                     {"aortic_peak_velocity_m_s", c.aorticPeak},
                     {"mitral_e_m_s", c.mitralE},
                     {"mitral_a_m_s", c.mitralA ? nlohmann::ordered_json(*c.mitralA) : nlohmann::ordered_json()}});
    if (k < kSkipped) continue;
    ++counted;
    aortic += c.aorticPeak, e += c.mitralE;
    if (c.mitralA) a += *c.mitralA, ++withA;
  }
  auto mean = [](double sum, std::size_t n) { return n > 0 ? nlohmann::ordered_json(sum / double(n)) : nlohmann::ordered_json(); };
  heart["aortic_peak_velocity_m_s"] = mean(aortic, counted);
  heart["mitral_e_m_s"] = mean(e, counted);
  heart["mitral_a_m_s"] = mean(a, withA);
  heart["echo_beats"] = beats;
}

// The E-wave filling vortex (cardiac/blood/filling_vortex.h): each beat's reading at its E peak,
// and the means over the complete beats after the first two in which a ring was found (null
// before). The position is a share of the long axis from the mitral plane (Elbaz et al. 2014:
// 0.19 +/- 0.04 in healthy subjects).
void addFillingVortexReport(nlohmann::ordered_json& heart, const cardiac::FillingVortex& vortex) {
  constexpr int kSkipped = 2;
  nlohmann::ordered_json beats = nlohmann::json::array();
  double position = 0, circulation = 0;
  std::size_t counted = 0;
  for (const cardiac::EVortexBeat& b : vortex.beats()) {
    const cardiac::EVortexSample& s = b.sample;
    auto figure = [&s](double value) { return s.found ? nlohmann::ordered_json(value) : nlohmann::ordered_json(); };
    beats.push_back({{"beat", b.beat},
                     {"complete", b.complete},
                     {"e_peak_s", s.time},
                     {"mitral_flow_ml_s", s.mitralFlow * kClinical.volume},
                     {"found", s.found},
                     {"position", figure(s.position)},
                     {"depth_mm", figure(s.depth * 1e3)},
                     {"long_axis_mm", s.longAxis * 1e3},
                     {"circulation_m2_s", figure(s.circulation)},
                     {"cores", {{"clockwise_depth_mm", s.coreDepth[0] * 1e3},
                                {"clockwise_circulation_m2_s", s.coreCirculation[0]},
                                {"anticlockwise_depth_mm", s.coreDepth[1] * 1e3},
                                {"anticlockwise_circulation_m2_s", s.coreCirculation[1]}}}});
    if (b.beat <= kSkipped || !b.complete || !s.found) continue;
    position += s.position;
    circulation += s.circulation;
    ++counted;
  }
  const bool measured = counted > 0;
  heart["e_vortex_position"] = measured ? nlohmann::ordered_json(position / double(counted)) : nullptr;
  heart["e_vortex_circulation_m2_s"] = measured ? nlohmann::ordered_json(circulation / double(counted)) : nullptr;
  heart["e_vortex_beats"] = beats;
}

// The wall's part: mesh, volume errors, cavity and beats.
// [motion]: the recorded beat's own volumes beside the 3D heart's (null without a recording).
nlohmann::ordered_json motionReport(const cardiac::RunSummary& run) {
  const std::vector<double>& v = run.motionFrameVolumes;
  if (v.empty()) return nullptr;
  const auto [smallest, largest] = std::minmax_element(v.begin(), v.end());
  return {{"frames", v.size()},
          {"period_s", run.motionPeriod},
          {"recorded_edv_ml", *largest * kClinical.volume},
          {"recorded_esv_ml", *smallest * kClinical.volume},
          {"recorded_ejection_fraction", (*largest - *smallest) / *largest},
          {"volume_error_max", run.motionVolumeErrorMax}};
}

void addHeartReport(nlohmann::ordered_json& report, const cardiac::RunSummary& run) {
  report["tissue"] = {
      {"vertices", run.vertices},
      {"tets", run.tets},
      {"surface_triangles", run.surfaceTriangles},
      {"volume_error_max", run.volumeErrorMax},
      {"volume_error_mean", run.volumeErrorMean},
      // The shape held (docs/reliability.md): the worst tet's volume change over the run (the
      // same figure as volume_error_max, by the name the anatomy's checks use) and the surface's
      // largest bend from rest, where a crease shows.
      {"worst_tet_volume_error", run.volumeErrorMax},
      {"surface_turn_max_deg", run.surfaceTurnMax * 180 / std::numbers::pi},
      // Two-way coupling: the cavity the blood's push moved in one step, largest and mean (mL);
      // null without it.
      {"moved_by_blood_ml_max", run.twoWay ? nlohmann::ordered_json(run.bloodPushMax * 1e6) : nlohmann::ordered_json()},
      {"moved_by_blood_ml_mean", run.twoWay ? nlohmann::ordered_json(run.bloodPushMean * 1e6) : nlohmann::ordered_json()},
      {"inverted_tets", run.invertedTets},
      {"rest_deviation_final_rel", run.restDeviation},
      {"min_dihedral_deg", run.minDihedralDeg},
      {"max_aspect_ratio", run.maxAspectRatio},
  };
  nlohmann::ordered_json beatList = nlohmann::json::array();
  for (const auto& b : run.beats.beats()) {
    beatList.push_back({{"beat", b.index},
                        {"start_s", b.startTime},
                        {"edv_ml", b.edv * 1e6},
                        {"esv_ml", b.esv * 1e6},
                        {"stroke_volume_ml", b.strokeVolume() * 1e6},
                        {"ejection_fraction", b.ejectionFraction()}});
  }
  report["cavity"] = {
      {"volume_rest_m3", run.restCavity},
      {"volume_min_m3", run.cavityMin},
      {"volume_max_m3", run.cavityMax},
      {"ejection_fraction", run.beats.beats().empty() ? nlohmann::ordered_json()
                                                      : nlohmann::ordered_json(run.beats.meanEjectionFraction())},
      {"beats", beatList},
  };
  report["beats"] = run.beats.beats().size();
  report["heart"] = heartPumpReport(run.beats);
  if (run.circulation) addCirculationReport(report["heart"], *run.circulation);
  if (run.ventricleBlood) addVentricleBloodReport(report["heart"], *run.ventricleBlood, run.beats);
  if (run.echo) addEchoReport(report["heart"], *run.echo);
  if (run.fillingVortex) addFillingVortexReport(report["heart"], *run.fillingVortex);
  report["motion"] = motionReport(run);
}

nlohmann::ordered_json bloodReport(const cardiac::RunSummary& run, int iterations) {
  const cardiac::BloodStats& b = run.bloodFinal;
  return {
      {"particles", b.particles},
      {"lost", run.bloodLost},
      {"inside_wall", run.bloodInsideWall},
      {"density_error_mean", run.densityErrorMean},
      {"density_error_max", run.densityErrorMax},
      {"full_neighbourhood", b.fullNeighbourhood},
      {"mean_neighbours", b.meanNeighbours},
      {"max_speed_m_s", b.maxSpeed},
      {"max_speed_run_m_s", run.bloodSpeedMax},
      // The smoothed field's largest speed over the run (with a circulation; 0 otherwise): the
      // hottest colour the viewer's and `render`'s speed scale shows.
      {"smoothed_speed_max_run_m_s", run.smoothedSpeedMax},
      {"iterations", iterations},
  };
}

}  // namespace

nlohmann::ordered_json heartPumpReport(const cardiac::BeatTracker& beats) {
  const cardiac::BeatMeans m = beats.means();
  // With no complete beat to average nothing was measured: null, never a 0 that reads as an
  // empty heart.
  const bool measured = m.count > 0;
  auto figure = [measured](double value) { return measured ? nlohmann::ordered_json(value) : nlohmann::ordered_json(); };
  return {{"beats", beats.beats().size()},
          {"beats_averaged", m.count},
          {"edv_ml", figure(m.edv * kClinical.volume)},
          {"esv_ml", figure(m.esv * kClinical.volume)},
          {"stroke_volume_ml", figure(m.strokeVolume * kClinical.volume)},
          {"ejection_fraction", figure(m.ejectionFraction)},
          {"cardiac_output_l_min", figure(m.cardiacOutput * kClinical.output)},
          {"regurgitant_volume_ml", figure(m.regurgitantVolume * kClinical.volume)},
          {"aortic_net_forward_ml", figure(m.aorticNet * kClinical.volume)}};
}

nlohmann::ordered_json anatomyReport(const cardiac::AnatomyFigures& anatomy) {
  const auto& root = anatomy.aorticRootDiameter;
  return {{"mitral_area_cm2", anatomy.mitralArea * 1e4},
          {"aortic_area_cm2", anatomy.aorticArea * 1e4},
          {"aortic_root_diameter_mm", root ? nlohmann::ordered_json(*root * 1e3) : nlohmann::ordered_json()},
          {"long_axis_mm", anatomy.longAxis * 1e3}};
}

nlohmann::ordered_json runReport(const cardiac::Scenario& scenario, const RunTiming& timing,
                                 const cardiac::RunSummary& run, const std::string& outputDir,
                                 const cardiac::AnatomyFigures* anatomy) {
  nlohmann::ordered_json report;
  report["scenario"] = scenario.name;
  report["steps"] = run.steps;
  report["sim_time_s"] = run.time;
  report["dt_s"] = double(scenario.simulation.dt);
  report["setup_s"] = timing.setupSeconds;
  report["wall_s"] = timing.wallSeconds;
  report["steps_per_s"] = timing.stepsPerSecond(run.steps);
  report["threads"] = timing.threads;
  report["iterations"] = scenario.simulation.iterations;
  report["state_hash"] = hex(run.stateHash);
  if (anatomy) report["model"] = anatomyReport(*anatomy);
  if (run.heart) addHeartReport(report, run);
  if (run.blood) report["blood"] = bloodReport(run, scenario.blood.iterations);
  report["output_dir"] = outputDir;
  return report;
}

std::string runSummaryLine(const cardiac::Scenario& scenario, const RunTiming& timing,
                           const cardiac::RunSummary& run, const std::string& outputDir) {
  std::ostringstream s;
  s << scenario.name << ": " << run.steps << " steps in " << timing.wallSeconds << " s ("
    << timing.stepsPerSecond(run.steps) << " steps/s, " << timing.threads << " threads)";
  if (run.heart && run.beats.beats().empty()) s << "; EF n/a (no beat)";
  else if (run.heart) s << "; EF " << run.beats.meanEjectionFraction() << " over " << run.beats.beats().size() << " beats";
  if (const cardiac::BeatMeans m = run.beats.means(); m.count > 0) {
    // The pump in clinical units (m^3 at the thesis's scale), as the means over the complete
    // beats after the first.
    const cardiac::VolumeScale u = cardiac::volumeScaleFor(m.edv);
    char pump[200];
    std::snprintf(pump, sizeof pump, "stroke volume %.3g %s, cardiac output %.3g %s, regurgitation %.2g %s",
                  m.strokeVolume * u.volume, u.volumeUnit, m.cardiacOutput * u.output, u.outputUnit,
                  m.regurgitantVolume * u.volume, u.volumeUnit);
    s << "; " << pump;
  }
  if (run.circulation) {
    if (const cardiac::CoupledMeans c = run.circulation->means(); c.count > 0) {
      char pressures[120];
      std::snprintf(pressures, sizeof pressures, "aortic pressure %.0f/%.0f mmHg, LV peak %.0f mmHg",
                    c.aorticSystolic / cardiac::kPascalPerMmHg, c.aorticDiastolic / cardiac::kPascalPerMmHg,
                    c.lvPeak / cardiac::kPascalPerMmHg);
      s << "; " << pressures;
    }
    // The 3D wall holds the lumped volume within 3% (CliLumped's bound) unless its contraction
    // ran out (docs/scenarios.md, circulation.radial_shortening): then its figures are not the
    // lumped heart's, and the line says so rather than let them pass as one heart's.
    if (const double miss = run.circulation->cavityVolumeErrorMax(); miss > 0.03) {
      char warning[200];
      std::snprintf(warning, sizeof warning,
                    "; warning: the 3D wall missed the lumped volume by up to %.0f%% (its contraction reached its "
                    "limit), so its EF and volumes are not the lumped heart's",
                    100 * miss);
      s << warning;
    }
  }
  if (run.blood)
    s << "; " << run.bloodFinal.particles << " blood particles, " << run.bloodLost << " lost, " << run.bloodInsideWall
      << " inside the wall, density error " << run.densityErrorMean;
  s << "; results in " << outputDir;
  return s.str();
}

}  // namespace hs::io
