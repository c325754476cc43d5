#pragma once
// The measured figures a lesson's text can quote, and the placeholders that quote them:
// "{ef}" is the figure measured at the end of the step (the last complete beat), "{ef@normal}"
// the one kept by an earlier step with `mark = "normal"`. Pure text and arithmetic, no ImGui.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "viewer/panels/ui_panel.h"

namespace hs::viewer {

enum class LessonFigure { Ef, Sv, Edv, Esv, Co, Hr, Sbp, Dbp, Lvedp, Direct, Retained, Delayed, Residual, Stayed, Count };

struct FigureInfo {
  const char* name;    // as written in a placeholder: "ef"
  const char* format;  // printf format of the number: "%.0f"
  const char* meaning;  // for docs and error messages: "ejection fraction, %"
};
const FigureInfo& figureInfo(LessonFigure figure);

// One beat's figures; a figure not measured (no complete beat yet, no lumped circulation for
// the pressures) is empty and quoted as "--".
struct LessonFigures {
  std::array<std::optional<double>, std::size_t(LessonFigure::Count)> values{};
  [[nodiscard]] std::optional<double> operator[](LessonFigure f) const { return values[std::size_t(f)]; }
  [[nodiscard]] bool measured() const { return values[std::size_t(LessonFigure::Ef)].has_value(); }
};

// The last complete beat's figures as the panels show them: with the lumped circulation its
// beat (the circulation strip under the heart: volumes, EF, pressures), otherwise the pump
// panel's (the 3D cavity); heart rate and cardiac output from the pump panel; the flow
// components from the pump panel's last beat of the 3D blood.
LessonFigures measuredFigures(const ViewerStatus& status);

// "" when every placeholder of `text` names a figure and, after '@', one of `marks`; else one
// line saying what is wrong ("unknown figure 'eff' (figures: ef, sv, ...)").
std::string checkPlaceholders(std::string_view text, const std::vector<std::string>& marks);

// The text with each placeholder replaced by its figure.
std::string fillFigures(std::string_view text, const LessonFigures& now,
                        const std::map<std::string, LessonFigures, std::less<>>& marks);

}  // namespace hs::viewer
