#include "viewer/app/pacing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "viewer/panels/blood_resolution.h"

namespace hs::viewer {

bool Pacer::elapse(double wallSeconds, double speed, double dt) {
  speed = std::max(speed, 0.0);
  m_debt += std::max(wallSeconds, 0.0) * speed;
  // At least one step may always be owed, however slow the speed.
  const double limit = std::max(kMaxLagSeconds * speed, dt);
  if (m_debt <= limit) return false;
  m_debt = limit;
  return true;
}

double Pacer::secondsUntilDue(double dt, double speed) const {
  if (due(dt)) return 0;
  if (speed <= 0) return std::numeric_limits<double>::infinity();
  return (dt - m_debt) / speed;
}

void PaceMeter::add(double wallSeconds, double simSeconds, bool dropped) {
  m_wall += std::max(wallSeconds, 0.0);
  m_sim += simSeconds;
  m_dropped = m_dropped || dropped;
  if (m_wall < kWindowSeconds) return;
  m_factor = m_sim / m_wall;
  m_lastDropped = m_dropped;
  m_wall = m_sim = 0;
  m_dropped = false;
}

FrameTimeSummary summariseFrameTimes(const std::vector<double>& seconds, std::size_t skip) {
  FrameTimeSummary summary;
  if (seconds.size() <= skip) skip = 0;
  std::vector<double> kept(seconds.begin() + std::ptrdiff_t(skip), seconds.end());
  if (kept.empty()) return summary;
  double sum = 0;
  for (double s : kept) sum += s;
  summary.frames = int(kept.size());
  summary.meanMs = 1000 * sum / double(kept.size());
  summary.fps = summary.meanMs > 0 ? 1000 / summary.meanMs : 0;
  // Nearest rank: the smallest time at least 95% of the frames do not exceed.
  const auto rank = std::size_t(std::ceil(0.95 * double(kept.size())));
  std::nth_element(kept.begin(), kept.begin() + std::ptrdiff_t(rank - 1), kept.end());
  summary.p95Ms = 1000 * kept[rank - 1];
  return summary;
}

std::string scriptedRunLine(const FrameTimeSummary& f, const std::optional<SimulationPace>& simulation) {
  char text[256];
  std::snprintf(text, sizeof text, "heartsim: %d frames: %.1f ms mean, %.1f fps, 95%% within %.1f ms", f.frames,
                f.meanMs, f.fps, f.p95Ms);
  std::string line = text;
  if (!simulation || simulation->wallSeconds <= 0) return line + "; simulation not started";
  const SimulationPace& p = *simulation;
  std::snprintf(text, sizeof text, "; simulation %.2fx real time (stepping %.0f%% of the time), ",
                p.simulatedSeconds / p.wallSeconds, 100 * std::min(p.steppingSeconds / p.wallSeconds, 1.0));
  line += text;
  return line + (p.particles > 0 ? withThousands(p.particles) + " particles" : std::string("no blood"));
}

}  // namespace hs::viewer
