#include "cardiac/circulation/lumped_circulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hs::cardiac {
namespace {

// Substeps no longer than this (s): a tenth of the fastest time constant, R_valve / Ees.
constexpr double kMaxSubstep = 5e-5;

void require(bool ok, const char* key, double value, const char* range) {
  if (ok) return;
  std::ostringstream message;
  message << key << ": got " << value << ", expected " << range;
  throw std::invalid_argument(message.str());
}

// value <= limit, allowing the float rounding of the scenario's SI fields: a value the file gave
// as exactly the limit in clinical units comes back from its float SI field a rounding above it.
bool atMost(double value, double limit) { return value <= limit * (1 + 4.0 * std::numeric_limits<float>::epsilon()); }

}  // namespace

void validateLumpedParameters(const LumpedParameters& p) {
  // Clinical units in the messages: what the scenario file holds.
  require(p.contractility > 0 && atMost(elastanceToClinical(p.contractility), 20), "circulation.contractility_mmhg_per_ml",
          elastanceToClinical(p.contractility), "> 0 and <= 20 mmHg/mL");
  require(p.peripheralResistance > 0 && atMost(resistanceToClinical(p.peripheralResistance), 20),
          "circulation.peripheral_resistance_mmhg_s_per_ml", resistanceToClinical(p.peripheralResistance),
          "> 0 and <= 20 mmHg s/mL");
  require(p.arterialCompliance > 0 && atMost(complianceToClinical(p.arterialCompliance), 20),
          "circulation.arterial_compliance_ml_per_mmhg", complianceToClinical(p.arterialCompliance),
          "> 0 and <= 20 mL/mmHg");
  require(p.characteristicImpedance >= 0 && atMost(resistanceToClinical(p.characteristicImpedance), 1),
          "circulation.characteristic_impedance_mmhg_s_per_ml", resistanceToClinical(p.characteristicImpedance),
          ">= 0 and <= 1 mmHg s/mL");
  require(p.pulmonaryVenousPressure >= 0 && atMost(p.pulmonaryVenousPressure, 100 * kPascalPerMmHg),
          "circulation.atrial_pressure_mmhg", p.pulmonaryVenousPressure / kPascalPerMmHg, ">= 0 and <= 100 mmHg");
  require(p.systemicVenousPressure >= 0 && atMost(p.systemicVenousPressure, 30 * kPascalPerMmHg),
          "circulation.venous_pressure_mmhg", p.systemicVenousPressure / kPascalPerMmHg, ">= 0 and <= 30 mmHg");
  require(p.unstressedVolume >= 0 && atMost(p.unstressedVolume, 200 * kCubicMetresPerMl), "circulation.lv_v0_ml",
          p.unstressedVolume / kCubicMetresPerMl, ">= 0 and <= 200 mL");
  require(p.diastolicScale > 0 && atMost(p.diastolicScale, 20 * kPascalPerMmHg), "circulation.lv_stiffness_mmhg",
          p.diastolicScale / kPascalPerMmHg, "> 0 and <= 20 mmHg");
  require(p.diastolicExponent > 0 && atMost(p.diastolicExponent * kCubicMetresPerMl, 0.05),
          "circulation.lv_stiffness_per_ml", p.diastolicExponent * kCubicMetresPerMl, "> 0 and <= 0.05 per mL");
  require(p.mitralArea > 0, "model.mitral_radius", p.mitralArea, "an orifice of positive area");
  require(p.aorticArea > 0, "circulation.aortic_valve_area_cm2", p.aorticArea * 1e4, "> 0 cm^2");
  require(p.mitralRegurgitantArea >= 0 && p.mitralRegurgitantArea <= p.mitralArea,
          "circulation.mitral_regurgitant_area_cm2", p.mitralRegurgitantArea * 1e4,
          ">= 0 and no larger than the mitral orifice");
  require(p.aorticRegurgitantArea >= 0 && p.aorticRegurgitantArea <= p.aorticArea,
          "circulation.aortic_regurgitant_area_cm2", p.aorticRegurgitantArea * 1e4,
          ">= 0 and no larger than the aortic orifice");
}

