// The blood's resolution at start-up (viewer_app_internal.h): the levels measured while the
// first frames draw, the finest that holds real time started; and the scripted run's last line.
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "viewer/app/viewer_app_internal.h"

namespace hs::viewer::detail {

void ViewerApp::startResolutionProbe() {
  if (m_options.resolution || !m_options.bloodFixedBy.empty() || !m_baseScenario.blood.enabled) return;
  std::vector<std::pair<BloodResolution, cardiac::Scenario>> levels;
  for (const ResolutionLevel& l : kResolutionLevels) {
    ViewerControls controls = m_controls;
    controls.blood.resolution = l.level;
    controls.blood.particlesEdited = false;
    levels.emplace_back(l.level, configuredScenario(m_baseScenario, controls, m_region));
  }
  m_runner.access([](SimulationState& s) { s.playing = false; });
  m_sentPlaying = false;
  m_probe = std::make_unique<ResolutionProbe>(std::move(levels), m_options.threads);
  m_status.resolution.measuring = true;
  m_status.resolution.measuringWhat = m_probe->progress();
}

void ViewerApp::followProbe() {
  if (m_probe && !m_probe->done()) {
    m_status.resolution.measuringWhat = m_probe->progress();
    return;
  }
  if (m_probe) {
    const std::vector<LevelMeasurement> results = m_probe->measurements();
    m_probe.reset();
    m_status.resolution.measuring = false;
    std::string measured;
    for (const LevelMeasurement& m : results) {
      if (!m.measured) continue;
      m_measuredPace[std::size_t(m.level)] = m.pace;
      char text[64];
      std::snprintf(text, sizeof text, "%s%s %.2gx", measured.empty() ? "" : ", ", resolutionName(m.level), m.pace);
      measured += text;
    }
    const BloodResolution chosen = chooseResolution(results);
    m_controls.blood.resolution = chosen;
    m_controls.blood.particlesEdited = false;
    if (chosen != m_runningBlood.resolution) {
      restart(std::string("blood ") + resolutionName(chosen));
    } else {
      m_status.resolution.measuredPace = m_measuredPace[std::size_t(chosen)];
    }
    const bool holds = m_measuredPace[std::size_t(chosen)].value_or(0) >= kHoldsRealTimePace;
    m_status.message = std::string("blood resolution: ") + resolutionName(chosen) + ", " +
                       (holds ? "the finest that holds real time on this computer"
                              : "the coarsest, still slower than real time on this computer") +
                       (measured.empty() ? "" : " (measured: " + measured + ")");
    std::fprintf(stderr, "heartsim: %s\n", m_status.message.c_str());
  }
  if (!m_paceStart) {
    // Let go: from here the scripted run's pace is measured.
    m_paceStart = Clock::now();
    m_runner.access([&](SimulationState& s) {
      m_simulatedAtStart = s.simulatedSeconds;
      m_steppingAtStart = s.steppingSeconds;
    });
  }
}

void ViewerApp::reportScriptedRun(const std::vector<double>& seconds) {
  std::optional<SimulationPace> pace;
  if (m_paceStart) {
    pace.emplace();
    pace->wallSeconds = std::chrono::duration<double>(Clock::now() - *m_paceStart).count();
    m_runner.access([&](SimulationState& s) {
      pace->simulatedSeconds = s.simulatedSeconds - m_simulatedAtStart;
      pace->steppingSeconds = s.steppingSeconds - m_steppingAtStart;
      const cardiac::HeartSimulation& sim = *s.sim;
      pace->particles = sim.hasBlood() ? int(sim.particles().size() - sim.firstBloodParticle()) : 0;
    });
  }
  std::fprintf(stderr, "%s\n", scriptedRunLine(summariseFrameTimes(seconds, 10), pace).c_str());
  if (!m_status.liquidNote.empty()) std::fprintf(stderr, "heartsim: %s\n", m_status.liquidNote.c_str());
}

}  // namespace hs::viewer::detail
