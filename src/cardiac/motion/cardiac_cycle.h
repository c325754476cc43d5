#pragma once
// The cardiac cycle acting on the wall (thesis 4.3): beating regions, each with its own
// BeatClock, move their vertices toward the heart centre during systole (Algorithm 3) and
// are released in diastole so the wall constraints restore the rest shape.
// Patterns: normal (one region, regular), irregular (diastoles cut short at random) and
// inconsistent (some segments beat with another rate and phase than the rest).
// Thesis mode moves each beating vertex by BEATING_DISPLACE per systolic step (Algorithm 3);
// the constraints push back every step, so the wall's net travel depends on its stiffness.
// Physiological mode prescribes the path instead. In systole a beating vertex goes from its
// anchor (where it was when the systole began) to its end-systolic target, the rest position
// moved `contraction` toward the centre, along anchor + F(s) (target - anchor) with the clock's
// smooth ramp F: from rest it travels exactly `contraction`. In the first `relaxationFraction`
// of a regular diastole it returns the same way to its rest position, then it is released to
// the wall's constraints. The end-systolic shape is fixed (as the heart's is, by its
// contractility), so a diastole cut short (irregular pattern) starts the next systole from a
// smaller volume and the beat ejects less: the thesis expert's "not fully released" beat.
// With cycle.base_held the end-systolic shape is a thickened shell (cardiac_cycle.cpp,
// heldShell) and the beating vertices are kinematic, as the lumped circulation's wall's are
// (volume_driven_wall.h): their constraints, which keep each surface triangle's area, would
// otherwise fold an endocardium that must shrink (surface turns of 80-111 degrees at 7-10 mm of
// contraction on the patient hearts); they follow their paths the whole beat, at rest after the
// relaxation. Under two-way coupling they keep their mass (heart_simulation.cpp), so the blood
// can push the held wall as it pushes any other.
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/circulation/beat_clock.h"
#include "cardiac/motion/cycle_settings.h"
#include "pbd/core/step_context.h"

namespace hs::cardiac {

struct BeatingRegion {
  std::vector<Index> particles;  // particle ids (model vertex + first particle)
  BeatClock clock;
  std::vector<Vec3> anchor;      // physiological mode: positions when the systole began
  std::vector<Vec3> rest;        // physiological mode: rest positions (the model's vertices)
  std::vector<Vec3> endSystole;  // physiological mode: positions when the diastole began
  std::vector<Vec3> target;      // physiological mode: end-systolic positions (endSystoleTargets)
};

// Model vertices chosen to beat: the union of segments, vertex ids and sphere; all myocardium
// when none is given; never the pinned vessel ends. Throws std::invalid_argument naming the
// key for out-of-range or pinned ids.
std::vector<Index> selectBeatingVertices(const CycleSettings& cycle, const LvModel& model);

// Algorithm 3: moves each particle toward `centre` by `displacement`, never past it. The
// move is kinematic: the start-of-step position x and the prediction p shift together, so it
// changes where the wall is but adds no momentum (v = (p - x)/dt is unchanged). Moving p
// alone would turn every systolic step into velocity and the wall would accelerate inward
// step after step (see docs/cardiac-cycle.md).
void moveTowardCentre(std::vector<Vec3>& positions, std::vector<Vec3>& predicted,
                      const std::vector<Index>& particles, const Vec3& centre, Real displacement);

class CardiacCycle {
 public:
  CardiacCycle(const CycleSettings& cycle, const LvModel& model, Index firstParticle);

  // Moves the beating particles for this step (after prediction) and advances the clocks.
  void apply(std::vector<Vec3>& positions, std::vector<Vec3>& predicted, const pbd::StepContext& context);

  // The clocks alone, for a wall moved by something else (volume_driven_wall.h).
  void advanceClocks(Real dt);

  [[nodiscard]] Phase phase() const;  // of the first (main) region
  [[nodiscard]] int beatsCompleted() const;  // systoles completed by the main region
  [[nodiscard]] const std::vector<BeatingRegion>& regions() const { return m_regions; }
  [[nodiscard]] const Vec3& centre() const { return m_centre; }
  // The beating vertices follow their paths the whole beat (cycle.base_held, physiological): the
  // simulation gives them no mass, except under two-way coupling.
  [[nodiscard]] bool kinematic() const { return m_kinematic; }
  // Checkpoints: each region's clock, anchor and end-systolic positions.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  std::vector<BeatingRegion> m_regions;
  Vec3 m_centre;
  Real m_contraction = 0;           // physiological mode (m)
  double m_relaxationSeconds = 0;   // physiological mode: prescribed return to rest
  bool m_kinematic = false;
};

}  // namespace hs::cardiac
