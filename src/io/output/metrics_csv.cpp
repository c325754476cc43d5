#include "io/output/metrics_csv.h"

#include <stdexcept>

namespace hs::io {
namespace {

// mL (cardiac::VolumeScale's clinical unit), whatever the model's size: the columns say so.
constexpr double kMlPerM3 = cardiac::VolumeScale{}.volume;

void writeFlowRow(std::ostream& csv, const cardiac::StepSample& sample) {
  using cardiac::FlowRegion;
  const cardiac::FlowStep& s = sample.flowStep;
  const cardiac::ValveFlows& f = sample.flows;
  auto count = [&](FlowRegion r) { return s.count[std::size_t(r)]; };
  csv << ',' << int(s.valves.mitralOpen) << ',' << int(s.valves.aorticOpen) << ','
      << count(FlowRegion::InflowVessel) << ',' << count(FlowRegion::Ventricle) << ','
      << count(FlowRegion::OutflowVessel) << ',' << count(FlowRegion::Parked) << ',' << count(FlowRegion::Outside)
      << ',' << f.mitralForward * kMlPerM3 << ',' << f.mitralBackward * kMlPerM3 << ','
      << f.aorticForward * kMlPerM3 << ',' << f.aorticBackward * kMlPerM3 << ','
      << sample.pressure(FlowRegion::InflowVessel) << ',' << sample.pressure(FlowRegion::Ventricle) << ','
      << sample.pressure(FlowRegion::OutflowVessel) << ',' << sample.ventricleKineticEnergy * 1e6 << ','
      << s.aorticEcho << ',' << s.mitralEcho;
}

void writeLumpedRow(std::ostream& csv, const cardiac::StepSample& sample) {
  const cardiac::CirculationSample l = sample.lumped.value_or(cardiac::CirculationSample{});
  constexpr double mmHg = cardiac::kPascalPerMmHg;
  csv << ',' << l.lvPressure / mmHg << ',' << l.aorticPressure / mmHg << ',' << l.laPressure / mmHg << ','
      << l.lvVolume * kMlPerM3 << ',' << l.mitralFlow * kMlPerM3 << ',' << l.aorticFlow * kMlPerM3 << ','
      << int(l.mitralOpen) << ',' << int(l.aorticOpen) << ',' << l.ventricularActivation << ','
      << l.atrialActivation << ',' << sample.contraction << ',' << sample.baseDescent * 1e3 << ','
      << sample.vesselFill << ',' << sample.ecg << ',' << cardiac::heartSoundName(sample.heartSound);
}

}  // namespace

void writeMetricsHeader(std::ostream& csv, const MetricsColumns& columns) {
  // lv_kinetic_energy_uj: of the smoothed velocity (cardiac/blood/ventricle_blood.h); the
  // Doppler columns: each orifice's reading (m/s, cardiac/blood/echo_velocities.h).
  // phase: the heart's, from the valves (cardiac/circulation/heart_phase.h); wall_phase: the
  // wall's own clock (systole, diastole, rest), which says when a beat starts.
  csv << "step,time_s,phase,wall_phase";
  if (columns.heart)
    csv << ",cavity_volume_m3,cavity_volume_ml,volume_error_mean,volume_error_max,inverted_tets,rest_deviation_rel";
  if (columns.blood)
    csv << ",blood_lost,blood_density_error_mean,blood_density_error_max,blood_max_speed_m_s,blood_inside_wall";
  if (columns.flows)
    csv << ",mitral_open,aortic_open,particles_inflow_vessel,particles_lv,particles_outflow_vessel,"
           "particles_returning,particles_outside,mitral_forward_ml,mitral_backward_ml,aortic_forward_ml,"
           "aortic_backward_ml,pressure_inflow_vessel_pa,pressure_lv_pa,pressure_outflow_vessel_pa,lv_kinetic_energy_uj,"
           "aortic_doppler_m_s,mitral_doppler_m_s";
  if (columns.lumped)
    csv << ",lv_pressure_mmhg,aortic_pressure_mmhg,la_pressure_mmhg,lumped_lv_volume_ml,lumped_mitral_flow_ml_s,"
           "lumped_aortic_flow_ml_s,lumped_mitral_open,lumped_aortic_open,activation_ventricle,activation_atrium,"
           "wall_contraction,base_descent_mm,vessel_fill,ecg_mv,heart_sound";
  csv << '\n';
}

void writeMetricsRow(std::ostream& csv, const MetricsColumns& columns, const cardiac::StepSample& sample) {
  csv << sample.step << ',' << sample.time << ',' << (columns.heart ? cardiac::heartPhaseKey(sample.heartPhase) : "none")
      << ',' << (columns.heart ? cardiac::phaseName(sample.phase) : "none");
  if (columns.heart) {
    const cardiac::TissueStats& t = sample.tissue;
    csv << ',' << sample.cavity << ',' << sample.cavity * kMlPerM3 << ',' << t.volumeErrorMean << ','
        << t.volumeErrorMax << ',' << t.invertedTets << ',' << sample.restDeviation;
  }
  if (columns.blood) {
    const cardiac::BloodStats blood = sample.blood.value_or(cardiac::BloodStats{});
    csv << ',' << blood.lost << ',' << blood.densityErrorMean << ',' << blood.densityErrorMax << ','
        << blood.maxSpeed << ',' << blood.insideWall;
  }
  if (columns.flows) writeFlowRow(csv, sample);
  if (columns.lumped) writeLumpedRow(csv, sample);
  csv << '\n';
}

MetricsCsvFile::MetricsCsvFile(const std::filesystem::path& path, const MetricsColumns& columns)
    : m_path(path), m_columns(columns), m_csv(path) {
  if (!m_csv) throw std::runtime_error(path.string() + ": cannot open for writing");
  writeMetricsHeader(m_csv, columns);
  m_csv.precision(9);
}

void MetricsCsvFile::close() {
  m_csv.flush();
  if (!m_csv) throw std::runtime_error(m_path.string() + ": write failed (disk full?)");
}

}  // namespace hs::io
