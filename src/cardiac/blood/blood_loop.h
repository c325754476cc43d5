#pragma once
// The closed loop: the particle count never changes. A particle that passes the far end of
// either vessel has left the model (into the body or back into the atrium). It is parked
// (pbd::ParticleState::Parked: out of the way above the vessels, ignored by the solvers, not
// drawn) and waits in a queue; the first in line re-enters at a free site of the inflow
// vessel's far end, moving with the blood there.
#include <cstddef>
#include <deque>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/blood/blood_settings.h"
#include "pbd/core/particles.h"

namespace hs::cardiac {

using pbd::Index;

class BloodLoop {
 public:
  // `inletLayers`: layers of re-entry sites under the inflow vessel's far end, a spacing apart.
  BloodLoop(const FlowPath& path, const BloodSettings& blood, int inletLayers = 1);

  // The last `count` of the blood particles [first, end) start outside the model, waiting.
  void startWaiting(pbd::Particles& particles, Index first, std::size_t count);

  struct Turnover {
    std::size_t returned = 0;   // parked this step
    std::size_t reentered = 0;  // re-entered this step
  };
  // End of a step: parks the blood past a vessel's far end, then lets waiting blood re-enter.
  Turnover circulate(pbd::Particles& particles, Index first);

  [[nodiscard]] std::size_t waiting() const { return m_queue.size(); }

  // The lumped circulation's inlet (VesselEnds): blood enters in whole layers of sites at rest
  // density (lumenDiscSites) a spacing apart, one layer for each spacing the inflow's plug has
  // moved on (`travel`: m into the heart this step), with the plug's velocity, instead of at
  // the free sites of the plain inlet.
  void meterInlet(Real travel, Real dt);
  // Checkpoints: the metered inlet's progress, the parking lot and the queue.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);


 private:
  [[nodiscard]] Vec3 parkingSite(std::size_t slot) const;
  void park(pbd::Particles& particles, Index particle);
  std::size_t reenter(pbd::Particles& particles, Index first);
  std::size_t enterLayers(pbd::Particles& particles, Index first);
  void locateParked(const pbd::Particles& particles, Index first);
  void enter(pbd::Particles& particles, Index first, const Vec3& site, const Vec3& velocity);

  FlowPath m_path;
  Real m_spacing, m_radius;
  int m_inletLayers;
  bool m_inletMetered = false;
  Real m_inletTravel = 0;  // m the plug has moved on since the last layer entered
  Vec3 m_inletVelocity = Vec3::Zero();
  int m_inletLayer = 0;  // layers entered so far (alternate ones turned by half a site)
  std::vector<Vec3> m_inletSites;  // lattice sites across the inflow vessel's far end
  Vec3 m_parkingOrigin = Vec3::Zero();
  Real m_parkingPitch = 0;
  static constexpr Index kFreeSlot = ~Index(0);
  std::vector<Index> m_lot;    // parking site k holds this particle id (or kFreeSlot)
  std::deque<Index> m_queue;   // parked particle ids, first in first out
  std::vector<Vec3> m_occupied;  // scratch: blood near the inlet
  std::vector<Index> m_parkedAt;  // scratch: particle index of each parked blood id - first id
};

}  // namespace hs::cardiac
