#include "view_command.h"

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "exit_codes.h"
#include "io/output/checkpoint.h"
#include "io/scenario/scenario_file.h"
#include "render/anatomy_labels.h"
#include "render/scene.h"
#include "simulation_setup.h"
#include "viewer/app/viewer_app.h"

namespace hs::app {
namespace {

bool parseWindowSize(const std::string& text, int& width, int& height) {
  constexpr int kMin = 200, kMax = 8192;
  char x = 0, extra = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) == 3 && (x == 'x' || x == 'X') &&
         width >= kMin && height >= kMin && width <= kMax && height <= kMax;
}

// What fixed the blood's particle count, so that the start-up pick keeps it (docs/viewer.md):
// a lesson, a checkpoint, a scenario file of one's own, or --set on the blood's size; "" for a
// built-in scenario as it is. `file`: the scenario's file when it is not a built-in.
std::string bloodFixedBy(const ViewOptions& options, const std::string& file) {
  if (!options.lesson.empty()) return "as the lesson sets it";
  if (!options.resume.empty()) return "as the checkpoint has it";
  for (const std::string& set : options.overrides) {
    std::string key = set.substr(0, set.find('='));
    key.erase(key.find_last_not_of(" \t") + 1);
    key.erase(0, key.find_first_not_of(" \t"));
    for (const char* size : {"blood.particles", "blood.spacing", "blood.radius", "blood.support_radius"})
      if (key == size) return "as --set " + key + " sets it";
  }
  if (!file.empty()) return "as " + std::filesystem::path(file).filename().string() + " sets it";
  return "";
}

}  // namespace

int viewCommand(const ViewOptions& options) {
  viewer::ViewerOptions viewer;
  if (!parseWindowSize(options.size, viewer.width, viewer.height)) {
    std::cerr << "heartsim: error: --size: '" << options.size
              << "' is not WIDTHxHEIGHT in pixels (e.g. 1280x800, each 200 to 8192)\n";
    return kExitBadInput;
  }
  if (options.frames < 0) {
    std::cerr << "heartsim: error: --frames: must be >= 0 (0 = until the window is closed)\n";
    return kExitBadInput;
  }
  if (options.resolution != "auto") {
    viewer.resolution = resolutionOrReport(options.resolution, "auto");
    if (!viewer.resolution) return kExitBadInput;
  }
  const std::optional<render::BloodLook> look = render::parseBloodLook(options.bloodLook);
  if (!look) {
    std::cerr << "heartsim: error: --blood-look: unknown look '" << options.bloodLook << "'; valid: liquid, spheres\n";
    return kExitBadInput;
  }
  const std::optional<render::FlowView> flow = render::parseFlowView(options.flow);
  if (!flow) {
    std::cerr << "heartsim: error: --flow: unknown flow view '" << options.flow << "'; valid: off, streaks, arrows\n";
    return kExitBadInput;
  }
  const std::optional<render::LabelSet> labels = render::parseLabelSet(options.labels);
  if (!labels) {
    std::cerr << "heartsim: error: --labels: unknown label set '" << options.labels
              << "'; valid: " << render::labelSetNames() << "\n";
    return kExitBadInput;
  }
  viewer.bloodLook = *look;
  viewer.flow = *flow;
  viewer.labels = *labels != render::LabelSet::Off;
  if (!options.resume.empty() && !options.lesson.empty()) {
    std::cerr << "heartsim: error: --resume: a lesson starts from its own scenario; give --resume or --lesson\n";
    return kExitBadInput;
  }
  std::string scenarioName = options.scenario;
  if (!options.lesson.empty()) {
    try {
      viewer.lesson = viewer::loadLesson(options.lesson);
    } catch (const viewer::LessonError& e) {
      std::cerr << "heartsim: error: " << e.what() << '\n';
      return kExitBadInput;
    }
    scenarioName = viewer.lesson->scenario;  // a lesson starts where its file says
  }
  std::optional<cardiac::Scenario> scenario;
  if (!options.resume.empty()) {
    // The checkpoint holds its scenario; the viewer's settings may change it after a Reset.
    try {
      viewer.resume = io::readCheckpointFile(options.resume);
      scenario = io::checkpointScenario(*viewer.resume, options.resume);
    } catch (const io::CheckpointError& e) {
      std::cerr << "heartsim: error: " << e.what() << '\n';
      return kExitBadInput;
    }
    viewer.resumeSource = scenarioName = options.resume;
  } else {
    scenario = loadScenarioOrReport(scenarioName, options.overrides);
  }
  if (!scenario) return kExitBadInput;
  viewer.scenario = *scenario;
  const std::vector<std::string> builtins = io::builtinScenarioNames();
  if (std::find(builtins.begin(), builtins.end(), scenarioName) != builtins.end()) viewer.builtinName = scenarioName;
  viewer.bloodFixedBy = bloodFixedBy(options, viewer.builtinName.empty() ? scenarioName : "");
  viewer.frames = options.frames;
  viewer.screenshot = options.screenshot;
  // The simulation runs in its own thread beside the drawing: by default it leaves one core to
  // the window (on a software renderer the drawing needs it, and an OpenMP team sharing its
  // cores with the renderer's threads waits at every barrier).
  viewer.threads = options.threads > 0 ? options.threads : std::max(1, omp_get_num_procs() - 1);
  try {
    viewer::runViewer(viewer);
  } catch (const io::CheckpointError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const viewer::DisplayError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  } catch (const std::invalid_argument& e) {
    std::cerr << "heartsim: error: " << scenarioName << ": " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::runtime_error& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
  if (!options.screenshot.empty()) std::cerr << "heartsim: saved " << options.screenshot << '\n';
  return kExitOk;
}

}  // namespace hs::app
