#include "viewer/pacing.h"

#include <algorithm>
#include <limits>

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

}  // namespace hs::viewer
