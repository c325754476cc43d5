#pragma once
// The viewer's side of choosing the beating region: keeps the selection being edited and the
// one the simulation runs with, acts on the panel's requests (segment clicks, Clear, All,
// Revert, Apply), paints with the brush, and hands the selection to the scene (highlight) and
// to the scenario (on Apply). No GL or window code, so ViewerApp stays the frame loop only.
#include <cstdint>
#include <optional>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "viewer/region/beating_selection.h"
#include "viewer/region/brush_selection.h"
#include "viewer/region/region_panel.h"

namespace hs::viewer {

class RegionEditor {
 public:
  // A new scenario (not a restart): the selection is what its cycle makes beat, nothing is
  // applied yet. The tint starts on when the scenario chose a region itself.
  void startScenario(const cardiac::HeartSimulation& sim, RegionControls& controls);

  // Acts on the one-frame requests and clears them. Returns true when Apply was asked for and
  // the selection is not empty: the caller restarts the simulation (configure() then puts the
  // selection into the cycle).
  bool handleRequests(RegionControls& controls);

  // One frame of a brush stroke at the query's position: adds the visible wall under it, or
  // removes it with `erase`.
  void paint(const cardiac::HeartSimulation& sim, const BrushQuery& query, bool erase,
             RegionControls& controls);

  // The applied selection as the cycle's segments and vertices; the scenario's own region
  // until something has been applied.
  void configure(cardiac::Scenario& scenario) const;

  void fillStatus(RegionStatus& status, bool cycleEnabled) const;

  // For render::SceneOptions::beating: the selection when shown, else nothing tinted.
  [[nodiscard]] std::vector<std::uint8_t> highlight(const RegionControls& controls) const;

  [[nodiscard]] const BeatingSelection& selection() const { return m_selection; }
  [[nodiscard]] bool available() const { return m_selection.selectableCount() > 0; }

 private:
  BeatingSelection m_selection;  // being edited
  BeatingSelection m_running;    // what the simulation beats with
  bool m_applied = false;        // m_running came from Apply (not from the scenario)
};

}  // namespace hs::viewer
