#pragma once
// A lumped (0D) left heart and systemic circulation: the pressures and flows the 3D heart and
// blood cannot give by themselves. SI units inside (m^3, Pa, s); clinical units only in the
// comments. Parameters, their sources and the textbook ranges they reproduce: docs/physiology.md.
//
//   pulmonary veins --R_pv--> left atrium --mitral--> left ventricle --aortic--Z_c--> aorta
//   (P_pv: preload)            (elastance)             (elastance)                 C | R_p
//                                                                                   systemic veins
//
// Left ventricle, time-varying elastance (Suga & Sagawa 1974), mixing the end-systolic and the
// end-diastolic pressure-volume relations with the activation e(t) in [0, 1]:
//   P_lv = e Ees (V - V0) + (1 - e) A (exp(B (V - V0)) - 1)
// Left atrium, the same with a linear passive part: P_la = (E_pass + e_a E_act) (V_la - V0_la).
// Valves: diodes with a linear resistance and the Borda-Carnot loss of the jet from their
// orifice A into the lumen after it, A_d (Garcia et al. 2000: the pressure not recovered
// downstream of a valve),
//   dp = R Q + rho/2 (Q/A - Q/A_d)^2,
// open while the pressure across them drives blood forward; a regurgitant orifice (area > 0)
// lets blood back with the same law (into the atrium or ventricle, A_d large). A valve as wide
// as its vessel loses only R Q; a stenotic one (A << A_d) the whole jet's dynamic pressure. Systemic arteries: a three-element Windkessel (Westerhof
// et al. 2009): characteristic impedance Z_c, compliance C, peripheral resistance R_p to the
// systemic veins at P_sv. State: V_lv, V_la and the compliance's pressure P_c.
// The model is integrated with explicit Euler substeps short against its fastest time
// constant (R_valve / Ees, about 2 ms), so one step of the 3D heart is many substeps.
#include <string>

#include "cardiac/circulation/circulation_trace.h"
#include "cardiac/circulation/clinical_units.h"

namespace hs::cardiac {

struct LumpedParameters {
  // Left ventricle.
  double contractility = elastanceFromClinical(2.7);  // Ees, Pa/m^3
  double unstressedVolume = 5 * kCubicMetresPerMl;    // V0, m^3
  double diastolicScale = 0.35 * kPascalPerMmHg;          // A, Pa
  double diastolicExponent = 0.028 / kCubicMetresPerMl;        // B, 1/m^3
  // Left atrium.
  double atrialPassiveElastance = elastanceFromClinical(0.15);
  double atrialActiveElastance = elastanceFromClinical(0.3);
  double atrialUnstressedVolume = 10 * kCubicMetresPerMl;
  // Preload: the pulmonary veins' pressure, through their resistance into the atrium.
  double pulmonaryVenousPressure = 8 * kPascalPerMmHg;
  double pulmonaryVenousResistance = resistanceFromClinical(0.02);
  // Valves: orifice areas (m^2) and the linear resistance shared by both.
  double mitralArea = 4.9e-4;
  double aorticArea = 3.46e-4;      // the valve's orifice (smaller than the root: stenosis)
  double aorticRootArea = 3.46e-4;  // the lumen the aortic jet enters
  double mitralRegurgitantArea = 0;  // m^2, 0 = a competent valve
  double aorticRegurgitantArea = 0;
  double valveResistance = resistanceFromClinical(0.003);
  // Afterload: three-element Windkessel.
  double characteristicImpedance = resistanceFromClinical(0.05);
  double arterialCompliance = complianceFromClinical(1.4);
  double peripheralResistance = resistanceFromClinical(1.05);
  double systemicVenousPressure = 5 * kPascalPerMmHg;
  double bloodDensity = 1060;  // kg/m^3, the Bernoulli loss
};

// Throws std::invalid_argument naming the scenario key (circulation.*) and its accepted range.
void validateLumpedParameters(const LumpedParameters& parameters);

struct LumpedState {
  double lvVolume = 0;          // m^3
  double laVolume = 0;          // m^3
  double compliancePressure = 0;  // Pa, P_c of the Windkessel
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// Activation of the ventricle and the atrium during one step, each in [0, 1] (the ventricle's
// already scaled by the share of the wall that beats).
struct Activation {
  double ventricle = 0;
  double atrium = 0;
};

// The atrium's activation (Regazzoni et al. 2022, the "cosine" activation): rising as
// (1 - cos(pi t / Tc)) / 2 over the contraction time Tc, falling as (1 + cos(pi (t - Tc) / Tr))
// / 2 over the relaxation time Tr, zero otherwise. t: time since the activation began (s).
double activationCurve(double t, double contractionTime, double relaxationTime);
// The ventricle's: the same relaxation, but a contraction rising as sin(pi t / (2 Tc)), at
// once rather than from a standstill: the elastance climbs steeply through the isovolumic
// contraction (30-70 ms in people) and keeps rising slowly through ejection, as measured
// elastance curves do (Senzaki et al. 1996).
double ventricularActivationCurve(double t, double contractionTime, double relaxationTime);

// Timing of a beat from the heart rate. The ejection time follows Weissler et al. (1968):
// LVET = 413 - 1.7 HR ms; the ventricle contracts over the isovolumic contraction and the
// ejection and relaxes in about half that; the atrium contracts a PR interval before the
// ventricle.
struct BeatTiming {
  double contraction = 0;  // s, ventricular Tc
  double relaxation = 0;   // s, ventricular Tr
  double systole = 0;      // s, electromechanical systole (isovolumic contraction + ejection)
  double atrialContraction = 0.09, atrialRelaxation = 0.09;  // s
  double prInterval = 0.16;  // s, atrial onset before the ventricle's
};
BeatTiming beatTimingForRate(double heartRateBpm);

class LumpedCirculation {
 public:
  explicit LumpedCirculation(const LumpedParameters& parameters);

  // A state near the periodic one of a normal heart: the ventricle at `lvVolume` (the 3D
  // cavity's), the atrium at its filling pressure, the arteries at their mean pressure.
  void startFrom(double lvVolume);
  // Advances dt seconds with the given activation (constant over the step); returns the step:
  // pressures and volume at its end, flows as means over it.
  const CirculationSample& advance(double time, double dt, const Activation& activation);

  [[nodiscard]] const LumpedState& state() const { return m_state; }
  [[nodiscard]] const CirculationSample& last() const { return m_last; }
  [[nodiscard]] const LumpedParameters& parameters() const { return m_parameters; }
  // The relations the loop moves between, with the effective (beating-share) contractility.
  [[nodiscard]] PressureVolumeRelations relations(double beatingShare = 1) const;
  // Checkpoints: the state and the last step (the parameters come from the scenario).
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

  // Pressures of the state for an activation (Pa).
  [[nodiscard]] double lvPressure(double volume, double activation) const;
  [[nodiscard]] double laPressure(double volume, double activation) const;
  // Forward flow (m^3/s, negative backward) through an orifice for a pressure drop dp (Pa).
  // `downstreamArea` 0: a chamber, no recovery.
  [[nodiscard]] double valveFlow(double dp, double area, double downstreamArea, double regurgitantArea,
                                 double seriesResistance) const;

 private:
  struct Rates {
    double lv = 0, la = 0, compliance = 0;  // d/dt of the state
    double mitral = 0, aortic = 0;          // m^3/s
  };
  [[nodiscard]] Rates rates(const LumpedState& state, const Activation& activation) const;

  LumpedParameters m_parameters;
  LumpedState m_state;
  CirculationSample m_last;
};

}  // namespace hs::cardiac
