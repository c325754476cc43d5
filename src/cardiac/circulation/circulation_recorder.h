#pragma once
// What the lumped circulation and the 3D heart it drives did over a run, beat by beat: the
// lumped samples (for the plots and metrics.csv), each beat's clinical figures
// (lumped_beat.h) beside the 3D heart's own (blood through the 3D aortic orifice, the fastest
// jet through it), and how closely the 3D heart followed the lumped one (cavity volume, stroke
// volume, vessels kept full). A beat runs from one onset of the ventricle's activation (its
// clock's systole) to the next, as in beat_metrics.h.
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "cardiac/circulation/beat_clock.h"
#include "cardiac/circulation/lumped_beat.h"

namespace hs::cardiac {

// One step as the recorder reads it. SI units.
struct CoupledStep {
  double startTime = 0, time = 0;  // s
  Phase phase = Phase::Rest;       // the main region's clock during the step
  double cavity = 0;               // m^3, the 3D cavity at the step's end
  CirculationSample lumped;
  double aorticForward = 0, aorticBackward = 0;  // m^3 through the 3D aortic orifice in the step
  double aorticJet = 0;   // m/s, fastest blood crossing the 3D aortic orifice forward (0: none)
  double vesselFill = 1;  // smallest share of the two vessels' lumens holding blood
};

struct CoupledBeat {
  int index = 0;  // 1-based
  double startTime = 0, duration = 0;
  bool complete = false;
  LumpedBeatFigures lumped;
  double aorticNet3d = 0;  // m^3 through the 3D aortic orifice, forward - backward
  double aorticJet = 0;    // m/s, fastest over the beat
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
  // |3D - lumped| / lumped net aortic volume over the beat.
  [[nodiscard]] double aorticFlowError() const;
};

// Means over the complete beats after the first (the first starts from the initial state);
// count = 0 when there are none.
struct CoupledMeans {
  int count = 0;
  double aorticSystolic = 0, aorticDiastolic = 0, lvPeak = 0, lvEndDiastolic = 0;  // Pa
  double isovolumicContraction = 0, isovolumicRelaxation = 0;                      // s
  std::optional<double> eToA;  // none when a beat had no A wave
  double regurgitantFraction = 0, aorticMeanGradient = 0, aorticJet = 0;
  double strokeVolume = 0;  // m^3, lumped net forward volume per beat
};

class CirculationRecorder {
 public:
  // `keepSamples`: the most recent samples kept for samples() (the viewer bounds them).
  explicit CirculationRecorder(double dt, std::size_t keepSamples = std::numeric_limits<std::size_t>::max())
      : m_dt(dt), m_keep(keepSamples) {}

  void record(const CoupledStep& step);
  // Closes the beat in progress (incomplete).
  void finish();

  [[nodiscard]] const std::vector<CoupledBeat>& beats() const { return m_beats; }
  [[nodiscard]] CoupledMeans means() const;
  [[nodiscard]] const std::vector<CirculationSample>& samples() const { return m_samples; }
  [[nodiscard]] const std::vector<double>& beatStarts() const { return m_beatStarts; }

  // Over the whole run.
  [[nodiscard]] std::size_t bothValvesOpenSteps() const { return m_bothOpen; }
  [[nodiscard]] double cavityVolumeErrorMax() const { return m_cavityErrorMax; }  // relative
  [[nodiscard]] double cavityStepMax() const { return m_cavityStepMax; }          // m^3 in one step
  [[nodiscard]] double vesselFillMin() const { return m_fillMin; }
  // Over the complete beats after the first; none without one.
  [[nodiscard]] std::optional<double> aorticFlowErrorMax() const;
  // Checkpoints: the samples, the beats and the beat in progress (dt and the samples kept are
  // settings).
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  void close(bool complete);

  double m_dt;
  std::size_t m_keep;
  std::vector<CirculationSample> m_samples;
  std::vector<double> m_beatStarts;
  std::vector<CoupledBeat> m_beats;
  // The beat in progress.
  std::vector<CirculationSample> m_beat;
  CoupledBeat m_current;
  std::optional<double> m_atrialOnset;
  double m_lastAtrial = 0;
  bool m_open = false;
  Phase m_previous = Phase::Rest;
  std::optional<double> m_lastCavity;
  // Run-wide.
  std::size_t m_bothOpen = 0;
  double m_cavityErrorMax = 0, m_cavityStepMax = 0, m_fillMin = 1;
};

}  // namespace hs::cardiac
