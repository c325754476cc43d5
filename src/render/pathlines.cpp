#include "render/pathlines.h"

#include <algorithm>

namespace hs::render {

PathlineRecorder::PathlineRecorder(double window, int stride) : m_window(window), m_stride(std::max(1, stride)) {}

void PathlineRecorder::record(const cardiac::HeartSimulation& sim) {
  if (!sim.hasBlood()) return;
  const double now = sim.time();
  if (!m_samples.empty() && now < m_samples.back().time) m_samples.clear();
  if (!m_samples.empty() && now == m_samples.back().time) return;
  const pbd::Particles& p = sim.particles();
  const std::size_t first = sim.firstBloodParticle();
  const std::size_t seeds = (p.size() - first + std::size_t(m_stride) - 1) / std::size_t(m_stride);
  Sample sample;
  sample.time = now;
  sample.position.assign(seeds, Vec3f::Zero());
  sample.active.assign(seeds, 0);
  for (std::size_t i = first; i < p.size(); ++i) {
    const std::size_t serial = std::size_t(p.id[i]) - first;  // ids of blood start at `first`
    if (serial % std::size_t(m_stride) != 0 || serial / std::size_t(m_stride) >= seeds) continue;
    sample.position[serial / std::size_t(m_stride)] = p.position[i].cast<float>();
    sample.active[serial / std::size_t(m_stride)] = sim.bloodActive(pbd::Index(i)) ? 1 : 0;
  }
  m_samples.push_back(std::move(sample));
  while (m_samples.size() > 2 && m_samples[1].time <= now - m_window) m_samples.pop_front();
}

std::vector<PathlineRecorder::Segment> PathlineRecorder::segments() const {
  std::vector<Segment> out;
  if (m_samples.size() < 2) return out;
  const double newest = m_samples.back().time;
  for (std::size_t s = 1; s < m_samples.size(); ++s) {
    const Sample& a = m_samples[s - 1];
    const Sample& b = m_samples[s];
    const float dt = float(b.time - a.time);
    for (std::size_t k = 0; k < std::min(a.position.size(), b.position.size()); ++k) {
      if (!a.active[k] || !b.active[k]) continue;
      const float speed = (b.position[k] - a.position[k]).norm() / dt;
      if (!(speed <= kMaxSpeed)) continue;
      out.push_back({a.position[k], b.position[k], speed, float(newest - b.time)});
    }
  }
  return out;
}

}  // namespace hs::render
