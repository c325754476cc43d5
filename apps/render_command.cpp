#include "render_command.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "contact_sheet.h"
#include "exit_codes.h"
#include "io/output/output_paths.h"
#include "progress_bar.h"
#include "render/anatomy_labels.h"
#include "render/gl_context.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "render/vortex_cut.h"
#include "simulation_setup.h"
#include "viz/image.h"

namespace hs::app {
namespace {

namespace fs = std::filesystem;

// One line on stderr and exit 2: every option is checked before anything is simulated.
struct BadInput {
  std::string message;
};

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');) {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    items.push_back(first == std::string::npos ? "" : item.substr(first, last - first + 1));
  }
  if (!list.empty() && list.back() == ',') items.emplace_back();
  return items;
}

std::vector<render::View> parseViews(const std::string& list) {
  std::vector<render::View> views;
  for (const std::string& name : splitList(list)) {
    const auto view = render::parseView(name);
    if (!view)
      throw BadInput{"--views: unknown view '" + name + "'; valid views: " + render::viewNames()};
    if (std::find(views.begin(), views.end(), *view) == views.end()) views.push_back(*view);
  }
  if (views.empty()) throw BadInput{"--views: no view given; valid views: " + render::viewNames()};
  return views;
}

// Sorted, without duplicates (as written in file names).
std::vector<double> parseTimes(const std::string& list, double duration) {
  std::vector<double> times;
  std::set<std::string> names;
  for (const std::string& text : splitList(list)) {
    char* end = nullptr;
    const double t = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(t))
      throw BadInput{"--times: '" + text + "' is not a time in seconds (give a comma list such as 0,0.08,1)"};
    if (t < 0) throw BadInput{"--times: " + text + " s is negative; times count seconds from the start (>= 0)"};
    // The duration is single precision (0.7 is 0.69999999): the end as written is within it.
    if (t > duration * (1 + 1e-6))
      throw BadInput{"--times: " + text + " s is beyond the scenario's duration of " + formatTime(duration) +
                     " s (lengthen it with --set simulation.duration=...)"};
    if (names.insert(formatTime(t)).second) times.push_back(t);
  }
  if (times.empty()) throw BadInput{"--times: no time given (give a comma list such as 0,0.08,1)"};
  std::sort(times.begin(), times.end());
  return times;
}

std::pair<int, int> parseSize(const std::string& text) {
  constexpr int kMin = 16, kMax = 8192;
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < kMin ||
      h < kMin || w > kMax || h > kMax)
    throw BadInput{"--size: '" + text + "' is not WIDTHxHEIGHT in pixels (e.g. 800x600, each " +
                   std::to_string(kMin) + " to " + std::to_string(kMax) + ")"};
  return {w, h};
}

// A folder that cannot be made or written is a failure to write (exit 1, as for run), not bad
// input.
struct WriteFailure {
  std::string message;
};

void prepareOutputDir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw WriteFailure{"--out: cannot create output directory '" + dir.string() + "': " +
                   (ec ? ec.message() : "not a directory")};
  // Permissions alone do not tell (root, read-only mounts): try to write.
  const fs::path probe = dir / ".heartsim-write-test";
  {
    std::ofstream test(probe);
    if (!(test << "x")) throw WriteFailure{"--out: output directory '" + dir.string() + "' is not writable"};
  }
  fs::remove(probe, ec);
}

// Every option checked, before anything is simulated.
struct RenderPlan {
  std::vector<render::View> views;
  std::vector<double> times;
  int width = 0, height = 0;
  fs::path outDir;
};

