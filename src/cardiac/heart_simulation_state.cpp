// HeartSimulation's checkpoint: the state every step changes, piece by piece, each piece
// writing its own fields (their save/load sit next to them). What the constructor builds from
// the scenario (the model, the constraints and their rest values, the solvers' settings, the
// flow path) is not written; neither are the per-step scratch buffers (the fluid solver's
// neighbour lists and pressures, the wall contact's grid, the vessel ends' plugs), which every
// step rebuilds before it reads them. The blood's Morton reordering follows the step count,
// which is saved, so a resumed run reorders on the same steps.
#include <string>

#include "cardiac/heart_simulation.h"

namespace hs::cardiac {
namespace {

// An optional piece present in the built simulation must be present in the state, and the
// other way round.
bool presence(pbd::StateReader& r, bool built, const char* piece) {
  const std::size_t at = r.offset();
  bool saved = false;
  r.get(saved);
  if (saved != built)
    throw pbd::StateError(std::string(piece) + (saved ? " saved, but the scenario has none" : " missing from the state"),
                          at);
  return saved;
}

}  // namespace

void TissueStats::save(pbd::StateWriter& w) const {
  w.fields(volumeErrorMax, volumeErrorMean, invertedTets, firstInvertedTet, finite, firstNonFinite);
}

void TissueStats::load(pbd::StateReader& r) {
  r.fields(volumeErrorMax, volumeErrorMean, invertedTets, firstInvertedTet, finite, firstNonFinite);
}

void HeartSimulation::save(pbd::StateWriter& w) const {
  w.section("heart simulation");
  w.fields(m_steps, m_lastPhase, m_lastBaseDescent);
  m_particles.save(w);
  w.put(m_cycle.has_value());
  if (m_cycle) m_cycle->save(w);
  w.put(m_lumped.has_value());
  if (m_lumped) m_lumped->save(w);
  w.put(m_drivenWall.has_value());
  if (m_drivenWall) m_drivenWall->save(w);
  w.put(m_ends.has_value());
  if (m_ends) m_ends->save(w);
  w.put(m_recordedBeat.has_value());
  if (m_recordedBeat) m_recordedBeat->save(w);
  w.put(m_circulation.has_value());
  if (m_circulation) {
    m_circulation->valves.save(w);
    m_circulation->meter.save(w);
    m_circulation->loop.save(w);
  }
}

void HeartSimulation::load(pbd::StateReader& r) {
  r.section("heart simulation");
  r.fields(m_steps, m_lastPhase, m_lastBaseDescent);
  m_particles.load(r);
  if (presence(r, m_cycle.has_value(), "the cardiac cycle")) m_cycle->load(r);
  if (presence(r, m_lumped.has_value(), "the lumped circulation")) m_lumped->load(r);
  if (presence(r, m_drivenWall.has_value(), "the driven wall")) m_drivenWall->load(r);
  if (presence(r, m_ends.has_value(), "the vessel ends")) m_ends->load(r);
  if (presence(r, m_recordedBeat.has_value(), "the recorded beat")) m_recordedBeat->load(r);
  if (presence(r, m_circulation.has_value(), "the circulation")) {
    m_circulation->valves.load(r);
    m_circulation->meter.load(r);
    m_circulation->loop.load(r);
  }
  // The fluid solver caches its list of fluid particles by the particle count: the count is the
  // same, the kinds are too (a particle's kind never changes), so the list still holds.
}

}  // namespace hs::cardiac
