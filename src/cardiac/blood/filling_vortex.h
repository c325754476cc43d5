#pragma once
// The E-wave filling vortex: the ring the mitral jet rolls up behind its front in early filling,
// read as 4D-flow MRI reads it (Elbaz et al. 2014, "Vortex flow during early and late left
// ventricular filling in normal subjects", JCMR 16:78: the E-vortex core at 0.19 +/- 0.04 of the
// long axis from the mitral annulus plane). At each beat's E-wave peak (the step of the largest
// lumped mitral flow before the atrial kick) the blood's velocity is read on the long-axis cut
// (pbd/fluid/plane_field.h), the vortex cores found in its vorticity where the flow swirls
// (pbd/fluid/vortex_cores.h: vorticity extrema that pass the plane's lambda-2 test, as Elbaz et
// al. found the ring with lambda-2; the jet's shear layers, as strong in vorticity, do not swirl),
// and the ring's place and strength reported:
//   position    = depth of the cores below the mitral plane / the long axis
//   circulation = |Gamma| of the cores (each the integral of omega over its half-peak region,
//                 half a Lamb-Oseen core's total: vortex_cores.h), the mean of the ring's two.
//
// The cut: the plane that holds the LV's long axis (the model's y axis through the endocardial
// spheroid's centre, lv_model.h) and the mitral orifice's centre: the three-chamber view (the
// apex, the mitral and, on the procedural heart, the aortic orifice; aha_segments.h), in which
// the mitral jet and both cores of its ring lie. The mitral plane: through the mitral orifice's
// centre, across the long axis. The long axis: from that plane to the farthest point of the
// cavity's surface (the endocardial apex) where the wall is now, as anatomy/lv_anatomy.h measures
// it at rest.
#include <array>
#include <optional>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/circulation/heart_phase.h"
#include "pbd/core/state_stream.h"
#include "pbd/fluid/plane_field.h"
#include "pbd/fluid/vortex_cores.h"

namespace hs::cardiac {

using pbd::Vec3d;

// Below this peak vorticity a core is particle noise, not the ring: the E-vortex's cores turn at
// ~100/s (an E wave of 0.7 m/s shed across a shear layer of ~5 mm); PBF's noise in a still
// ventricle stays at a few per second after the Shepard average.
inline constexpr double kVortexMinPeak = 10.0;  // 1/s
// The ring's second core holds at least this share of the first's circulation (readEVortex).
inline constexpr double kPartnerShare = 0.25;

// The long-axis cut's frame, where the wall is now.
struct LongAxisCut {
  Vec3d mitralCentre = Vec3d::Zero();
  Vec3d down = -Vec3d::UnitY();  // along the long axis, toward the apex
  Vec3d across = Vec3d::UnitX(); // in the cut, across the long axis, from the mitral orifice toward the axis
  Vec3d axisAtMitralPlane = Vec3d::Zero();  // where the long axis crosses the mitral plane
  double longAxis = 0;           // m, mitral plane to the endocardial apex
  double mitralRadius = 0;       // m, the mitral orifice's
  double leafletLength = 0;      // m, how far its open leaflets hang (FlowPath::mitralLeafletLength)
  [[nodiscard]] double depth(const Vec3d& x) const { return down.dot(x - mitralCentre); }
};

// `path`: the flow path where the base is now (FlowPath::descended); `positions`: the particles
// (the model's vertices first, heart_simulation.h).
LongAxisCut longAxisCut(const LvModel& model, const FlowPath& path, std::span<const pbd::Vec3> positions);

// One reading of the ring.
struct EVortexSample {
  double time = 0, mitralFlow = 0;  // s; m^3/s (lumped)
  bool found = false;               // at least one core below the mitral plane
  double position = 0;              // share of the long axis from the mitral plane
  double depth = 0, longAxis = 0;   // m
  double circulation = 0;           // m^2/s, > 0
  std::array<double, 2> coreDepth{}, coreCirculation{};  // the clockwise-in-the-cut (omega > 0) and the other; 0 if absent
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// What the picture draws: the field, its vorticity, the cores and the frame.
struct EVortexView {
  LongAxisCut cut;
  pbd::PlaneField field;
  std::vector<double> omega;
  std::vector<pbd::VortexCore> cores;  // every core found, strongest first
  std::array<int, 2> ring{-1, -1};     // indices into `cores` of the ring's two (-1: none)
  EVortexSample sample;
};

// The grid over the cut (u = across, v = down: n = u x v, the sense of positive omega) covering
// the cavity, `nodeSpacing` apart, from a few nodes above the mitral plane to past the apex.
pbd::PlaneGrid longAxisGrid(const LongAxisCut& cut, const LvModel& model, std::span<const pbd::Vec3> positions,
                            double nodeSpacing);

// The ring from the field on the cut: the strongest core of each sign below the mitral plane,
// the weaker dropped when it holds less than kPartnerShare of the stronger's circulation.
EVortexView readEVortex(const LongAxisCut& cut, pbd::PlaneField field, double time, double mitralFlow);

// One beat's E-vortex: its early filling's index in the run (1 = the first), whether the run saw
// it from its start, and the reading at its E peak.
struct EVortexBeat {
  int beat = 0;
  bool complete = false;
  EVortexSample sample;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// When to read: each step says whether it is early filling (filling before the atrial kick) and
// the lumped mitral flow; a step whose flow is the beat's largest yet is a new E peak, read then
// (the reading is kept while the flow still rises, so the last kept is the peak's: the field is
// read on the rising E wave's steps only, a tenth of the beat).
class FillingVortex {
 public:
  // True when this step is to be read (then call keep()).
  bool step(bool earlyFilling, double mitralFlow);
  void keep(EVortexView view);
  [[nodiscard]] const std::vector<EVortexBeat>& beats() const { return m_beats; }
  // The view at the E peak of the last closed beat (not in checkpoints: a resumed run has one
  // after its next beat).
  [[nodiscard]] const std::optional<EVortexView>& lastBeatView() const { return m_lastView; }
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  bool m_open = false, m_seenOutside = false, m_complete = false;
  int m_count = 0;
  double m_peakFlow = 0;
  std::optional<EVortexSample> m_best;
  std::optional<EVortexView> m_view, m_lastView;
  std::vector<EVortexBeat> m_beats;
};

}  // namespace hs::cardiac
