#pragma once
// The blood's path through the LV model and what happens on it, in pieces that each do one
// job: inflow vessel -> mitral valve -> ventricle -> aortic valve -> outflow vessel -> (the
// body) -> inflow vessel again.
//   anatomy/flow_path.h      the geometry: orifices, vessel ends, which region a point is in
//   circulation/valves.h     the valves as gates, open by timing or by pressure
//   blood/flow_meter.h       crossings, flows, regions and pressures of each step
//   blood/blood_loop.h       blood that leaves through a vessel's end waits and re-enters
//   blood/filling_force.h    the filling pressure as a body force in the inflow vessel
// HeartSimulation::step() calls each piece at its stage of the step.
#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/blood_loop.h"
#include "cardiac/blood/filling_force.h"
#include "cardiac/blood/flow_meter.h"
#include "cardiac/circulation/valves.h"
#include "cardiac/scenario.h"

namespace hs::cardiac {

struct Circulation {
  Circulation(const LvModel& model, const Scenario& scenario)
      : valves(model.flowPath, scenario.circulation.valveMode, scenario.cycle.enabled, scenario.blood.radius),
        meter(model.flowPath, scenario.blood, scenario.circulation.atrialPressureMmHg * kPascalPerMmHg),
        // The lumped atrium refills the inflow vessel as fast as the E wave drains it (up to
        // 510 mL/s): three layers of re-entry sites rather than one.
        loop(model.flowPath, scenario.blood, scenario.circulation.lumped ? 3 : 1),
        filling(model.flowPath, scenario.blood, scenario.circulation.atrialPressureMmHg),
        settings(scenario.circulation) {}

  Valves valves;
  FlowMeter meter;
  BloodLoop loop;
  FillingForce filling;
  CirculationSettings settings;
};

}  // namespace hs::cardiac
