#pragma once
// The blood's flow components per beat, by particle tracking, as 4D-flow MRI papers define them
// (Bolger et al. 2007, J Cardiovasc Magn Reson 9:741; Eriksson et al. 2010, J Cardiovasc Magn
// Reson 12:9; Stoll et al. 2018). Of the blood in the ventricle at end-diastole:
// - direct flow: entered in this diastole and left in the next systole;
// - retained inflow: entered in this diastole and stayed;
// - delayed ejection: was in the ventricle before this diastole and left in this systole;
// - residual volume: was there before and stayed.
// Each particle carries the diastole it last entered the ventricle in; every blood particle
// carries the same volume, so the shares are fractions of the particles at end-diastole.
// Pure bookkeeping over "which particles are in the ventricle now" and the beat's two events;
// the run's monitor feeds it (run_monitor.h).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "pbd/core/state_stream.h"

namespace hs::cardiac {

struct FlowComponents {
  double direct = 0, retainedInflow = 0, delayedEjection = 0, residual = 0;  // fractions of the EDV
  std::size_t particles = 0;  // in the ventricle at end-diastole
  // Of the blood ejected in the beat whose entry was seen, the mean number of beats it spent in
  // the ventricle (1: entered in the diastole just before); 0 when none was seen entering.
  double meanResidenceBeats = 0;
  // The share of the end-diastolic blood that had been in the ventricle for more than three
  // beats (entered four or more diastoles before, or there since the run began that long ago).
  double stayedOverThreeBeats = 0;
  [[nodiscard]] double sum() const { return direct + retainedInflow + delayedEjection + residual; }
};

// Which of the four components a blood particle belongs to, for pictures; None: it was not in
// the ventricle at the last end-diastole (or none has come yet).
enum class FlowComponent : std::uint8_t { None, Direct, RetainedInflow, DelayedEjection, Residual };

// The component of blood that was in the ventricle at an end-diastole, new (entered in that
// diastole) or earlier, by whether it has left since: the rule the shares count by.
FlowComponent componentOf(bool enteredThisDiastole, bool left);

// How long a blood particle has been in the ventricle, for pictures of where blood stagnates.
enum class Stay : std::uint8_t { Outside, UpToThreeBeats, OverThreeBeats };

class FlowComponentTracker {
 public:
  explicit FlowComponentTracker(std::size_t particles = 0);

  // After a step: inVentricle[k] is 1 when blood particle k (by identity, not by storage order)
  // is in the ventricle. A particle that was outside and is in now entered in this diastole; at
  // the first look, one that is in has been there since before tracking began.
  void observe(std::span<const std::uint8_t> inVentricle);
  // The ventricle is at its fullest: its blood is sorted into new (entered in this diastole)
  // and earlier.
  void endDiastole();
  // Ejection is over: the beat's components, once an end-diastole came before it; a new
  // diastole begins.
  std::optional<FlowComponents> endSystole();

  // Per particle (by identity), the live view's rule: from an end-diastole on, the blood that
  // was in the ventricle then is new (retained inflow) or earlier (residual) and, once it has
  // left, direct flow or delayed ejection; so at an end-systole each particle shows the
  // component endSystole() counted it in. The colours stay until the next end-diastole sorts
  // the blood again; blood that was not in the ventricle at the last end-diastole is None.
  // Reads the bookkeeping only.
  [[nodiscard]] std::vector<FlowComponent> components() const;
  // Per particle (by identity): outside the ventricle, or in it for up to or more than three
  // beats (more: entered four or more diastoles ago, counting the one in progress, or there
  // since tracking began that long ago), as FlowComponents::stayedOverThreeBeats counts.
  [[nodiscard]] std::vector<Stay> stays() const;

  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  static constexpr std::int32_t kBeforeTracking = -1;
  enum AtEndDiastole : std::uint8_t { Absent = 0, New = 1, Earlier = 2 };
  // Beats particle k has spent in the ventricle so far, this diastole's counted as the first.
  [[nodiscard]] std::int32_t beatsInside(std::size_t k) const;
  std::vector<std::uint8_t> m_inside;
  std::vector<std::int32_t> m_enteredDiastole;  // kBeforeTracking: in the ventricle from the start
  std::vector<std::uint8_t> m_atEndDiastole;
  std::int32_t m_diastole = 0;  // diastoles begun since tracking began
  bool m_observed = false;      // a first look has been taken
  bool m_haveEndDiastole = false;
  double m_stayedOverThreeBeats = 0;
};

}  // namespace hs::cardiac
