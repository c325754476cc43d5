#include "run_command.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cardiac/beat_metrics.h"
#include "cardiac/heart_simulation.h"
#include "exit_codes.h"
#include "flow_report.h"
#include "io/scenario_file.h"
#include "io/vtk_writer.h"
#include "progress_bar.h"
#include "simulation_setup.h"

namespace hs::app {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string hex(std::uint64_t value) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
  return buffer;
}

io::VtuFrame wallFrame(const cardiac::HeartSimulation& sim) {
  const auto& model = sim.model();
  io::VtuFrame frame;
  frame.points.assign(sim.particles().position.begin(),
                      sim.particles().position.begin() + static_cast<std::ptrdiff_t>(model.mesh.vertices.size()));
  frame.tets = model.mesh.tets;
  std::vector<int> segment(model.segment.begin(), model.segment.end());
  std::vector<int> region;
  for (auto r : model.region) region.push_back(static_cast<int>(r));
  frame.intArrays = {{"aha_segment", segment}, {"region", region}};
  std::vector<pbd::Vec3> velocity(sim.particles().velocity.begin(),
                                  sim.particles().velocity.begin() + static_cast<std::ptrdiff_t>(frame.points.size()));
  std::vector<pbd::Vec3> displacement(frame.points.size());
  for (std::size_t i = 0; i < frame.points.size(); ++i) displacement[i] = frame.points[i] - model.mesh.vertices[i];
  frame.vectorArrays = {{"velocity", velocity}, {"displacement", displacement}};
  return frame;
}

const char* regionName(cardiac::Region region) {
  switch (region) {
    case cardiac::Region::Myocardium: return "myocardium";
    case cardiac::Region::BasePlate: return "base plate";
    case cardiac::Region::InflowVessel: return "inflow vessel";
    case cardiac::Region::OutflowVessel: return "outflow vessel";
  }
  return "?";
}

// "x, y, z m, <region>" of a model tet's first vertex, for error messages.
std::string tetLocation(const cardiac::HeartSimulation& sim, pbd::Index tet) {
  const pbd::Index v = sim.model().mesh.tets[tet][0];
  const pbd::Vec3& x = sim.particles().position[v];
  std::ostringstream s;
  s.precision(3);
  s << "x = " << x.x() << ", y = " << x.y() << ", z = " << x.z() << " m, ";
  if (sim.model().region[v] == cardiac::Region::Myocardium) s << "AHA segment " << int(sim.model().segment[v]);
  else s << regionName(sim.model().region[v]);
  return s.str();
}

// Running extremes and means over every step of the run.
struct RunStatistics {
  double volumeErrorMax = 0;
  double volumeErrorMeanSum = 0;  // sum over steps of the per-step mean
  std::size_t invertedTetsMax = 0;
  double cavityMin = INFINITY;
  double cavityMax = -INFINITY;
  // Blood: the density error over the last simulated second (issue: "over the last second").
  std::size_t bloodLostMax = 0;
  std::size_t bloodInsideWallMax = 0;
  double bloodSpeedMax = 0;
  double lastSecondFrom = 0;      // steps ending after this time count
  double densityErrorMeanSum = 0;
  double densityErrorMax = 0;
  std::size_t lastSecondSteps = 0;
};


// The wall's part of the JSON report: mesh, volume errors, cavity and beats.
void addHeartReport(nlohmann::ordered_json& report, const cardiac::HeartSimulation& sim, const RunStatistics& stats,
                    const cardiac::BeatTracker& beats, std::int64_t steps) {
  const cardiac::TissueStats finalTissue = sim.tissueStats();
  const pbd::MeshQuality quality = pbd::measureQuality(sim.model().mesh);
  const auto& model = sim.model();
  report["tissue"] = {
      {"vertices", model.mesh.vertices.size()},
      {"tets", model.mesh.tets.size()},
      {"surface_triangles", model.surface.size()},
      {"volume_error_max", stats.volumeErrorMax},
      {"volume_error_mean", steps > 0 ? stats.volumeErrorMeanSum / double(steps) : 0.0},
      {"inverted_tets", finalTissue.invertedTets},
      {"rest_deviation_final_rel", sim.restDeviationRelative()},
      {"min_dihedral_deg", quality.minDihedralDeg},
      {"max_aspect_ratio", quality.maxAspectRatio},
  };
  nlohmann::ordered_json beatList = nlohmann::json::array();
  for (const auto& b : beats.beats()) {
    beatList.push_back({{"beat", b.index},
                        {"start_s", b.startTime},
                        {"edv_ml", b.edv * 1e6},
                        {"esv_ml", b.esv * 1e6},
                        {"stroke_volume_ml", b.strokeVolume() * 1e6},
                        {"ejection_fraction", b.ejectionFraction()}});
  }
  report["cavity"] = {
      {"volume_rest_m3", cardiac::cavityVolume(model, model.mesh.vertices)},
      {"volume_min_m3", steps > 0 ? stats.cavityMin : sim.cavityVolume()},
      {"volume_max_m3", steps > 0 ? stats.cavityMax : sim.cavityVolume()},
      {"ejection_fraction", beats.meanEjectionFraction()},
      {"beats", beatList},
  };
  report["beats"] = beats.beats().size();
}

