#pragma once
// The wall moved so that the 3D cavity holds the volume the lumped circulation gives
// (lumped_circulation.h): the 3D heart follows the 0D one step by step, and the cavity volume
// never jumps. The motion is a heart's (Rushmer 1956; Rogers et al. 1991, MRI tagging): the
// base, with the valve plane and the vessels' roots, descends toward a nearly still apex
// (longitudinal shortening, `longitudinal` of the long axis at a = 1), and the beating
// segments move toward the long axis (radial shortening, `radial` of their distance from it).
// One scalar a, the contraction, scales both: each driven vertex is predicted at
//   p_v = X_v + a D_v        (X_v its rest position, D_v its displacement at a = 1).
// The wall's own constraints then act on every vertex, and the vertices not driven follow,
// so the cavity's volume V(a) is not known in closed form. Each step a is found by Newton's
// method on the predicted shape's volume V_p(a) (driven vertices moved, others at rest),
// corrected by what the constraints did to it in the last step:
//   V_p(a_n) + (V_measured,n-1 - V_p(a_n-1)) = V_target,n.
// The correction changes slowly, so the cavity tracks the target within a step's change.
#include <vector>

#include "cardiac/lv_model.h"

namespace hs::cardiac {

struct WallMotionSettings {
  Real longitudinal = Real(0.15);  // base descent at a = 1, share of the long axis
  Real radial = Real(0.4);         // inward travel of a beating vertex at a = 1, share of its radius
};

class VolumeDrivenWall {
 public:
  // `beating`: model vertices chosen to beat (cycle.segments etc.); only they move inward.
  // The base plate and the vessels descend with the base (the vessels less toward their
  // pinned far ends), by the beating share of the myocardium.
  VolumeDrivenWall(const LvModel& model, const std::vector<Index>& beating, Index firstParticle,
                   const WallMotionSettings& settings = {});

  // Sets the driven particles' predictions for a cavity of `targetVolume` (m^3), given the
  // positions at the step's start (their cavity volume is what the last step reached).
  void drive(const std::vector<Vec3>& positions, std::vector<Vec3>& predicted, double targetVolume);

  // Share of the myocardium's cavity-side vertices that beat, in [0, 1].
  [[nodiscard]] double beatingShare() const { return m_beatingShare; }
  [[nodiscard]] double contraction() const { return m_contraction; }
  // The predicted shape's cavity volume at contraction a (m^3).
  [[nodiscard]] double predictedVolume(double a) const;
  // Base-plane descent and apex travel at contraction a (m), along the long axis.
  [[nodiscard]] double baseDescent(double a) const;

 private:
  const LvModel* m_model;
  Index m_firstParticle;
  std::vector<Index> m_driven;         // model vertices
  std::vector<Vec3> m_displacement;    // D_v at a = 1, per driven vertex
  double m_beatingShare = 0;
  double m_longitudinalTravel = 0;     // m at a = 1
  double m_contraction = 0;            // a of the last step
  double m_lastPredicted = 0;          // V_p(a) of the last step
  bool m_started = false;
  mutable std::vector<Vec3> m_scratch;  // the predicted shape
};

}  // namespace hs::cardiac
