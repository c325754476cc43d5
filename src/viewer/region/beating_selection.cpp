#include "viewer/region/beating_selection.h"

#include <algorithm>

#include "cardiac/motion/cardiac_cycle.h"

namespace hs::viewer {

BeatingSelection::BeatingSelection(const cardiac::LvModel& model, const cardiac::CycleSettings& cycle) {
  const std::size_t n = model.mesh.vertices.size();
  m_chosen.assign(n, 0);
  m_selectable.assign(n, 0);
  m_segment.assign(n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    if (model.region[v] != cardiac::Region::Myocardium) continue;
    m_selectable[v] = 1;
    m_segment[v] = model.segment[v] <= 17 ? model.segment[v] : 0;
  }
  for (const cardiac::Index id : model.pinned)
    if (id < n) m_selectable[id] = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!m_selectable[v]) continue;
    ++m_selectableCount;
    ++m_totalIn[m_segment[v]];
  }
  for (const cardiac::Index v : cardiac::selectBeatingVertices(cycle, model)) set(v, true);
}

void BeatingSelection::set(std::uint32_t v, bool on) {
  if (v >= m_chosen.size() || !m_selectable[v] || bool(m_chosen[v]) == on) return;
  m_chosen[v] = on ? 1 : 0;
  if (on) {
    ++m_count;
    ++m_chosenIn[m_segment[v]];
  } else {
    --m_count;
    --m_chosenIn[m_segment[v]];
  }
}

void BeatingSelection::paint(const std::vector<std::uint32_t>& vertices, bool on) {
  for (const std::uint32_t v : vertices) {
    if (v >= m_chosen.size() || !m_selectable[v]) continue;
    set(v, on);
    set(v ^ 1u, on);  // the partner on the other side of the wall
  }
}

void BeatingSelection::toggleSegment(int segment) {
  if (segment < 1 || segment > 17) return;
  const bool fill = segmentState(segment) != SegmentState::Full;
  for (std::size_t v = 0; v < m_chosen.size(); ++v)
    if (m_segment[v] == segment) set(std::uint32_t(v), fill);
}

void BeatingSelection::clear() {
  for (std::size_t v = 0; v < m_chosen.size(); ++v) set(std::uint32_t(v), false);
}

void BeatingSelection::selectAllMyocardium() {
  for (std::size_t v = 0; v < m_chosen.size(); ++v) set(std::uint32_t(v), true);
}

SegmentState BeatingSelection::segmentState(int segment) const {
  if (segment < 1 || segment > 17) return SegmentState::None;
  const std::size_t chosen = m_chosenIn[std::size_t(segment)], total = m_totalIn[std::size_t(segment)];
  if (chosen == 0) return SegmentState::None;
  return chosen == total ? SegmentState::Full : SegmentState::Partial;
}

void BeatingSelection::writeTo(cardiac::CycleSettings& cycle) const {
  cycle.segments.clear();
  cycle.vertices.clear();
  cycle.sphereEnabled = false;
  for (int s = 1; s <= 17; ++s)
    if (m_totalIn[std::size_t(s)] > 0 && segmentState(s) == SegmentState::Full) cycle.segments.push_back(s);
  for (std::size_t v = 0; v < m_chosen.size(); ++v) {
    if (!m_chosen[v]) continue;
    const int s = m_segment[v];
    if (s == 0 || segmentState(s) != SegmentState::Full) cycle.vertices.push_back(cardiac::Index(v));
  }
}

}  // namespace hs::viewer
