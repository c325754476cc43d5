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
// The epicardium. Left to the wall's constraints (one tet across the wall), the epicardium of a
// contracting recording folded: its edges and areas resist the shortening the recording asks of
// them, and the surface buckles (biv-me ejecting 30%: folds in the outer wall at end-systole,
// the worst tet 58% off its volume). The myocardium is incompressible, so the wall thickens as
// the endocardium shrinks; each epicardial vertex is placed by that rule instead, from its
// endocardial partner i along the direction d_i(t) the wall was extruded along (the
// endocardium's normals smoothed by ExtrusionSettings::normalSmoothing Jacobi sweeps,
// wall_extrusion.h), as it turns with the endocardium:
//   x_epi = x_i + h_i(t) d_i(t) + sqrt(a / a0) R_i(t) s_i,
// with s_i the rest offset's part across d_i(0), turned by the smallest rotation R_i(t) that
// takes d_i(0) to d_i(t) and stretched as the endocardium's patch is (a its area), and h_i(t)
// the thickness that keeps the volume of the wall's patch over i. The patch is a piece of a
// spherical shell of solid angle Omega (its endocardial area a = Omega r^2, its epicardial area
// Omega (r + h)^2, found from the rest areas: (1 + h0 / r0)^2 = a_epi / a_endo), so as the
// endocardial area goes from a0 to a, r = r0 sqrt(a / a0) and
//   (r + h)^3 - r^3 = (r0 + h0)^3 - r0^3.
// Where the wall is flat or concave (a_epi <= a_endo) the thin-wall limit h = h0 a0 / a holds.
// The smoothed directions matter: the raw normals turn sharply where the endocardium bends, over
// the rims of the annuli and below the base in systole, and offsets along them crossed within
// the wall's thickness (on the tests' recording of a ventricle's motion, lv_beat_frames.h, a tet
// of AHA segment 1 three edges from the annuli turned inside out at 0.243 s;
// docs/patient-meshes.md). Along the smoothed directions every vertex of the wall is driven, the
// rims too, so whether the wall can follow a recording is known before the first step (findFold).
// The vessels. The vessels raised on the annuli follow them as the procedural heart's follow
// its base (volume_driven_wall.h): a vessel vertex moves by its share of its ring vertex's
// displacement, 1 at the ring and 0 at the pinned far end (LvModel::vesselFollowers).
//
// The driven vertices are kinematic (inverse mass 0): the recording, not the constraints or
// the blood, sets where the wall is; only the vertices of a base plate made for a truncated
// ventricle are left to the constraints (the solver lists the constraints that touch them and
// skips the rest unread).
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/patient/patient_wall.h"
#include "pbd/core/state_stream.h"

namespace hs::cardiac {

// The periodic Catmull-Rom spline over `count` evenly spaced knots at time t of a beat of
// length `period`: the four knots around t and their weights (they sum to 1).
struct SplineWeights {
  int knot[4] = {0, 0, 0, 0};
  double weight[4] = {0, 0, 0, 0};
};
SplineWeights periodicCatmullRom(double time, double period, int count);

// Where the wall cannot follow a recording at some step of one beat: the tets driven wholly by
// it (all four vertices) whose volume is gone (signed volume <= 0), and the endocardial
// triangles that turn over (their normal more than 90 degrees from its rest direction, n . n0
// <= 0: the surface folded back on itself, as where a segment is pushed through the cavity;
// the wall over such a fold can keep its tets positive and still pass through itself).
struct RecordedFold {
  int tets = 0;                         // how many tets turn inside out at some step
  int triangles = 0;                    // how many endocardial triangles turn over at some step
  double firstTime = -1;                // s, the first such step
  int firstFrame = -1, lastFrame = -1;  // the frames nearest the steps where one does
  std::vector<int> segments;            // their AHA segments (of each one's first vertex), sorted
  double smallestShare = 1;             // the least V / V_rest of a driven tet over the beat
};

class RecordedBeat {
 public:
  // `model` built from `wall` (lvModelFromPatientWall: endocardial wall vertex i is model
  // vertex 2i); `frames` in the file's frame and units (wall.frame places them), each with the
  // vertices and triangles of frames[0]; `period` in s. Throws std::invalid_argument for fewer
  // than 2 frames, frames of different sizes, or a period that is not positive.
  RecordedBeat(const LvModel& model, const PatientWall& wall, const std::vector<Surface>& frames, double period,
               Index firstParticle);

  // Sets the driven particles' predictions to the recorded shape at `time` (s): the
  // endocardium from the frames, then the epicardium over it.
  void drive(double time, std::vector<Vec3>& predicted) const;
  // The recorded cavity volume (m^3) at `time`.
  [[nodiscard]] double recordedVolume(double time) const;
  // Compares the 3D cavity volume at `time` with the recorded one: volumeErrorMax() keeps the
  // largest |V_3D - V_recorded| / V_recorded.
  void observe(double time, double cavityVolume);
  // The wall driven through one beat at the steps of `dt` (s) the run takes, (k + 1) dt, and
  // every driven tet's volume and endocardial triangle's facing checked: the run inverts a tet
  // of the driven wall exactly when this finds one.
  [[nodiscard]] RecordedFold findFold(double dt) const;

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
  // The epicardial partner of a driven endocardial vertex (see the header's comment).
  struct EpicardialPatch {
    Index vertex;          // model vertex 2i + 1
    Vec3d across;          // s_i: the rest offset's part across d_i(0) (m)
    double restArea;       // a0: the endocardial vertex's area at rest (m^2)
    double restThickness;  // h0 (m)
    double restRadius;     // r0 of the spherical patch (m); 0 where the wall is flat or concave
  };
  [[nodiscard]] double thicknessAt(const EpicardialPatch& patch, double area) const;
  // x holds the model's vertices from x[first].
  void driveAt(double time, std::vector<Vec3>& x, Index first) const;
  // d_i and the endocardial areas of the endocardium at x (into m_direction, m_area).
  void findDirections(const std::vector<Vec3>& x, Index first) const;
  void placeEpicardium(std::vector<Vec3>& x, Index first) const;
  // The vessels, carried by the annuli already placed.
  void carryVessels(std::vector<Vec3>& x, Index first) const;

  const LvModel* m_model = nullptr;
  std::vector<Index> m_driven;                 // model vertices: the endocardial ones, then the others
  std::vector<Index> m_endocardial;            // driven endocardial model vertices (2i)
  std::vector<Vec3> m_rest;                    // per driven endocardial vertex
  std::vector<std::vector<Vec3>> m_offset;     // per frame, per driven endocardial vertex: from its rest (m)
  std::vector<EpicardialPatch> m_epicardium;   // the driven epicardial vertices
  std::vector<VesselFollower> m_vessels;       // the vessels' vertices on driven ring vertices
  std::vector<std::vector<Index>> m_neighbours;  // per model vertex: its neighbours on the endocardium
  std::vector<Vec3d> m_restDirection;          // per model vertex: d_i(0)
  mutable std::vector<Vec3d> m_direction;      // scratch per model vertex: d_i(t)
  mutable std::vector<double> m_area;          // scratch per model vertex: the endocardium's area
  std::vector<double> m_frameVolume;           // m^3, per frame
  double m_period = 0;
  Index m_firstParticle = 0;
  double m_volumeErrorMax = 0;
};

}  // namespace hs::cardiac
