#pragma once
// The beating region the student is choosing in the viewer (thesis 4.3.3,
// "selectedBeatingParticles"): one flag per model vertex, edited by ticking AHA segments on
// the bull's-eye or painting on the heart, and written back as CycleSettings.segments and
// CycleSettings.vertices when applied. Pure data over the LV model (no GL, no ImGui), tested.
//
// Only myocardium vertices that are not pinned can be chosen: the base plate and vessels never
// beat (cardiac::selectBeatingVertices). Painting marks the wall through its thickness: the
// shell is one tet thick with partner vertices 2i (cavity side) and 2i+1 (outside)
// (cardiac::LvModel), and the brush sees only the side facing the camera, so each painted
// vertex brings its partner along; otherwise the outside would contract without the inside.
#include <array>
#include <cstdint>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/scenario.h"

namespace hs::viewer {

enum class SegmentState { None, Partial, Full };

class BeatingSelection {
 public:
  BeatingSelection() = default;
  // What beats under `cycle` (cardiac::selectBeatingVertices: all myocardium when the cycle
  // names no region). Throws std::invalid_argument for ids the model rejects.
  BeatingSelection(const cardiac::LvModel& model, const cardiac::CycleSettings& cycle);

  // Adds (on) or removes the vertices and their transmural partners; ids that cannot beat
  // are ignored.
  void paint(const std::vector<std::uint32_t>& vertices, bool on);
  // A fully chosen segment is emptied, any other one filled.
  void toggleSegment(int segment);
  void clear();
  void selectAllMyocardium();

  [[nodiscard]] std::size_t count() const { return m_count; }
  [[nodiscard]] std::size_t selectableCount() const { return m_selectableCount; }
  [[nodiscard]] bool empty() const { return m_count == 0; }
  [[nodiscard]] bool isAllMyocardium() const { return m_count == m_selectableCount; }
  [[nodiscard]] SegmentState segmentState(int segment) const;
  // Per model vertex: 1 = chosen.
  [[nodiscard]] const std::vector<std::uint8_t>& flags() const { return m_chosen; }
  // Per model vertex: 1 = may be chosen (myocardium, not pinned).
  [[nodiscard]] const std::vector<std::uint8_t>& selectable() const { return m_selectable; }

  // The selection as the cycle's settings: segments = those chosen completely, vertices = the
  // chosen rest, sphere off; cardiac::selectBeatingVertices then gives back exactly this set.
  // The beat pattern, timing and the rest of `cycle` are left as they are.
  void writeTo(cardiac::CycleSettings& cycle) const;

  bool operator==(const BeatingSelection& other) const { return m_chosen == other.m_chosen; }

 private:
  void set(std::uint32_t v, bool on);

  std::vector<std::uint8_t> m_chosen, m_selectable;
  std::vector<std::uint8_t> m_segment;                    // per vertex, 1..17 or 0
  std::array<std::size_t, 18> m_chosenIn{}, m_totalIn{};  // per segment
  std::size_t m_count = 0, m_selectableCount = 0;
};

}  // namespace hs::viewer