RenderPlan planRender(const RenderOptions& options, const cardiac::Scenario& scenario) {
  const double duration = double(scenario.simulation.duration);
  RenderPlan plan;
  plan.outDir = options.outDir.empty() ? io::defaultOutputFolder(scenario.name) / "render" : fs::path(options.outDir);
  plan.views = parseViews(options.views);
  plan.times = parseTimes(options.times.empty() ? "0," + formatTime(duration) : options.times, duration);
  std::tie(plan.width, plan.height) = parseSize(options.size);
  if (!(options.wallOpacity > 0 && options.wallOpacity <= 1))
    throw BadInput{"--wall-opacity: must be in (0, 1], got " + formatTime(options.wallOpacity)};
  if (!(options.speedMax >= 0) || !std::isfinite(options.speedMax))
    throw BadInput{"--speed-max: must be a finite speed >= 0 (m/s; 0 = from the scenario)"};
  if (!(options.pressureMax >= 0) || !std::isfinite(options.pressureMax))
    throw BadInput{"--pressure-max: must be a finite pressure >= 0 (mmHg; 0 = from the scenario)"};
  if (!render::parseBloodColour(options.bloodColour))
    throw BadInput{"--blood-colour: unknown colour '" + options.bloodColour +
                   "'; valid: speed, pressure, origin, components, stay"};
  if (!render::parseBloodLook(options.bloodLook))
    throw BadInput{"--blood-look: unknown look '" + options.bloodLook + "'; valid: liquid, spheres"};
  if (!render::parseFlowView(options.flow))
    throw BadInput{"--flow: unknown flow view '" + options.flow + "'; valid: off, streaks, arrows"};
  if (!render::parseLabelSet(options.labels))
    throw BadInput{"--labels: unknown label set '" + options.labels + "'; valid: " + render::labelSetNames()};
  if (!std::isfinite(options.clipZ)) throw BadInput{"--clip-z: must be a finite position (m)"};
  prepareOutputDir(plan.outDir);
  return plan;
}

render::SceneOptions sceneOptionsFor(const RenderOptions& options, bool heart) {
  render::SceneOptions scene;
  scene.clip = options.clip.value_or(heart);
  scene.clipZ = float(options.clipZ);
  scene.wallOpacity = float(options.wallOpacity);
  scene.speedMax = options.speedMax;
  scene.pressureMax = options.pressureMax;
  scene.bloodColour = *render::parseBloodColour(options.bloodColour);
  scene.bloodLook = *render::parseBloodLook(options.bloodLook);
  scene.flow = *render::parseFlowView(options.flow);
  return scene;
}

// " colour label" for each row of a colour key, comma-separated.
template <class Rows>
void appendKeyRows(std::string& footer, const Rows& rows) {
  for (const auto& row : rows) footer += std::string(" ") + row.colourName + " " + row.label + ",";
  footer.pop_back();
}

// The contact sheet's colour key: what the wall's and the blood's colours mean.
std::string sheetFooter(const cardiac::HeartSimulation& sim, const render::SceneOptions& scene, double clipZ,
                        double scaleMax) {
  std::string footer;
  if (sim.hasHeart())
    footer += "wall: red = myocardium, orange = chosen beating region, light = base plate and vessels, "
              "dark = cut face" +
              std::string(scene.clip ? " (front view cut open at z = " + formatTime(clipZ) + " m)" : "");
  if (!sim.hasBlood()) return footer;
  footer += footer.empty() ? "" : "; ";
  if (scene.flow != render::FlowView::Off)
    return footer + "flow " + render::flowViewName(scene.flow) + " coloured by speed, blue 0 to yellow " +
           formatTime(scene.speedMax > 0 ? scene.speedMax : render::defaultSpeedScale(sim.scenario())) +
           " m/s, over pale blood";
  switch (scene.bloodColour) {
    case render::BloodColour::Speed:
      footer += "blood coloured by speed, blue 0 to yellow " + formatTime(scaleMax) + " m/s";
      if (sim.lumped()) footer += ", grey = the vessels' far ends (the lumped model's boundary)";
      break;
    case render::BloodColour::Pressure:
      footer += "blood coloured by pressure, blue 0 to yellow " + formatTime(scaleMax) + " mmHg";
      break;
    case render::BloodColour::Origin:
      footer += "blood coloured by where it started:";
      appendKeyRows(footer, render::originKey());
      break;
    case render::BloodColour::Components:
      footer += "blood coloured by its flow component in the beat whose systole ends next:";
      appendKeyRows(footer, render::componentKey());
      break;
    case render::BloodColour::Stay:
      footer += "blood coloured by how long it has been in the ventricle:";
      appendKeyRows(footer, render::stayKey());
      break;
  }
  return footer;
}

// The offscreen context, its frame and the renderer, made once for every view.
struct Offscreen {
  render::GlContext gl;
  render::FrameTarget target;
  render::Renderer renderer;
  Offscreen(int width, int height) : target(width, height) {}
};

