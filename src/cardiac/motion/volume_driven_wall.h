#pragma once
// The wall moved so that the 3D cavity holds the volume the lumped circulation gives
// (lumped_circulation.h): the 3D heart follows the 0D one step by step, and the cavity volume
// never jumps. The motion is a heart's (Rushmer 1956; Rogers et al. 1991, MRI tagging; Carlsson
// et al. 2007): the base, with the valve plane and the vessels' roots, descends toward a still
// apex (longitudinal shortening), the epicardium moves a little toward the long axis, and the
// myocardium, incompressible, thickens: the endocardium moves in as far as the wall's volume
// requires. One scalar a, the contraction, sets the motion: at a the base has descended
// d = a `longitudinal` L (L the long axis) and the epicardium has moved in by a `radial` of its
// radius; the beating wall is then the shell between two half prolate spheroids,
//   epicardium   a_o' = a_o (1 - a radial),  c_o' = c_o - d   (the apex stays),
//   endocardium  a_i' = a_o' - h',           c_i' = c_o' - h',
// whose thickness h' keeps the wall's volume, a_o'^2 c_o' - a_i'^2 c_i' = a_o^2 c_o - a_i^2 c_i
// (the thickening is uniform). Each beating vertex is mapped from its rest spheroid to the new
// one (x, z scaled, y scaled below the descended base plane); toward the base, the radial part
// fades, for the fibrous base plate does not shorten. The base plate descends by d, the
// vessels less toward their pinned far ends.
//
// The driven vertices are kinematic (their inverse mass is 0 while the lumped circulation
// drives them): a linear tetrahedron one element thick cannot keep its volume tet by tet while
// the endocardium shrinks more than the epicardium (volumetric locking), so its constraints
// would hold the wall back. The parts that do not beat (an akinetic segment) descend with the
// base but take the radial motion only in their border zone, fading with the distance from the
// beating wall (volume_driven_wall.cpp, kBorderZone). The free vertices (the vessels near their
// pinned ends, the rims) are left to the constraints, so the cavity's volume V(a) is not known in
// closed form. Each step a is found by Newton's method on the predicted shape's volume V_p(a)
// (driven vertices moved, others at rest), corrected by what the constraints did to it in the
// last step:
//   V_p(a_n) + (V_measured,n-1 - V_p(a_n-1)) = V_target,n.
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "pbd/core/state_stream.h"

namespace hs::cardiac {

struct WallMotionSettings {
  Real longitudinal = Real(0.15);  // base descent at a = 1, share of the long axis
  Real radial = Real(0.1);         // epicardium's inward travel at a = 1, share of its radius
};

class VolumeDrivenWall {
 public:
  // `beating`: model vertices chosen to beat (cycle.segments etc.); only they contract (the others
  // move in only in their border zone). The base plate and the vessels descend with the base by
  // the beating share of the myocardium.
  VolumeDrivenWall(const LvModel& model, const std::vector<Index>& beating, Index firstParticle,
                   const WallMotionSettings& settings = {});

  // Sets the driven particles' predictions for a cavity of `targetVolume` (m^3), given the
  // positions at the step's start (their cavity volume is what the last step reached).
  void drive(const std::vector<Vec3>& positions, std::vector<Vec3>& predicted, double targetVolume);

  // Model vertices the wall drives (kinematic while it does).
  [[nodiscard]] const std::vector<Index>& drivenVertices() const { return m_driven; }
  // Share of the myocardium's cavity-side vertices that beat, in [0, 1].
  [[nodiscard]] double beatingShare() const { return m_beatingShare; }
  [[nodiscard]] double contraction() const { return m_contraction; }
  [[nodiscard]] double maxContraction() const { return m_maxContraction; }
  // The predicted shape's cavity volume at contraction a (m^3).
  [[nodiscard]] double predictedVolume(double a) const;
  // Base-plane descent at contraction a (m), along the long axis.
  [[nodiscard]] double baseDescent(double a) const;
  // Checkpoints: the last step's contraction and predicted volume.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  // How a driven vertex moves: `kind` picks the map, `share` is the descent share of a vessel
  // vertex and the radial taper of a myocardium vertex.
  enum class Kind : std::uint8_t { Endocardium, Epicardium, Base, Vessel };
  struct Driven {
    Index vertex;
    Kind kind;
    Real share;
  };
  struct Spheroids {  // the beating wall at one contraction (m): base plane y = -descent
    double descent, endoRadius, endoLong, epiRadius, epiLong;
  };
  [[nodiscard]] Spheroids wallAt(double a) const;
  [[nodiscard]] Vec3 place(const Driven& d, const Spheroids& wall) const;
  void placeAll(double a, std::vector<Vec3>& out, Index offset) const;

  const LvModel* m_model;
  Index m_firstParticle;
  WallMotionSettings m_settings;
  std::vector<Index> m_driven;         // model vertices
  std::vector<Driven> m_motion;        // per driven vertex
  Spheroids m_rest{};
  double m_wallVolume = 0;             // a_o^2 c_o - a_i^2 c_i (m^3, without 2 pi / 3)
  double m_beatingShare = 0;
  double m_longitudinalTravel = 0;     // m at a = 1
  double m_maxContraction = 0;         // the endocardium's two radii stay above a fifth of rest
  double m_contraction = 0;            // a of the last step
  double m_lastPredicted = 0;          // V_p(a) of the last step
  bool m_started = false;
  mutable std::vector<Vec3> m_scratch;  // the predicted shape
};

}  // namespace hs::cardiac
