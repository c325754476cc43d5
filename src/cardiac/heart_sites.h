#pragma once
// Sites of the heart's lumen at the blood's rest density, and how full of blood the vessels
// are, measured on them.
//
// A site stands for the d^3 of lumen around it (d the blood's spacing). The cavity's and the
// vessels' sites are horizontal layers of lumenDiscSites a spacing apart, a particle radius in
// from the walls: blood.start = "heart" puts one particle on each, so the heart starts full at
// rest density (a cubic lattice inside the same surfaces holds only 85% as many).
#include <functional>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/scenario.h"

namespace hs::cardiac {

// The cavity's half spheroid (the endocardium less a particle radius), in layers from a radius
// under the base plane down to the apex.
std::vector<Vec3> cavitySites(const Scenario& scenario);
// The cavity's sites of this model: the spheroid's above, or a patient's (FlowPath::cavity): a
// cubic lattice a spacing apart inside its endocardium closed over the annuli, a particle radius
// from the wall and below the vessels' columns.
std::vector<Vec3> cavitySites(const Scenario& scenario, const LvModel& model);

// Each vessel's lumen, from a spacing above the cavity's top layer (a patient's: a particle
// radius above its orifice's plane, sites a radius from the wall) to a particle radius under
// the vessel's far end, with the blood colour (bloodColour) each site has when the heart is
// full at rest: blood on every site of the cavity and of both vessels.
struct VesselSites {
  std::vector<Vec3> inflow, outflow;
  std::vector<double> inflowFull, outflowFull;
  Real lowest = 0;  // y of the lowest site of either
  // Leaves out the sites where `dropped` holds, with their colours.
  void drop(const std::function<bool(const Vec3&)>& dropped);
  // The sites where a base `descent` below rest carries the lumen: each vessel is stretched
  // between its orifice and its pinned far end, so a site keeps its share u of the vessel's
  // height (FlowPath::descended, vessel_shape.h) and stays where it was across the lumen. A
  // straight vessel's sites would stay inside their lumen unmoved; an atrium's or a sinus's,
  // taken at rest, would end up in the wall.
  [[nodiscard]] VesselSites descended(const FlowPath& path, Real descent) const;
};
VesselSites vesselSites(const Scenario& scenario, const LvModel& model);

// The cavity's sites, then the inflow's, then the outflow's.
std::vector<Vec3> heartSites(const Scenario& scenario, const LvModel& model);

// The SPH colour of blood at each site: c(x) = d^3 sum_j W_poly6(|x - x_j|, h), each particle's
// volume m/rho0 = d^3 times its kernel (thesis eq. 4.8 divided by rho0). It reads about 1
// inside blood at rest density, falls toward 0 across a void, and less near a wall, which
// holds no blood beyond it.
std::vector<double> bloodColour(const std::vector<Vec3>& sites, const std::vector<Vec3>& blood, Real spacing,
                                Real supportRadius);

// Share of `sites` filled with blood: those whose colour is at least half of `full` (their
// colour when the heart is full at rest). The half level is where SPH puts a liquid's surface
// (the colour field's iso-surface, Mueller et al. 2003), so the share counts the lumen on the
// blood's side of its surface: a void a few particles across counts, the gap of one particle
// moved aside (colour about 0.8 of full) does not. Sites taken at rest are first carried where
// the base has moved the lumen (VesselSites::descended).
double vesselFillShare(const std::vector<Vec3>& sites, const std::vector<double>& full,
                       const std::vector<Vec3>& blood, Real spacing, Real supportRadius);

}  // namespace hs::cardiac
