#pragma once
// Setting up a simulation for a command, with the commands' error convention: one line on
// stderr naming the scenario, exit 2 for parameters the model rejects, 1 for anything else.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <vector>

#include "cardiac/blood_resolution.h"
#include "cardiac/heart_simulation.h"
#include "exit_codes.h"
#include "io/scenario/scenario_file.h"

namespace hs::app {

// The level --resolution names, or nullopt after printing why the word is not one. `orAlso`: a
// word the command takes besides the levels (the viewer's "auto"), named in the error.
inline std::optional<cardiac::BloodResolution> resolutionOrReport(const std::string& word,
                                                                  const char* orAlso = nullptr) {
  if (const auto level = cardiac::parseResolution(word)) return level;
  std::cerr << "heartsim: error: --resolution: '" << word << "' is not a blood resolution; expected coarse, medium, "
            << (orAlso ? std::string("fine, finest or ") + orAlso : std::string("fine or finest")) << '\n';
  return std::nullopt;
}

// --resolution as the headless commands take it: unset is the scenario as written (fine).
inline std::optional<cardiac::BloodResolution> levelOrReport(const std::string& word) {
  return word.empty() ? std::optional(cardiac::kScenarioResolution) : resolutionOrReport(word);
}

// The scenario (a built-in name or a .toml path, with --set overrides, its blood at
// --resolution), or nullopt after printing the one-line error (the caller exits with
// kExitBadInput).
inline std::optional<cardiac::Scenario> loadScenarioOrReport(const std::string& nameOrPath,
                                                             const std::vector<std::string>& overrides,
                                                             const std::string& resolution = "") {
  const std::optional<cardiac::BloodResolution> level = levelOrReport(resolution);
  if (!level) return std::nullopt;
  try {
    cardiac::Scenario scenario = io::loadScenario(nameOrPath, overrides);
    cardiac::applyResolution(*level, scenario);
    return scenario;
  } catch (const io::ScenarioError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return std::nullopt;
  }
}

// The simulation, or nullptr after printing the error; exitCode then holds the exit code.
inline std::unique_ptr<cardiac::HeartSimulation> makeSimulation(const cardiac::Scenario& scenario, int threads,
                                                                const std::string& source, int& exitCode) {
  try {
    return std::make_unique<cardiac::HeartSimulation>(scenario, threads);
  } catch (const std::invalid_argument& e) {
    std::cerr << "heartsim: error: " << source << ": " << e.what() << '\n';
    exitCode = kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "heartsim: error: " << source << ": could not set up the simulation: " << e.what() << '\n';
    exitCode = kExitFailure;
  }
  return nullptr;
}

// The output directory (with its parents), or false after printing why it cannot be made (the
// caller exits with kExitFailure).
inline bool createOutputDirOrReport(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) std::cerr << "heartsim: error: " << dir.string() << ": cannot create output directory: " << ec.message() << '\n';
  return !ec;
}

// One line of text (a --json report) on stdout, flushed; false after printing why it could not
// be written (a full disk, a closed pipe: the caller exits with kExitFailure).
inline bool writeStdoutOrReport(const std::string& text) {
  std::cout << text << std::endl;
  if (std::cout) return true;
  std::cerr << "heartsim: error: stdout: cannot write the JSON report (disk full or output closed?)\n";
  return false;
}

}  // namespace hs::app