// One time's scene, waiting for its blood's colours when they are known only later.
struct Shot {
  double time = 0;
  render::Scene scene;
  std::vector<render::SceneLabel> labels;
  std::vector<std::size_t> identities;  // of the scene's blood (render::drawnBloodIdentities)
};

// Colouring by component looks ahead: the blood at a time is coloured by the component it ends
// up in when the beat's systole is over (the first end-systole after that time), as the 4D-flow
// papers colour the end-diastolic volume by its fate. The run steps on past the last time for
// that, by at most this long.
constexpr double kComponentLookAhead = 3.0;  // s: two beats at 40 bpm

// Draws each time's views into PNGs and their thumbnails into `cells` (a row per time),
// stepping the simulation to each time under the monitor's health checks.
int drawTimes(cardiac::HeartSimulation& sim, Offscreen& out, const RenderPlan& plan,
              render::SceneOptions sceneOptions, double scaleMax, render::LabelSet labelSet,
              std::vector<std::vector<viz::Image>>& cells, std::vector<std::string>& rowLabels) {
  const double dt = double(sim.scenario().simulation.dt);
  // Streaks: the seeds' trajectories over the window before each time, sampled every step.
  render::PathlineRecorder pathlines;
  sceneOptions.pathlines = &pathlines;
  sceneOptions.flowLineWidth = float(std::max(2, std::min(plan.width, plan.height) / 200));
  const auto windowSteps = static_cast<std::int64_t>(std::ceil(pathlines.window() / dt));
  const float aspect = float(plan.width) / float(plan.height);
  const int shrinkFactor = std::max(1, (plan.width + 399) / 400);
  const int textScale = std::max(1, std::min(plan.width, plan.height) / 300);
  const bool byComponent = sceneOptions.bloodColour == render::BloodColour::Components;
  const bool byStay = sceneOptions.bloodColour == render::BloodColour::Stay;
  const bool lookAhead = byComponent && sceneOptions.flow == render::FlowView::Off;
  // The blood's own bookkeeping (flow components) only where the colours need it: it reads the
  // state and changes nothing.
  cardiac::MonitorSettings settings = cardiac::MonitorSettings::healthOnly();
  settings.pump = byComponent || byStay;
  settings.lumpedSamples = 1000;  // the lumped recorder keeps a bounded window; nothing here reads it
  cardiac::RunMonitor monitor(sim, settings);
  const cardiac::VentricleBlood* blood = monitor.ventricleBlood();
  std::vector<cardiac::FlowComponent> components;
  std::vector<cardiac::Stay> stays;
  ProgressBar progress(static_cast<long>(std::llround(plan.times.back() / dt)));

  auto drawShot = [&](Shot& shot) {
    const std::string label = "t = " + formatTime(shot.time) + " s";
    rowLabels.push_back(label);
    cells.emplace_back();
    for (const render::View view : plan.views) {
      render::applyView(shot.scene, sceneOptions, view);
      out.target.bind();
      out.renderer.draw(shot.scene, render::viewCamera(view, shot.scene.bounds, aspect), plan.width, plan.height);
      viz::Image image = out.target.read();
      std::vector<viz::Rect> key;
      if (sim.hasBlood()) key.push_back(render::drawBloodLegend(image, sceneOptions.bloodColour, scaleMax));
      render::drawLabels(image, shot.labels, render::viewCamera(view, shot.scene.bounds, aspect), key);
      image.drawText(6 * textScale, 6 * textScale, std::string(render::viewName(view)) + ", " + label, textScale,
                     {40, 40, 50});
      image.savePng((plan.outDir / ("t" + formatTime(shot.time) + "_" + render::viewName(view) + ".png")).string());
      cells.back().push_back(shrink(image, shrinkFactor));
    }
  };
  std::vector<Shot> waiting;  // in time order
  auto drawWaiting = [&] {
    components = blood->components();
    for (Shot& shot : waiting) {
      render::colourByComponent(shot.scene, shot.identities, components);
      drawShot(shot);
    }
    waiting.clear();
  };
  std::size_t beatsEnded = blood ? blood->beats().size() : 0;
  // One step under the health checks; a finished beat colours the shots waiting for it.
  auto step = [&]() -> bool {
    sim.step();
    if (const cardiac::Verdict& verdict = monitor.observe(); !verdict.healthy()) {
      progress.finish();
      std::cerr << "heartsim: error: " << verdict.message() << '\n';
      return false;
    }
    progress.update(static_cast<long>(sim.stepCount()), sim.time());
    if (blood && blood->beats().size() > beatsEnded) {
      beatsEnded = blood->beats().size();
      if (!waiting.empty()) drawWaiting();
    }
    return true;
  };
  for (const double t : plan.times) {
    const auto target = static_cast<std::int64_t>(std::llround(t / dt));
    pathlines.clear();
    while (sim.stepCount() < target) {
      if (sceneOptions.flow == render::FlowView::Streaks && sim.stepCount() >= target - windowSteps)
        pathlines.record(sim);
      if (!step()) return kExitInvalidSimulation;
    }
    if (sceneOptions.flow == render::FlowView::Streaks) pathlines.record(sim);
    if (blood && byComponent) components = blood->components();
    if (blood && byStay) stays = blood->stays();
    sceneOptions.components = blood ? &components : nullptr;
    sceneOptions.stays = blood ? &stays : nullptr;
    Shot shot{t, render::buildScene(sim, sceneOptions), render::anatomyLabels(sim, labelSet), {}};
    if (lookAhead) {
      shot.identities = render::drawnBloodIdentities(sim);
      waiting.push_back(std::move(shot));
    } else {
      drawShot(shot);
    }
  }
  const auto lastStep = sim.stepCount() + static_cast<std::int64_t>(std::llround(kComponentLookAhead / dt));
  while (!waiting.empty() && sim.stepCount() < lastStep)
    if (!step()) return kExitInvalidSimulation;
  if (!waiting.empty()) {
    std::cerr << "heartsim: warning: no end of systole within " << formatTime(kComponentLookAhead)
              << " s after the last time: its blood is coloured by the components so far\n";
    drawWaiting();
  }
  progress.finish();
  return kExitOk;
}