// Blood particles as a VTK point cloud with their velocities.
io::VtuFrame bloodFrame(const cardiac::HeartSimulation& sim) {
  io::VtuFrame frame;
  const auto first = static_cast<std::ptrdiff_t>(sim.firstBloodParticle());
  frame.points.assign(sim.particles().position.begin() + first, sim.particles().position.end());
  std::vector<pbd::Vec3> velocity(sim.particles().velocity.begin() + first, sim.particles().velocity.end());
  frame.vectorArrays = {{"velocity", velocity}};
  // 0: parked outside the model by the closed loop, waiting to re-enter (hide with a threshold).
  std::vector<int> active;
  for (std::size_t i = sim.firstBloodParticle(); i < sim.particles().size(); ++i)
    active.push_back(sim.bloodActive(pbd::Index(i)) ? 1 : 0);
  frame.intArrays = {{"active", active}};
  return frame;
}

}  // namespace

int runCommand(const RunOptions& options) {
  const auto setupStart = Clock::now();
  std::optional<cardiac::Scenario> loaded = loadScenarioOrReport(options.scenario, options.overrides);
  if (!loaded) return kExitBadInput;
  cardiac::Scenario scenario = *loaded;
  if (options.duration) {
    if (!std::isfinite(*options.duration) || *options.duration < 0) {
      std::cerr << "heartsim: error: --duration: must be a finite number >= 0 (s), got "
                << *options.duration << '\n';
      return kExitBadInput;
    }
    scenario.simulation.duration = static_cast<pbd::Real>(*options.duration);
  }
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  int setupError = kExitOk;
  const std::unique_ptr<cardiac::HeartSimulation> simPtr = makeSimulation(scenario, threads, options.scenario, setupError);
  if (!simPtr) return setupError;
  cardiac::HeartSimulation& sim = *simPtr;
  const double setupSeconds = secondsSince(setupStart);

  const fs::path outDir = options.outDir.empty() ? fs::path("results") / scenario.name : fs::path(options.outDir);
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) {
    std::cerr << "heartsim: error: " << outDir.string() << ": cannot create output directory: " << ec.message() << '\n';
    return kExitFailure;
  }
  std::ofstream csv(outDir / "metrics.csv");
  if (!csv) {
    std::cerr << "heartsim: error: " << (outDir / "metrics.csv").string() << ": cannot open for writing\n";
    return kExitFailure;
  }
  csv << "step,time_s,phase";
  if (sim.hasHeart())
    csv << ",cavity_volume_m3,cavity_volume_ml,volume_error_mean,volume_error_max,inverted_tets,rest_deviation_rel";
  if (sim.hasBlood())
    csv << ",blood_lost,blood_density_error_mean,blood_density_error_max,blood_max_speed_m_s,blood_inside_wall";
  if (sim.circulation()) writeFlowHeader(csv);
  csv << '\n';
  csv.precision(9);

  const bool vtk = options.vtk || scenario.output.vtk;
  // One ParaView series per body: wall_N.vtu (tets) and blood_N.vtu (points).
  io::PvdSeries wallSeries(outDir / "wall.pvd"), bloodSeries(outDir / "blood.pvd");
  auto writeFrame = [&](std::int64_t step) {
    const std::string suffix = "_" + std::to_string(step) + ".vtu";
    if (sim.hasHeart()) {
      io::writeVtu(outDir / ("wall" + suffix), wallFrame(sim));
      wallSeries.add(sim.time(), "wall" + suffix);
    }
    if (sim.hasBlood()) {
      io::writeVtu(outDir / ("blood" + suffix), bloodFrame(sim));
      bloodSeries.add(sim.time(), "blood" + suffix);
    }
  };

  const double dt = scenario.simulation.dt;
  const double stepCount = std::round(double(scenario.simulation.duration) / dt);
  constexpr double kMaxSteps = 1e9;
  if (stepCount > kMaxSteps) {
    std::cerr << "heartsim: error: " << options.scenario << ": simulation.duration / simulation.dt = " << stepCount
              << " steps, more than " << kMaxSteps << "; shorten the duration or lengthen dt\n";
    return kExitBadInput;
  }
  const auto steps = static_cast<std::int64_t>(stepCount);
  RunStatistics stats;
  stats.lastSecondFrom = double(steps) * dt - 1.0;
  cardiac::BeatTracker beats(sim.hasHeart() ? sim.cavityVolume() : 0.0, dt);
  ProgressBar progress(static_cast<long>(steps));
  double wallSeconds = 0;
  try {
    if (vtk) writeFrame(0);
    for (std::int64_t s = 0; s < steps; ++s) {
      const double startTime = sim.time();
      const auto stepStart = Clock::now();
      sim.step();
      wallSeconds += secondsSince(stepStart);

      const cardiac::TissueStats tissue = sim.tissueStats();
      const double cavity = sim.hasHeart() ? double(sim.cavityVolume()) : 0.0;
      if (!tissue.finite || !std::isfinite(cavity)) {
        progress.finish();
        std::cerr << "heartsim: error: simulation became invalid at step " << s + 1 << " (t = " << sim.time()
                  << " s): particle " << tissue.firstNonFinite << " has a non-finite position or velocity\n";
        return kExitInvalidSimulation;
      }
      if (tissue.invertedTets > 0) {
        progress.finish();
        std::cerr << "heartsim: error: simulation became invalid at step " << s + 1 << " (t = " << sim.time()
                  << " s): " << tissue.invertedTets << " wall tetrahedra inverted (first: tet "
                  << tissue.firstInvertedTet << " at " << tetLocation(sim, tissue.firstInvertedTet) << ")\n";
        return kExitInvalidSimulation;
      }
      csv << s + 1 << ',' << sim.time() << ',' << (sim.hasHeart() ? cardiac::phaseName(sim.lastPhase()) : "none");
      if (sim.hasHeart()) {
        stats.volumeErrorMax = std::max(stats.volumeErrorMax, double(tissue.volumeErrorMax));
        stats.volumeErrorMeanSum += double(tissue.volumeErrorMean);
        stats.cavityMin = std::min(stats.cavityMin, cavity);
        stats.cavityMax = std::max(stats.cavityMax, cavity);
        beats.record(startTime, sim.lastPhase(), cavity,
                     sim.circulation() ? sim.circulation()->meter.lastStepFlows() : cardiac::ValveFlows{});
        csv << ',' << cavity << ',' << cavity * 1e6 << ',' << tissue.volumeErrorMean << ','
            << tissue.volumeErrorMax << ',' << tissue.invertedTets << ',' << sim.restDeviationRelative();
      }
      if (sim.hasBlood()) {
        const cardiac::BloodStats blood = sim.bloodStats();
        stats.bloodLostMax = std::max(stats.bloodLostMax, blood.lost);
        stats.bloodInsideWallMax = std::max(stats.bloodInsideWallMax, blood.insideWall);
        stats.bloodSpeedMax = std::max(stats.bloodSpeedMax, blood.maxSpeed);
        if (sim.time() > stats.lastSecondFrom) {
          stats.densityErrorMeanSum += blood.densityErrorMean;
          stats.densityErrorMax = std::max(stats.densityErrorMax, blood.densityErrorMax);
          ++stats.lastSecondSteps;
        }
        csv << ',' << blood.lost << ',' << blood.densityErrorMean << ',' << blood.densityErrorMax << ','
            << blood.maxSpeed << ',' << blood.insideWall;
      }
      if (sim.circulation()) writeFlowRow(csv, *sim.circulation());
      csv << '\n';
      if (vtk && (s + 1) % scenario.output.vtkEvery == 0) writeFrame(s + 1);
      progress.update(static_cast<long>(s + 1), sim.time());
    }
    progress.finish();
    beats.finish();
    if (vtk && sim.hasHeart()) wallSeries.write();
    if (vtk && sim.hasBlood()) bloodSeries.write();
    csv.flush();
    if (!csv) throw std::runtime_error((outDir / "metrics.csv").string() + ": write failed (disk full?)");
  } catch (const std::runtime_error& e) {
    progress.finish();
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }

  nlohmann::ordered_json report;
  report["scenario"] = scenario.name;
  report["steps"] = steps;
  report["sim_time_s"] = sim.time();
  report["dt_s"] = dt;
  report["setup_s"] = setupSeconds;
  report["wall_s"] = wallSeconds;
  report["steps_per_s"] = wallSeconds > 0 ? double(steps) / wallSeconds : 0.0;
  report["threads"] = threads;
  report["iterations"] = scenario.simulation.iterations;
  report["state_hash"] = hex(pbd::stateHash(sim.particles()));
  if (sim.hasHeart()) {
    addHeartReport(report, sim, stats, beats, steps);
    report["heart"] = heartPumpReport(beats);
  }
  if (sim.hasBlood()) {
    const cardiac::BloodStats blood = sim.bloodStats();
    const double lastSecondMean =
        stats.lastSecondSteps > 0 ? stats.densityErrorMeanSum / double(stats.lastSecondSteps) : blood.densityErrorMean;
    report["blood"] = {
        {"particles", blood.particles},
        {"lost", std::max(stats.bloodLostMax, blood.lost)},
        {"inside_wall", std::max(stats.bloodInsideWallMax, blood.insideWall)},
        {"density_error_mean", lastSecondMean},
        {"density_error_max", stats.lastSecondSteps > 0 ? stats.densityErrorMax : blood.densityErrorMax},
        {"full_neighbourhood", blood.fullNeighbourhood},
        {"mean_neighbours", blood.meanNeighbours},
        {"max_speed_m_s", blood.maxSpeed},
        {"max_speed_run_m_s", std::max(stats.bloodSpeedMax, blood.maxSpeed)},
        {"iterations", scenario.blood.iterations},
    };
  }
  report["output_dir"] = outDir.string();

  std::ofstream summary(outDir / "summary.json");
  summary << report.dump(2) << '\n';
  if (!summary) {
    std::cerr << "heartsim: error: " << (outDir / "summary.json").string() << ": write failed\n";
    return kExitFailure;
  }
  if (options.json) {
    std::cout << report.dump() << std::endl;
  } else {
    std::cerr << "heartsim: " << scenario.name << ": " << steps << " steps in " << wallSeconds << " s ("
              << report["steps_per_s"].get<double>() << " steps/s, " << threads << " threads)";
    if (sim.hasHeart())
      std::cerr << "; EF " << beats.meanEjectionFraction() << " over " << beats.beats().size() << " beats";
    if (const cardiac::BeatMeans m = beats.means(); m.count > 0) {
      // The pump in clinical units (m^3 at the thesis's scale), as the means over the complete
      // beats after the first.
      const cardiac::VolumeScale u = cardiac::volumeScaleFor(m.edv);
      char pump[200];
      std::snprintf(pump, sizeof pump, "stroke volume %.3g %s, cardiac output %.3g %s, regurgitation %.2g %s",
                    m.strokeVolume * u.volume, u.volumeUnit, m.cardiacOutput * u.output, u.outputUnit,
                    m.regurgitantVolume * u.volume, u.volumeUnit);
      std::cerr << "; " << pump;
    }
    if (sim.hasBlood())
      std::cerr << "; " << report["blood"]["particles"].get<std::size_t>() << " blood particles, "
                << report["blood"]["lost"].get<std::size_t>() << " lost, "
                << report["blood"]["inside_wall"].get<std::size_t>() << " inside the wall, density error "
                << report["blood"]["density_error_mean"].get<double>();
    std::cerr << "; results in " << outDir.string() << '\n';
  }
  return kExitOk;
}

}  // namespace hs::app
