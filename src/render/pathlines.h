#pragma once
// Short pathlines of the blood: where a subset of blood particles (the seeds: every stride-th
// by creation id, so the same particles are followed however the solver reorders them) were
// over the last `window` seconds of simulated time. Drawn as streaks, they show where the blood
// goes: the mitral jet in early diastole, the vortex it rolls up, the aortic jet in systole.
// These are true pathlines (the particles' own trajectories, sampled when record() is called),
// not streamlines of one instant's field. Drawing only: the simulation is not touched.
#include <cstdint>
#include <deque>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "render/camera.h"

namespace hs::render {

class PathlineRecorder {
 public:
  // window: seconds of trajectory kept; stride: one seed per this many blood particles.
  explicit PathlineRecorder(double window = 0.02, int stride = 2);

  // Appends the seeds' positions now. Samples older than the window are dropped (the newest
  // one before it is kept, so a streak spans the whole window); a time earlier than the last
  // sample (a restart) starts afresh.
  void record(const cardiac::HeartSimulation& sim);
  void clear() { m_samples.clear(); }

  // One piece of a pathline between consecutive samples: both ends active (not parked), at a
  // speed a heart can give (a particle parked and re-entering between two samples jumps).
  struct Segment {
    Vec3f from, to;
    float speed = 0;  // m/s, |to - from| / (time between the samples)
    float age = 0;    // seconds from `to` to the newest sample: 0 at a streak's head
  };
  [[nodiscard]] std::vector<Segment> segments() const;

  [[nodiscard]] double window() const { return m_window; }
  [[nodiscard]] std::size_t sampleCount() const { return m_samples.size(); }
  // Speeds above this are jumps, not flow (blood in the heart stays below ~6 m/s).
  static constexpr float kMaxSpeed = 20;

 private:
  struct Sample {
    double time = 0;
    std::vector<Vec3f> position;       // per seed
    std::vector<std::uint8_t> active;  // per seed
  };
  double m_window;
  int m_stride;
  std::deque<Sample> m_samples;
};

}  // namespace hs::render
