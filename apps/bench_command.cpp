#include "bench_command.h"

#include <omp.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "exit_codes.h"
#include "io/scenario/scenario_file.h"
#include "simulation_setup.h"

namespace hs::app {
namespace {

using Clock = std::chrono::steady_clock;

// A case whose simulation failed a health check (cardiac::RunMonitor): exit 3, as `run`.
struct InvalidSimulation : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The monitor's checks on the state after a timed stretch, so that a benchmark of a broken
// simulation reports the failure instead of its speed; outside the timing.
void checkHealth(cardiac::RunMonitor& monitor) {
  if (const cardiac::Verdict& verdict = monitor.checkNow(); !verdict.healthy())
    throw InvalidSimulation(verdict.message());
}

struct BenchCase {
  std::string name;
  std::string description;
  // Builds the workload; returns a function that advances one step, and the particle count.
  std::function<nlohmann::json(int threads, double seconds)> run;
};

// Blood particles in the flow (not waiting in the body or parked): the ones a step works on.
std::size_t activeBlood(const cardiac::HeartSimulation& sim) {
  const pbd::Particles& p = sim.particles();
  std::size_t active = 0;
  for (std::size_t i = sim.firstBloodParticle(); i < p.size(); ++i) active += p.active(i) ? 1 : 0;
  return active;
}

// Steps a simulation for at least `seconds` after a warm-up, in windows of about 0.2 s, and
// reports the median window's throughput (a shared machine's hiccups land in a few windows;
// the median ignores them) with the slowest and fastest windows beside it, and the blood
// particles in the flow, counted at the end of each window outside its timing.
nlohmann::json measure(cardiac::HeartSimulation& sim, std::size_t particles, int threads, double seconds,
                       cardiac::StepProfile* profile = nullptr) {
  cardiac::RunMonitor monitor(sim, cardiac::MonitorSettings::healthOnly());
  for (int i = 0; i < 50; ++i) sim.step();  // warm-up: caches, first-touch, lazy allocation
  if (profile) *profile = {};
  const std::int64_t reducedBefore = sim.threadGovernor().reducedSteps();
  long steps = 0;
  std::vector<double> windowRates;
  double activeSum = 0;
  const auto start = Clock::now();
  double elapsed = 0;
  while (elapsed < seconds || windowRates.size() < 5) {
    const auto windowStart = Clock::now();
    long windowSteps = 0;
    double window = 0;
    while (window < 0.2) {
      for (int i = 0; i < 10; ++i) sim.step();
      windowSteps += 10;
      window = std::chrono::duration<double>(Clock::now() - windowStart).count();
    }
    windowRates.push_back(double(windowSteps) / window);
    activeSum += double(activeBlood(sim));
    checkHealth(monitor);
    steps += windowSteps;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  std::sort(windowRates.begin(), windowRates.end());
  const double stepsPerSecond = windowRates[windowRates.size() / 2];
  const double active = activeSum / double(windowRates.size());
  return {{"steps_per_s", stepsPerSecond},
          {"ns_per_particle_step", 1e9 / (stepsPerSecond * double(particles))},
          {"particles", particles},
          {"active_particles_mean", active},
          {"ns_per_active_particle_step", 1e9 / (stepsPerSecond * std::max(active, 1.0))},
          {"threads", threads},
          // The thread governor's choice (pbd/core/thread_governor.h): the measured steps that
          // ran on fewer threads than allowed, as a share (its probes' and, on a busy machine,
          // its holds').
          {"fewer_threads_share",
           double(sim.threadGovernor().reducedSteps() - reducedBefore) / double(std::max(1L, steps))},
          {"steps", steps},
          {"seconds", elapsed},
          {"steps_per_s_min", windowRates.front()},
          {"steps_per_s_max", windowRates.back()},
          {"windows", windowRates.size()}};
}

// A thesis-scale dam break (Table 5.2: radius 0.08 m, spacing 2 radii, support 4 radii;
// dt = 0.005 s, 4 iterations): a column of nx x ny x nz particles against the left wall of a
// tank four columns long, released at t = 0.
cardiac::Scenario damBreakScenario(int nx, int ny, int nz) {
  cardiac::Scenario s;
  s.name = "pbf-dam-break";
  s.heart = false;
  s.cycle.enabled = false;
  s.simulation.dt = pbd::Real(0.005);
  cardiac::BloodSettings& b = s.blood;
  b.enabled = true;
  b.particles = 0;
  b.radius = pbd::Real(0.08);
  b.spacing = 2 * b.radius;
  b.supportRadius = 4 * b.radius;
  b.iterations = 4;
  b.blockMin = pbd::Vec3::Zero();
  b.blockMax = b.spacing * pbd::Vec3(pbd::Real(nx), pbd::Real(ny), pbd::Real(nz));
  s.container.enabled = true;
  s.container.min = pbd::Vec3::Zero();
  s.container.max = b.spacing * pbd::Vec3(pbd::Real(4 * nx), pbd::Real(ny + 4), pbd::Real(nz));
  return s;
}

BenchCase damBreakCase(const std::string& name, int nx, int ny, int nz) {
  const std::string count = std::to_string(nx * ny * nz);
  return {name,
          "PBF dam break, " + count + " particles (" + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
              std::to_string(nz) + "), thesis constants, 4 iterations, dt 5 ms",
          [nx, ny, nz](int threads, double seconds) {
            const cardiac::Scenario scenario = damBreakScenario(nx, ny, nz);
            cardiac::HeartSimulation sim(scenario, threads);
            nlohmann::json r = measure(sim, sim.particles().size(), threads, seconds);
            r["iterations"] = scenario.blood.iterations;  // density solver iterations per step
            return r;
          }};
}

// A built-in scenario run from t = 0 to its end, as `heartsim run` steps it (the per-step
// metrics and files left out): three fresh runs, the median's wall time. This is the figure
// to set beside the thesis's Table 5.5 ("computational time" of its 400-step experiments).
// A real-size heart with its blood, stepped as the viewer steps it (health checks, no files):
// the median window's steps per second, and the mean wall time of each stage of a step
// (cardiac::StepStage) over all measured steps, in milliseconds.
BenchCase heartCase(const std::string& name, cardiac::BloodResolution level) {
  return {name, "the " + name + " scenario stepped for the measuring time, with each stage's time per step",
          [name, level](int threads, double seconds) {
            cardiac::Scenario scenario = io::loadScenario(name);
            cardiac::applyResolution(level, scenario);
            cardiac::HeartSimulation sim(scenario, threads);
            cardiac::StepProfile profile;
            sim.attachProfile(&profile);
            const std::size_t blood = sim.particles().size() - sim.firstBloodParticle();
            nlohmann::json r = measure(sim, blood, threads, seconds, &profile);
            nlohmann::json stages = nlohmann::json::object();
            double total = 0;
            for (std::size_t k = 0; k < profile.seconds.size(); ++k) {
              const double ms = 1e3 * profile.seconds[k] / double(std::max(1L, profile.steps));
              stages[std::string(cardiac::kStepStageNames[k])] = ms;
              total += ms;
            }
            r["stages_ms_per_step"] = stages;
            r["stages_ms_total"] = total;
            r["iterations"] = scenario.blood.iterations;
            r["resolution"] = cardiac::resolutionName(level);
            r["dt_s"] = scenario.simulation.dt;
            r["real_time_factor"] = r["steps_per_s"].get<double>() * double(scenario.simulation.dt);
            return r;
          }};
}

BenchCase scenarioCase(const std::string& name, cardiac::BloodResolution level) {
  return {name, "the " + name + " scenario from t = 0 to its end (median of 3 fresh runs)",
          [name, level](int threads, double) {
            cardiac::Scenario scenario = io::loadScenario(name);
            cardiac::applyResolution(level, scenario);
            const auto steps = static_cast<long>(std::round(double(scenario.simulation.duration) /
                                                            double(scenario.simulation.dt)));
            std::vector<double> times;
            std::size_t particles = 0;
            for (int run = 0; run < 3; ++run) {
              cardiac::HeartSimulation sim(scenario, threads);
              cardiac::RunMonitor monitor(sim, cardiac::MonitorSettings::healthOnly());
              particles = sim.particles().size();
              const auto start = Clock::now();
              for (long k = 0; k < steps; ++k) sim.step();
              times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
              checkHealth(monitor);
            }
            std::sort(times.begin(), times.end());
            const double seconds = times[1];
            return nlohmann::json{{"steps_per_s", double(steps) / seconds},
                                  {"ns_per_particle_step", 1e9 * seconds / (double(steps) * double(particles))},
                                  {"particles", particles},
                                  {"threads", threads},
                                  {"iterations", scenario.blood.iterations},
                                  {"resolution", cardiac::resolutionName(level)},
                                  {"seconds", seconds},
                                  {"steps", steps},
                                  {"seconds_min", times.front()},
                                  {"seconds_max", times.back()},
                                  {"simulated_s", double(steps) * double(scenario.simulation.dt)}};
          }};
}

// The named scenarios' blood at `level` (--resolution); the dam breaks keep the counts their
// names give, and tissue-lv has no blood.
std::vector<BenchCase> allCases(cardiac::BloodResolution level = cardiac::kScenarioResolution) {
  return {
      scenarioCase("paper-vessel", level),
      scenarioCase("paper-vessel-beating", level),
      scenarioCase("paper-chamber", level),
      scenarioCase("paper-chamber-beating", level),
      heartCase("normal", level),
      heartCase("irregular", level),
      heartCase("inconsistent", level),
      heartCase("patient-biv-me", level),
      heartCase("idealized-lv", level),
      damBreakCase("pbf-dam-break-1k", 10, 20, 5),
      damBreakCase("pbf-dam-break-10k", 25, 40, 10),
      damBreakCase("pbf-dam-break-100k", 50, 80, 25),
      {"tissue-lv", "heart-only scenario: default LV beating in thesis mode, no blood",
       [](int threads, double seconds) {
         cardiac::Scenario scenario = io::loadScenario("heart-only");
         cardiac::HeartSimulation sim(scenario, threads);
         nlohmann::json r = measure(sim, sim.particles().size(), threads, seconds);
         r["iterations"] = scenario.simulation.iterations;  // solver iterations per step
         r["volume_passes"] = scenario.simulation.volumePasses;
         r["tets"] = sim.model().mesh.tets.size();
         return r;
       }},
  };
}

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// Runs one case in a forked child; the child writes its JSON result to a pipe.
nlohmann::ordered_json runIsolated(const BenchCase& c, int threads, double seconds) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("bench: pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("bench: fork failed");
  if (pid == 0) {
    close(fds[0]);
    nlohmann::json r;
    try {
      r = c.run(threads, seconds);
    } catch (const InvalidSimulation& e) {
      r = {{"invalid", e.what()}};
    }
    r["name"] = c.name;
    r["description"] = c.description;
    r["peak_rss_mb"] = peakRssMb();
    const std::string text = r.dump();
    const ssize_t written = write(fds[1], text.data(), text.size());
    close(fds[1]);
    _exit(written == static_cast<ssize_t>(text.size()) ? 0 : 1);
  }
  close(fds[1]);
  std::string text;
  char buffer[4096];
  ssize_t n;
  while ((n = read(fds[0], buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty())
    throw std::runtime_error("bench: case '" + c.name + "' failed");
  nlohmann::ordered_json ordered;
  const nlohmann::json parsed = nlohmann::json::parse(text);
  if (parsed.contains("invalid"))
    throw InvalidSimulation("bench: case '" + c.name + "': " + parsed["invalid"].get<std::string>());
  for (const char* key : {"name", "steps_per_s", "ns_per_particle_step", "particles", "threads", "iterations",
                          "peak_rss_mb", "seconds"})
    ordered[key] = parsed.at(key);
  for (const auto& [key, value] : parsed.items())
    if (!ordered.contains(key)) ordered[key] = value;
  return ordered;
}

}  // namespace

std::vector<std::string> benchCaseNames() {
  std::vector<std::string> names;
  for (const BenchCase& c : allCases()) names.push_back(c.name);
  return names;
}

int benchCommand(const BenchOptions& options) {
  const std::optional<cardiac::BloodResolution> level = levelOrReport(options.resolution);
  if (!level) return kExitBadInput;
  const std::vector<BenchCase> cases = allCases(*level);
  std::vector<const BenchCase*> chosen;
  for (const std::string& name : options.cases) {
    const BenchCase* found = nullptr;
    for (const BenchCase& c : cases)
      if (c.name == name) found = &c;
    if (!found) {
      std::string known;
      for (const BenchCase& c : cases) known += (known.empty() ? "" : ", ") + c.name;
      std::cerr << "heartsim: error: --case " << name << ": unknown bench case (known: " << known << ")\n";
      return kExitBadInput;
    }
    chosen.push_back(found);
  }
  std::vector<BenchCase> files;  // checked here so that a bad file is one line and exit 2
  for (const std::string& path : options.scenarios) {
    try {
      io::loadScenario(path);
    } catch (const std::exception& e) {
      std::cerr << "heartsim: error: " << e.what() << '\n';
      return kExitBadInput;
    }
    files.push_back(heartCase(path, *level));
  }
  for (const BenchCase& c : files) chosen.push_back(&c);
  if (chosen.empty())
    for (const BenchCase& c : cases) chosen.push_back(&c);
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();

  nlohmann::ordered_json report;
  report["cases"] = nlohmann::json::array();
  for (const BenchCase* c : chosen) {
    std::cerr << "heartsim bench: " << c->name << " (" << threads << " threads)...\n";
    nlohmann::ordered_json r;
    try {
      r = runIsolated(*c, threads, options.seconds);
    } catch (const InvalidSimulation& e) {
      std::cerr << "heartsim: error: " << e.what() << '\n';
      return kExitInvalidSimulation;
    } catch (const std::exception& e) {
      std::cerr << "heartsim: error: " << e.what() << '\n';
      return kExitFailure;
    }
    if (!options.json) {
      std::printf("%-24s %12.1f steps/s %10.1f ns/particle-step %8zu particles %2d threads %8.1f MB peak %8.3f s\n",
                  c->name.c_str(), r["steps_per_s"].get<double>(), r["ns_per_particle_step"].get<double>(),
                  r["particles"].get<std::size_t>(), threads, r["peak_rss_mb"].get<double>(),
                  r["seconds"].get<double>());
      if (threads > 1 && r.contains("fewer_threads_share"))
        std::printf("%-24s %11.0f%% of the steps on fewer threads (the governor's choice)\n", "",
                    100 * r["fewer_threads_share"].get<double>());
    }
    report["cases"].push_back(r);
  }
  if (options.json && !writeStdoutOrReport(report.dump())) return kExitFailure;
  return kExitOk;
}

}  // namespace hs::app