double activationCurve(double t, double contractionTime, double relaxationTime) {
  if (t <= 0 || t >= contractionTime + relaxationTime) return 0;
  if (t < contractionTime) return 0.5 * (1 - std::cos(std::numbers::pi * t / contractionTime));
  return 0.5 * (1 + std::cos(std::numbers::pi * (t - contractionTime) / relaxationTime));
}

double ventricularActivationCurve(double t, double contractionTime, double relaxationTime) {
  if (t <= 0 || t >= contractionTime + relaxationTime) return 0;
  if (t < contractionTime) return std::sin(0.5 * std::numbers::pi * t / contractionTime);
  return 0.5 * (1 + std::cos(std::numbers::pi * (t - contractionTime) / relaxationTime));
}

BeatTiming beatTimingForRate(double heartRateBpm) {
  // Weissler, Harris & Schoenfeld (1968): LVET = 413 - 1.7 HR ms; isovolumic contraction ~45 ms.
  const double ejection = std::max(0.12, 0.413 - 0.0017 * heartRateBpm);
  BeatTiming timing;
  timing.systole = 0.045 + ejection;
  timing.contraction = timing.systole;  // the elastance peaks as ejection ends
  timing.relaxation = 0.35 * timing.contraction;
  // The atrial contraction and the PR interval shorten a little at fast rates.
  const double period = 60.0 / heartRateBpm;
  timing.prInterval = std::min(0.16, 0.2 * period);
  timing.atrialContraction = timing.atrialRelaxation = std::min(0.09, 0.11 * period);
  return timing;
}

LumpedCirculation::LumpedCirculation(const LumpedParameters& parameters) : m_parameters(parameters) {
  validateLumpedParameters(parameters);
}

void LumpedCirculation::startFrom(double lvVolume) {
  const LumpedParameters& p = m_parameters;
  m_state.lvVolume = lvVolume;
  m_state.laVolume = p.atrialUnstressedVolume + p.pulmonaryVenousPressure / p.atrialPassiveElastance;
  // Mean arterial pressure of a cardiac output near 5 L/min.
  m_state.compliancePressure = p.systemicVenousPressure + 83e-6 * p.peripheralResistance;
  m_last = {};
  m_last.lvVolume = lvVolume;
  m_last.lvPressure = lvPressure(lvVolume, 0);
  m_last.laPressure = laPressure(m_state.laVolume, 0);
  m_last.aorticPressure = m_state.compliancePressure;
}

double LumpedCirculation::lvPressure(double volume, double activation) const {
  const LumpedParameters& p = m_parameters;
  const double filled = volume - p.unstressedVolume;
  const double systolic = p.contractility * filled;
  const double diastolic = p.diastolicScale * (std::exp(p.diastolicExponent * filled) - 1);
  return activation * systolic + (1 - activation) * diastolic;
}

double LumpedCirculation::laPressure(double volume, double activation) const {
  const LumpedParameters& p = m_parameters;
  return (p.atrialPassiveElastance + activation * p.atrialActiveElastance) * (volume - p.atrialUnstressedVolume);
}

double LumpedCirculation::valveFlow(double dp, double area, double downstreamArea, double regurgitantArea,
                                     double seriesResistance) const {
  // dp = R Q + K Q^2 with K = rho/2 (1/A - 1/A_d)^2, solved for Q >= 0 (the root that is
  // continuous at dp = 0 with slope 1/R); backward flow through the regurgitant orifice alone,
  // into a chamber.
  const double orifice = dp >= 0 ? area : regurgitantArea;
  if (orifice <= 0) return 0;
  const double expansion = 1 / orifice - (dp >= 0 && downstreamArea >= orifice ? 1 / downstreamArea : 0);
  const double k = 0.5 * m_parameters.bloodDensity * expansion * expansion;
  const double r = seriesResistance;
  // Q = (-R + sqrt(R^2 + 4 K dp)) / (2K), written without the cancellation (and valid at K = 0).
  const double magnitude = 2 * std::abs(dp) / (r + std::sqrt(r * r + 4 * k * std::abs(dp)));
  return dp >= 0 ? magnitude : -magnitude;
}

