#include "flow_report.h"

namespace hs::app {
namespace {

// mL and L/min (cardiac::VolumeScale's clinical units), whatever the model's size: the keys
// and columns say so.
constexpr cardiac::VolumeScale kClinical{};
constexpr double kMlPerM3 = kClinical.volume;
constexpr double kLitresPerMinutePerM3PerSecond = kClinical.output;

}  // namespace

void writeFlowHeader(std::ostream& csv) {
  csv << ",mitral_open,aortic_open,particles_inflow_vessel,particles_lv,particles_outflow_vessel,"
         "particles_returning,particles_outside,mitral_forward_ml,mitral_backward_ml,aortic_forward_ml,"
         "aortic_backward_ml,pressure_inflow_vessel_pa,pressure_lv_pa,pressure_outflow_vessel_pa";
}

void writeFlowRow(std::ostream& csv, const cardiac::Circulation& circulation) {
  using cardiac::FlowRegion;
  const cardiac::FlowStep& s = circulation.meter.lastStep();
  const cardiac::ValveFlows f = circulation.meter.lastStepFlows();
  auto count = [&](FlowRegion r) { return s.count[std::size_t(r)]; };
  auto pressure = [&](FlowRegion r) { return s.pressure[std::size_t(r)]; };
  csv << ',' << int(s.valves.mitralOpen) << ',' << int(s.valves.aorticOpen) << ','
      << count(FlowRegion::InflowVessel) << ',' << count(FlowRegion::Ventricle) << ','
      << count(FlowRegion::OutflowVessel) << ',' << count(FlowRegion::Parked) << ',' << count(FlowRegion::Outside)
      << ',' << f.mitralForward * kMlPerM3 << ',' << f.mitralBackward * kMlPerM3 << ','
      << f.aorticForward * kMlPerM3 << ',' << f.aorticBackward * kMlPerM3 << ','
      << pressure(FlowRegion::InflowVessel) << ',' << pressure(FlowRegion::Ventricle) << ','
      << pressure(FlowRegion::OutflowVessel);
}

nlohmann::ordered_json heartPumpReport(const cardiac::BeatTracker& beats) {
  const cardiac::BeatMeans m = beats.means();
  return {{"beats", beats.beats().size()},
          {"beats_averaged", m.count},
          {"edv_ml", m.edv * kMlPerM3},
          {"esv_ml", m.esv * kMlPerM3},
          {"stroke_volume_ml", m.strokeVolume * kMlPerM3},
          {"ejection_fraction", m.ejectionFraction},
          {"cardiac_output_l_min", m.cardiacOutput * kLitresPerMinutePerM3PerSecond},
          {"regurgitant_volume_ml", m.regurgitantVolume * kMlPerM3},
          {"aortic_net_forward_ml", m.aorticNet * kMlPerM3}};
}

}  // namespace hs::app