// Runs `prepare`; a bad input or an output that cannot be written is said in one line and gives
// the exit code (kExitBadInput, kExitFailure); nothing when it succeeded.
template <class Prepare>
std::optional<int> exitOnInputError(Prepare prepare) {
  try {
    prepare();
  } catch (const BadInput& e) {
    std::cerr << "heartsim: error: " << e.message << '\n';
    return kExitBadInput;
  } catch (const WriteFailure& e) {
    std::cerr << "heartsim: error: " << e.message << '\n';
    return kExitFailure;
  }
  return std::nullopt;
}

// --e-vortex: steps to the end of beat `beat`'s early filling under a monitor that reads the
// filling vortex (cardiac/run_monitor.h), then draws its view at the E peak.
int renderEVortex(const RenderOptions& options, const cardiac::Scenario& scenario) {
  const int beat = *options.eVortexBeat;
  fs::path outDir;
  int height = 0;
  if (const std::optional<int> failed = exitOnInputError([&] {
    if (beat < 1) throw BadInput{"--e-vortex: beat " + std::to_string(beat) + " is not a beat (give 1 or more)"};
    if (!scenario.circulation.lumped || !scenario.blood.enabled)
      throw BadInput{"--e-vortex: scenario '" + scenario.name +
                     "' has no lumped circulation with blood (circulation.lumped and blood.enabled), whose E wave the "
                     "filling vortex is read at"};
    height = parseSize(options.size).second;
    outDir = options.outDir.empty() ? io::defaultOutputFolder(scenario.name) / "render" : fs::path(options.outDir);
    prepareOutputDir(outDir);
  }))
    return *failed;
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  int setupError = kExitOk;
  const std::unique_ptr<cardiac::HeartSimulation> sim = makeSimulation(scenario, threads, options.scenario, setupError);
  if (!sim) return setupError;
  cardiac::MonitorSettings settings;
  settings.beatList = false;
  cardiac::RunMonitor monitor(*sim, settings);
  const double dt = double(scenario.simulation.dt);
  const auto lastStep = static_cast<std::int64_t>(std::llround(double(scenario.simulation.duration) / dt));
  ProgressBar progress(static_cast<long>(lastStep));
  const cardiac::FillingVortex* vortex = monitor.fillingVortex();
  while (vortex && int(vortex->beats().size()) < beat && sim->stepCount() < lastStep) {
    sim->step();
    if (const cardiac::Verdict& verdict = monitor.observe(); !verdict.healthy()) {
      progress.finish();
      std::cerr << "heartsim: error: " << verdict.message() << '\n';
      return kExitInvalidSimulation;
    }
    progress.update(static_cast<long>(sim->stepCount()), sim->time());
  }
  progress.finish();
  if (!vortex || int(vortex->beats().size()) < beat || !vortex->lastBeatView()) {
    std::cerr << "heartsim: error: --e-vortex: the run ended at " << formatTime(sim->time()) << " s before beat " << beat
              << "'s early filling ended (lengthen it with --set simulation.duration=...)\n";
    return kExitFailure;
  }
  const cardiac::EVortexView& view = *vortex->lastBeatView();
  const std::string title = scenario.name + ": the E-wave filling vortex in the long-axis cut, beat " +
                            std::to_string(beat) + ", E peak at t = " + formatTime(view.sample.time) + " s (mitral flow " +
                            std::to_string(int(std::lround(view.sample.mitralFlow * 1e6))) + " mL/s)";
  const fs::path file = outDir / ("e_vortex_beat" + std::to_string(beat) + ".png");
  try {
    render::drawEVortexCut(view, height, title).savePng(file.string());
  } catch (const std::runtime_error& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
  std::cerr << "heartsim: " << scenario.name << ": the E-wave vortex of beat " << beat << " in " << file.string() << '\n';
  return kExitOk;
}

}  // namespace

