// heartsim: the command-line entry point. Subcommands: run, view, render, bench, validate, compare, mesh.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "bench_command.h"
#include "compare_command.h"
#include "exit_codes.h"
#include "mesh_command.h"
#include "render_command.h"
#include "run_command.h"
#include "validate_command.h"
#include "version.h"
#include "view_command.h"

namespace {

// Options several subcommands share, with one wording and one range.
void addThreadsOption(CLI::App* command, int& threads, const char* help = "Worker threads (default: all cores)") {
  command->add_option("--threads", threads, help)->check(CLI::Range(1, 1024));
}

void addResolutionOption(CLI::App* command, std::string& resolution) {
  command->add_option("--resolution", resolution,
                      "Blood resolution: coarse, medium, fine (the scenario as written) or finest; the viewer's levels");
}

void addSetOption(CLI::App* command, std::vector<std::string>& overrides, const char* example = "cycle.beats=2") {
  command->add_option("--set", overrides, std::string("Override a scenario key: --set ") + example + " (repeatable)")
      ->take_all()
      ->expected(1);
}

// Every subcommand's options and, once parsed, which one was given.
struct Commands {
  hs::app::RunOptions run;
  double duration = -1;
  double checkpointEvery = 0;
  hs::app::RenderOptions render;
  bool renderClip = true;
  hs::app::ViewOptions view;
  hs::app::BenchOptions bench;
  hs::app::ValidateOptions validate;
  hs::app::CompareOptions compare;
  hs::app::MeshOptions mesh;
  CLI::App* meshApp = nullptr;
  CLI::App* compareApp = nullptr;
  CLI::App* runApp = nullptr;
  CLI::App* renderApp = nullptr;
  CLI::App* viewApp = nullptr;
  CLI::App* benchApp = nullptr;
  CLI::App* damBreakApp = nullptr;
};

void addRunCommand(CLI::App& app, Commands& c) {
  hs::app::RunOptions& run = c.run;
  CLI::App* runApp = c.runApp = app.add_subcommand("run", "Run a scenario headless and write its results");
  // Required unless --resume names a checkpoint, which holds its scenario (dispatch checks).
  runApp->add_option("scenario", run.scenario, "Built-in scenario name or path to a .toml file");
  runApp->add_option("--duration", c.duration, "Simulated time (s), overrides simulation.duration");
  addThreadsOption(runApp, run.threads);
  addResolutionOption(runApp, run.resolution);
  runApp->add_option("--out", run.outDir, "Output directory (default: results/<scenario>)");
  runApp->add_flag("--json", run.json, "Print one JSON summary object on stdout");
  runApp->add_flag("--vtk", run.vtk, "Write VTK frames and a .pvd series for ParaView");
  runApp->add_option("--checkpoint-every", c.checkpointEvery,
                     "Write the whole state every S simulated seconds into the output folder (checkpoint_<time>s.hsck)");
  runApp->add_option("--resume", run.resume, "Continue a checkpoint file to --duration (the scenario comes from it)");
  addSetOption(runApp, run.overrides);
}

void addCompareCommand(CLI::App& app, Commands& c) {
  hs::app::CompareOptions& compare = c.compare;
  CLI::App* compareApp = c.compareApp = app.add_subcommand(
      "compare", "Run two lumped-circulation scenarios, draw their pressure-volume loops on one plot and print their blood's flow components side by side");
  compareApp->add_option("scenarios", compare.scenarios, "Two built-in scenario names or .toml paths")
      ->required()
      ->expected(2);
  compareApp->add_option("--duration", compare.duration, "Simulated time of each (s); default 1.8, two beats");
  addThreadsOption(compareApp, compare.threads);
  compareApp->add_option("--out", compare.outDir, "Output directory (default: results/compare_<a>_<b>)");
}

void addRenderCommand(CLI::App& app, Commands& c) {
  hs::app::RenderOptions& render = c.render;
  CLI::App* renderApp = c.renderApp =
      app.add_subcommand("render", "Run a scenario headless and draw it offscreen as PNG images");
  renderApp->add_option("scenario", render.scenario, "Built-in scenario name or path to a .toml file")->required();
  renderApp->add_option("--times", render.times, "Comma list of times (s) to draw, e.g. 0,0.08,1,2 (default: 0 and the end)");
  renderApp->add_option("--views", render.views, "Comma list of views: front, left, right, top")->capture_default_str();
  renderApp->add_option("--out", render.outDir, "Output directory (default: results/<scenario>/render)");
  renderApp->add_option("--size", render.size, "Size of each view, WIDTHxHEIGHT pixels")->capture_default_str();
  renderApp->add_flag("--clip,!--no-clip", c.renderClip, "Cut the wall open at z = --clip-z (default: on with a heart)");
  renderApp->add_option("--clip-z", render.clipZ, "Position of the cutting plane z = const (m)")->capture_default_str();
  renderApp->add_option("--wall-opacity", render.wallOpacity, "Wall opacity in (0, 1]; below 1 the wall is see-through")
      ->capture_default_str();
  renderApp->add_option("--speed-max", render.speedMax, "Blood speed (m/s) at the top of the colour scale (0: from the scenario)");
  renderApp->add_option("--blood-colour", render.bloodColour, "Colour the blood by speed, pressure, origin, components (its flow component in the beat: green direct, blue retained inflow, yellow delayed ejection, red residual) or stay (more than 3 beats in the ventricle)")
      ->capture_default_str();
  renderApp->add_option("--blood-look", render.bloodLook, "Draw the blood as a liquid surface or as spheres")
      ->capture_default_str();
  renderApp->add_option("--flow", render.flow, "Flow view: off, streaks (short pathlines) or arrows")
      ->capture_default_str();
  renderApp->add_option("--labels", render.labels, "Names on the heart: off or anatomy")->capture_default_str();
  renderApp->add_option("--pressure-max", render.pressureMax,
                        "Blood pressure (mmHg) at the top of the pressure colour scale (0: from the scenario)");
  renderApp->add_option("--e-vortex", render.eVortexBeat,
                        "Draw the E-wave filling vortex in the long-axis cut at the E peak of this beat (1 = the first "
                        "filling) instead of the views; needs circulation.lumped and blood");
  addThreadsOption(renderApp, render.threads);
  addResolutionOption(renderApp, render.resolution);
  addSetOption(renderApp, render.overrides);
}

void addViewCommand(CLI::App& app, Commands& c) {
  hs::app::ViewOptions& view = c.view;
  CLI::App* viewApp = c.viewApp =
      app.add_subcommand("view", "Open the interactive viewer: watch, steer and photograph a scenario");
  viewApp->add_option("scenario", view.scenario, "Built-in scenario name or path to a .toml file")->capture_default_str();
  viewApp->add_option("--size", view.size, "Window size, WIDTHxHEIGHT pixels")->capture_default_str();
  viewApp->add_option("--frames", view.frames, "Quit after N frames (scripted use; 0 = until closed)");
  viewApp->add_option("--screenshot", view.screenshot, "Save the last frame as this PNG file");
  viewApp->add_option("--lesson", view.lesson,
                      "Run a lesson: a built-in (regional-wall-motion, rhythm, preload-afterload) or a .toml file");
  viewApp->add_option("--resume", view.resume, "Start from a checkpoint file (F5 in the viewer or run --checkpoint-every writes one)");
  viewApp->add_option("--blood-look", view.bloodLook, "Draw the blood as a liquid surface or as spheres")
      ->capture_default_str();
  viewApp->add_option("--flow", view.flow, "Flow view: off, streaks (short pathlines) or arrows")->capture_default_str();
  viewApp->add_option("--labels", view.labels, "Names on the heart: off or anatomy")->capture_default_str();
  viewApp->add_option("--resolution", view.resolution,
                      "Blood resolution: coarse, medium, fine (the scenario's), finest, or auto (the finest that "
                      "holds real time here)")
      ->capture_default_str();
  addThreadsOption(viewApp, view.threads,
                   "Simulation threads (default: all cores but one, which the drawing needs)");
  addSetOption(viewApp, view.overrides);
}

void addBenchCommand(CLI::App& app, Commands& c) {
  hs::app::BenchOptions& bench = c.bench;
  CLI::App* benchApp = c.benchApp = app.add_subcommand("bench", "End-to-end throughput benchmarks");
  benchApp->add_option("--case", bench.cases, "Case to run (repeatable; default: all)")->expected(1)->take_all();
  benchApp->add_option("--scenario", bench.scenarios,
                       "A scenario .toml file to step as the heart cases are, with each stage's time (repeatable)")
      ->expected(1)
      ->take_all();
  addThreadsOption(benchApp, bench.threads);
  addResolutionOption(benchApp, bench.resolution);
  benchApp->add_option("--seconds", bench.seconds, "Measuring time per case (s)")->check(CLI::Range(0.1, 600.0));
  benchApp->add_flag("--json", bench.json, "Print one JSON object on stdout");
}

void addValidateCommand(CLI::App& app, Commands& c) {
  hs::app::ValidateOptions& validate = c.validate;
  CLI::App* validateApp = app.add_subcommand("validate", "Compare a simulation with experimental data");
  validateApp->require_subcommand(1);
  CLI::App* damBreakApp = c.damBreakApp =
      validateApp->add_subcommand("dam-break", "Surge front of a collapsing column vs Martin & Moyce (1952), n^2 = 2");
  damBreakApp->add_option("--scenario", validate.scenario, "Built-in scenario name or path to a .toml file")
      ->capture_default_str();
  addSetOption(damBreakApp, validate.overrides, "blood.iterations=6");
  damBreakApp->add_option("--out", validate.outDir, "Output directory")->capture_default_str();
  addThreadsOption(damBreakApp, validate.threads);
  damBreakApp->add_flag("--json", validate.json, "Print one JSON report object on stdout");
}

void addMeshCommand(CLI::App& app, Commands& c) {
  CLI::App* meshApp = c.meshApp = app.add_subcommand(
      "mesh", "Read a patient mesh (.obj .stl .ply .off .msh .vtu .vtk .node) and print what it holds");
  meshApp->add_option("file", c.mesh.file, "The mesh file")->required();
  meshApp->add_flag("--json", c.mesh.json, "Print one JSON object on stdout");
  meshApp->add_flag("--wall", c.mesh.wall, "Also build the tetrahedral wall of the ventricle and report it");
  meshApp->add_option("--units", c.mesh.units, "The file's length unit for --wall: mm or m (default: guessed)");
  meshApp->add_option("--thickness", c.mesh.thickness, "Wall thickness in m without an epicardium (default 0.010)");
  meshApp->add_option("--resolution", c.mesh.resolution, "coarse, default or fine")->capture_default_str();
  meshApp->add_option("--septum", c.mesh.septum, "Direction toward the septum in the file's frame: x,y,z");
  meshApp->add_option("--mitral-loop", c.mesh.mitralLoop, "Boundary loop number of the mitral annulus (default: the larger)");
  meshApp->add_option("--aortic-loop", c.mesh.aorticLoop, "Boundary loop number of the aortic annulus");
  meshApp->add_option("--epicardium", c.mesh.epicardium, "An epicardial surface file for --wall");
}

std::string joinedNames(const std::vector<CLI::App*>& subcommands) {
  std::string names;
  for (const CLI::App* sub : subcommands) names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

// A word where a subcommand is expected that names none ("heartsim frobnicate", "heartsim
// validate foo"), as a one-line message with the valid names; nothing when every such word is
// known (options and the rest are the parser's business).
std::optional<std::string> unknownSubcommand(CLI::App& app, int argc, char** argv) {
  CLI::App* level = &app;
  std::string kind = "command";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    const std::vector<CLI::App*> subcommands = level->get_subcommands([](CLI::App*) { return true; });
    if (word.empty() || word[0] == '-' || subcommands.empty()) return std::nullopt;
    const auto named = std::find_if(subcommands.begin(), subcommands.end(),
                                    [&word](const CLI::App* sub) { return sub->check_name(word); });
    if (named == subcommands.end()) return "unknown " + kind + " '" + word + "'; expected one of: " + joinedNames(subcommands);
    level = *named;
    kind = level->get_name() == "validate" ? "validation" : "command";
  }
  // The words ran out where a subcommand is still expected ("heartsim", "heartsim validate").
  const std::vector<CLI::App*> subcommands = level->get_subcommands([](CLI::App*) { return true; });
  if (subcommands.empty()) return std::nullopt;
  return "missing " + kind + "; expected one of: " + joinedNames(subcommands);
}

// The parsed subcommand's exit code.
int dispatch(Commands& c) {
  using namespace hs::app;
  if (c.runApp->parsed()) {
    if (c.runApp->count("--duration") > 0) c.run.duration = c.duration;
    if (c.runApp->count("--checkpoint-every") > 0) c.run.checkpointEvery = c.checkpointEvery;
    if (c.runApp->count("scenario") == 0) {
      if (c.run.resume.empty()) {
        std::cerr << "heartsim: error: run: a scenario is required (or --resume FILE) (see heartsim --help)\n";
        return kExitBadInput;
      }
      c.run.scenario.clear();
    }
    return runCommand(c.run);
  }
  if (c.renderApp->parsed()) {
    if (c.renderApp->count("--clip") + c.renderApp->count("--no-clip") > 0) c.render.clip = c.renderClip;
    return renderCommand(c.render);
  }
  if (c.viewApp->parsed()) return viewCommand(c.view);
  if (c.benchApp->parsed()) return benchCommand(c.bench);
  if (c.damBreakApp->parsed()) return validateDamBreakCommand(c.validate);
  if (c.compareApp->parsed()) return compareCommand(c.compare);
  if (c.meshApp->parsed()) return meshCommand(c.mesh);
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hs::app;
  CLI::App app{"heartsim: an interactive simulator of the heart's left ventricle and its blood flow"};
  app.set_version_flag("--version", std::string("heartsim ") + HS_VERSION + " (git " + HS_GIT_REVISION + ")");
  app.require_subcommand(1);
  Commands commands;
  addRunCommand(app, commands);
  addRenderCommand(app, commands);
  addViewCommand(app, commands);
  addBenchCommand(app, commands);
  addValidateCommand(app, commands);
  addCompareCommand(app, commands);
  addMeshCommand(app, commands);
  if (const std::optional<std::string> unknown = unknownSubcommand(app, argc, argv)) {
    std::cerr << "heartsim: error: " << *unknown << " (see heartsim --help)\n";
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "heartsim: error: " << e.what() << " (see heartsim --help)\n";
    return kExitBadInput;
  }
  try {
    return dispatch(commands);
  } catch (const std::exception& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
}
