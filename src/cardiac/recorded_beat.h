#pragma once
// A recorded heartbeat driving a patient's wall ([motion], issue 16 item 5): the endocardium
// follows a sequence of endocardial surfaces recorded over one beat (cine MRI frames, each with
// the vertices and triangles of the model's endocardium file), the rest of the wall follows by
// its constraints.
//
// Tying the wall to the frames. The wall was remeshed from the endocardium (patient_wall.h), so
// its vertices are not the file's. Each endocardial wall vertex k is tied to the point of frame
// 0 closest to it, in the heart's frame: a triangle (j1, j2, j3) and barycentric weights w. In
// frame f it moves as that point of the moved triangle does, from where it is at rest:
//   x_k(f) = x_k,rest + sum_j w_kj (X_f,j - X_0,j),
// so the replay starts from the wall's rest shape and a vertex on the surface stays on it.
// Vertices of a base plate made for a truncated ventricle are not on the recording and are
// carried by the constraints.
//
// Time. The beat repeats every `period`; frame f is at t = f period / count. Between frames
// the motion is the periodic Catmull-Rom spline through them (C1 in time, through every
// frame), so the wall's velocity has no jumps at the frames. The recorded volume of a frame is
// its surface closed by flat caps over its boundary loops (pbd::cappedSignedVolume, as
// `heartsim mesh` measures a cavity); the recorded volume at time t is the same spline of the
// frames' volumes.
//
// The driven vertices are kinematic (inverse mass 0): the recording, not the constraints or
// the blood, sets where the endocardium is.
#include <vector>

#include "cardiac/lv_model.h"
#include "cardiac/patient_wall.h"
#include "pbd/state_stream.h"

namespace hs::cardiac {

// The periodic Catmull-Rom spline over `count` evenly spaced knots at time t of a beat of
// length `period`: the four knots around t and their weights (they sum to 1).
struct SplineWeights {
  int knot[4] = {0, 0, 0, 0};
  double weight[4] = {0, 0, 0, 0};
};
SplineWeights periodicCatmullRom(double time, double period, int count);

class RecordedBeat {
 public:
  // `model` built from `wall` (lvModelFromPatientWall: endocardial wall vertex i is model
  // vertex 2i); `frames` in the file's frame and units (wall.frame places them), each with the
  // vertices and triangles of frames[0]; `period` in s. Throws std::invalid_argument for fewer
  // than 2 frames, frames of different sizes, or a period that is not positive.
  RecordedBeat(const LvModel& model, const PatientWall& wall, const std::vector<Surface>& frames, double period,
               Index firstParticle);

  // Sets the driven particles' predictions to the recorded shape at `time` (s).
  void drive(double time, std::vector<Vec3>& predicted) const;
  // The recorded cavity volume (m^3) at `time`.
  [[nodiscard]] double recordedVolume(double time) const;
  // Compares the 3D cavity volume at `time` with the recorded one: volumeErrorMax() keeps the
  // largest |V_3D - V_recorded| / V_recorded.
  void observe(double time, double cavityVolume);

  [[nodiscard]] const std::vector<Index>& drivenVertices() const { return m_driven; }
  [[nodiscard]] int frameCount() const { return int(m_frameVolume.size()); }
  [[nodiscard]] double period() const { return m_period; }
  [[nodiscard]] const std::vector<double>& frameVolumes() const { return m_frameVolume; }
  // The share of the beat before the smallest recorded volume (the frame of end-systole over
  // the count): the cardiac cycle's systole, for the phases and the beats' EDV and ESV.
  [[nodiscard]] double systolicFraction() const;
  [[nodiscard]] double volumeErrorMax() const { return m_volumeErrorMax; }
  // Checkpoints: the largest volume error so far.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  std::vector<Index> m_driven;                 // model vertices
  std::vector<Vec3> m_rest;                    // per driven vertex
  std::vector<std::vector<Vec3>> m_offset;     // per frame, per driven vertex: from its rest (m)
  std::vector<double> m_frameVolume;           // m^3, per frame
  double m_period = 0;
  Index m_firstParticle = 0;
  double m_volumeErrorMax = 0;
};

}  // namespace hs::cardiac