LumpedCirculation::Rates LumpedCirculation::rates(const LumpedState& s, const Activation& a) const {
  const LumpedParameters& p = m_parameters;
  const double plv = lvPressure(s.lvVolume, a.ventricle);
  const double pla = laPressure(s.laVolume, a.atrium);
  Rates r;
  const double pulmonary = (p.pulmonaryVenousPressure - pla) / p.pulmonaryVenousResistance;
  r.mitral = valveFlow(pla - plv, p.mitralArea, 0, p.mitralRegurgitantArea, p.valveResistance);
  r.aortic = valveFlow(plv - s.compliancePressure, p.aorticArea, p.aorticRootArea, p.aorticRegurgitantArea,
                       p.valveResistance + p.characteristicImpedance);
  r.lv = r.mitral - r.aortic;
  r.la = pulmonary - r.mitral;
  r.compliance = (r.aortic - (s.compliancePressure - p.systemicVenousPressure) / p.peripheralResistance) /
                 p.arterialCompliance;
  return r;
}

const CirculationSample& LumpedCirculation::advance(double time, double dt, const Activation& activation) {
  const int substeps = std::max(1, int(std::ceil(dt / kMaxSubstep)));
  const double h = dt / substeps;
  double mitralVolume = 0, aorticVolume = 0;
  bool mitralForward = false, aorticForward = false;
  for (int k = 0; k < substeps; ++k) {
    const Rates r = rates(m_state, activation);
    m_state.lvVolume += h * r.lv;
    m_state.laVolume += h * r.la;
    m_state.compliancePressure += h * r.compliance;
    mitralVolume += h * r.mitral;
    aorticVolume += h * r.aortic;
    mitralForward = mitralForward || r.mitral > 0;
    aorticForward = aorticForward || r.aortic > 0;
  }
  CirculationSample& out = m_last;
  out.time = time;
  out.lvVolume = m_state.lvVolume;
  out.lvPressure = lvPressure(m_state.lvVolume, activation.ventricle);
  out.laPressure = laPressure(m_state.laVolume, activation.atrium);
  out.mitralFlow = mitralVolume / dt;
  out.aorticFlow = aorticVolume / dt;
  out.aorticPressure = m_state.compliancePressure + m_parameters.characteristicImpedance * out.aorticFlow;
  out.mitralOpen = mitralForward;
  out.aorticOpen = aorticForward;
  out.ventricularActivation = activation.ventricle;
  out.atrialActivation = activation.atrium;
  return out;
}

PressureVolumeRelations LumpedCirculation::relations(double beatingShare) const {
  return {m_parameters.contractility * beatingShare, m_parameters.unstressedVolume, m_parameters.diastolicScale,
          m_parameters.diastolicExponent};
}

void LumpedState::save(pbd::StateWriter& w) const {
  w.fields(lvVolume, laVolume, compliancePressure);
}

void LumpedState::load(pbd::StateReader& r) {
  r.fields(lvVolume, laVolume, compliancePressure);
}

void LumpedCirculation::save(pbd::StateWriter& w) const {
  w.section("lumped circulation");
  w.fields(m_state, m_last);
}

void LumpedCirculation::load(pbd::StateReader& r) {
  r.section("lumped circulation");
  r.fields(m_state, m_last);
}

void CirculationSample::save(pbd::StateWriter& w) const {
  w.fields(time, lvVolume, lvPressure, laPressure, aorticPressure, mitralFlow, aorticFlow, mitralOpen, aorticOpen, ventricularActivation, atrialActivation, ecg);
}

void CirculationSample::load(pbd::StateReader& r) {
  r.fields(time, lvVolume, lvPressure, laPressure, aorticPressure, mitralFlow, aorticFlow, mitralOpen, aorticOpen, ventricularActivation, atrialActivation, ecg);
}

}  // namespace hs::cardiac