std::string formatTime(double seconds) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", seconds);
  std::string s = buffer;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

int renderCommand(const RenderOptions& options) {
  std::optional<cardiac::Scenario> loaded = loadScenarioOrReport(options.scenario, options.overrides, options.resolution);
  if (!loaded) return kExitBadInput;
  const cardiac::Scenario& scenario = *loaded;
  if (options.eVortexBeat) return renderEVortex(options, scenario);
  RenderPlan plan;
  if (const std::optional<int> failed = exitOnInputError([&] { plan = planRender(options, scenario); })) return *failed;
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  int setupError = kExitOk;
  const std::unique_ptr<cardiac::HeartSimulation> sim = makeSimulation(scenario, threads, options.scenario, setupError);
  if (!sim) return setupError;
  if (const render::BloodColour colour = *render::parseBloodColour(options.bloodColour);
      (colour == render::BloodColour::Components || colour == render::BloodColour::Stay) &&
      !(sim->hasHeart() && sim->hasBlood() && sim->circulation())) {
    std::cerr << "heartsim: error: --blood-colour " << options.bloodColour << ": '" << scenario.name
              << "' has no heart with blood and valves, so no beat sorts its blood\n";
    return kExitBadInput;
  }
  std::optional<Offscreen> out;
  try {
    out.emplace(plan.width, plan.height);
  } catch (const std::runtime_error& e) {
    std::cerr << "heartsim: error: cannot render: " << e.what() << '\n';
    return kExitFailure;
  }
  const render::SceneOptions sceneOptions = sceneOptionsFor(options, sim->hasHeart());
  // One scale for every time and view of the sheet.
  const double scaleMax = render::colourScaleMax(sceneOptions, scenario);
  std::vector<std::vector<viz::Image>> cells;
  std::vector<std::string> rowLabels;
  try {
    const render::LabelSet labelSet = *render::parseLabelSet(options.labels);
    if (const int drawn = drawTimes(*sim, *out, plan, sceneOptions, scaleMax, labelSet, cells, rowLabels);
        drawn != kExitOk)
      return drawn;
    std::string title = scenario.name;
    if (!scenario.description.empty()) title += ": " + scenario.description;
    contactSheet(title, rowLabels, plan.views, cells, sheetFooter(*sim, sceneOptions, options.clipZ, scaleMax))
        .savePng((plan.outDir / "contact_sheet.png").string());
  } catch (const std::runtime_error& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
  std::cerr << "heartsim: " << scenario.name << ": " << plan.times.size() * plan.views.size()
            << " views and a contact sheet in " << plan.outDir.string() << " (" << out->gl.description() << ")\n";
  return kExitOk;
}

}  // namespace hs::app
