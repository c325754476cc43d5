#include "viewer/region/region_editor.h"

#include <stdexcept>

#include "render/scene.h"

namespace hs::viewer {

void RegionEditor::startScenario(const cardiac::HeartSimulation& sim, RegionControls& controls) {
  m_selection = BeatingSelection();
  if (sim.hasHeart()) {
    try {
      m_selection = BeatingSelection(sim.model(), sim.scenario().cycle);
    } catch (const std::invalid_argument&) {
      // Bad vertex ids with the cycle off (with it on the simulation would not have started):
      // start from the whole myocardium instead.
      m_selection = BeatingSelection(sim.model(), cardiac::CycleSettings{});
    }
  }
  m_running = m_selection;
  m_applied = false;
  controls.showRegion = !render::chosenBeatingRegion(sim).empty();
  controls.paintMode = controls.paintMode && available();
}

bool RegionEditor::handleRequests(RegionControls& c) {
  const bool edited = c.segmentToggled > 0 || c.clearRequested || c.allRequested || c.revertRequested;
  if (c.segmentToggled > 0) m_selection.toggleSegment(c.segmentToggled);
  if (c.clearRequested) m_selection.clear();
  if (c.allRequested) m_selection.selectAllMyocardium();
  if (c.revertRequested) m_selection = m_running;
  // Whatever the student edits is shown, or the edit would go unseen.
  if (edited) c.showRegion = true;
  const bool apply = c.applyRequested && !m_selection.empty() && !(m_selection == m_running);
  if (apply) {
    m_running = m_selection;
    m_applied = true;
  }
  c.segmentToggled = 0;
  c.clearRequested = c.allRequested = c.revertRequested = c.applyRequested = false;
  return apply;
}

void RegionEditor::paint(const cardiac::HeartSimulation& sim, const BrushQuery& query, bool erase,
                         RegionControls& controls) {
  if (!sim.hasHeart() || !available()) return;
  const auto& model = sim.model();
  // The wall's particles come first: particle i is model vertex i (heart_simulation.h).
  const auto& x = sim.particles().position;
  std::vector<render::Vec3f> positions(model.mesh.vertices.size());
  for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = x[v].cast<float>();
  const BrushSurface surface{&positions, &m_selection.selectable(), &model.surface};
  m_selection.paint(verticesInBrush(surface, query), !erase);
  controls.showRegion = true;
}

void RegionEditor::configure(cardiac::Scenario& scenario) const {
  if (m_applied) m_running.writeTo(scenario.cycle);
}

void RegionEditor::fillStatus(RegionStatus& s, bool cycleEnabled) const {
  for (int k = 1; k <= 17; ++k) s.segments[std::size_t(k)] = m_selection.segmentState(k);
  s.count = m_selection.count();
  s.selectable = m_selection.selectableCount();
  s.pending = !(m_selection == m_running);
  s.cycleEnabled = cycleEnabled;
}

std::vector<std::uint8_t> RegionEditor::highlight(const RegionControls& controls) const {
  if (!controls.showRegion) return {};
  return m_selection.flags();
}

}  // namespace hs::viewer
