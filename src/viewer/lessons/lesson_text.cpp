#include "viewer/lessons/lesson_text.h"

#include <algorithm>
#include <cstdio>

namespace hs::viewer {
namespace {

constexpr std::array<FigureInfo, std::size_t(LessonFigure::Count)> kFigures = {{
    {"ef", "%.0f", "ejection fraction, %"},
    {"sv", "%.0f", "stroke volume, mL"},
    {"edv", "%.0f", "end-diastolic volume, mL"},
    {"esv", "%.0f", "end-systolic volume, mL"},
    {"co", "%.1f", "cardiac output, L/min"},
    {"hr", "%.0f", "heart rate of the beat, bpm"},
    {"sbp", "%.0f", "aortic systolic pressure, mmHg (lumped circulation)"},
    {"dbp", "%.0f", "aortic diastolic pressure, mmHg (lumped circulation)"},
    {"lvedp", "%.0f", "LV end-diastolic pressure, mmHg (lumped circulation)"},
    {"direct", "%.0f", "direct flow, % of the end-diastolic volume (3D blood)"},
    {"retained", "%.0f", "retained inflow, % of the end-diastolic volume (3D blood)"},
    {"delayed", "%.0f", "delayed ejection, % of the end-diastolic volume (3D blood)"},
    {"residual", "%.0f", "residual volume, % of the end-diastolic volume (3D blood)"},
    {"stayed", "%.0f", "blood in the ventricle more than 3 beats, % of the end-diastolic volume (3D blood)"},
}};

std::optional<LessonFigure> figureNamed(std::string_view name) {
  for (std::size_t i = 0; i < kFigures.size(); ++i)
    if (name == kFigures[i].name) return LessonFigure(i);
  return std::nullopt;
}

std::string figureList() {
  std::string list;
  for (const FigureInfo& f : kFigures) list += (list.empty() ? "" : ", ") + std::string(f.name);
  return list;
}

// A placeholder's parts: "ef@normal" -> figure "ef", mark "normal".
struct Placeholder {
  std::string_view figure, mark;
};
Placeholder split(std::string_view inside) {
  const auto at = inside.find('@');
  if (at == std::string_view::npos) return {inside, {}};
  return {inside.substr(0, at), inside.substr(at + 1)};
}

// Calls fn(literal text) and fn-placeholder(inside) in order; returns an error for an
// unclosed or stray brace.
template <class Literal, class Quote>
std::string walk(std::string_view text, Literal literal, Quote quote) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto open = text.find_first_of("{}", pos);
    if (open == std::string_view::npos) break;
    if (text[open] == '}') return "a '}' without its '{'";
    const auto close = text.find_first_of("{}", open + 1);
    if (close == std::string_view::npos || text[close] == '{')
      return "a '{' without its '}' (figures are quoted as {ef} or {ef@mark})";
    literal(text.substr(pos, open - pos));
    quote(text.substr(open + 1, close - open - 1));
    pos = close + 1;
  }
  literal(text.substr(std::min(pos, text.size())));
  return "";
}

}  // namespace

const FigureInfo& figureInfo(LessonFigure figure) { return kFigures[std::size_t(figure)]; }

LessonFigures measuredFigures(const ViewerStatus& status) {
  LessonFigures f;
  auto set = [&](LessonFigure which, double value) { f.values[std::size_t(which)] = value; };
  const PumpStatus& pump = status.pump;
  if (pump.beats.last) {
    const ClinicalFigures c = clinicalFigures(*pump.beats.last, pump.scale);
    set(LessonFigure::Ef, c.ejectionFraction);
    set(LessonFigure::Sv, c.strokeVolume);
    set(LessonFigure::Edv, c.edv);
    set(LessonFigure::Esv, c.esv);
    if (c.heartRate > 0) set(LessonFigure::Hr, c.heartRate), set(LessonFigure::Co, c.cardiacOutput);
  }
  if (const std::optional<cardiac::FlowComponents>& c = pump.flowComponents; c && c->particles > 0) {
    set(LessonFigure::Direct, 100 * c->direct);
    set(LessonFigure::Retained, 100 * c->retainedInflow);
    set(LessonFigure::Delayed, 100 * c->delayedEjection);
    set(LessonFigure::Residual, 100 * c->residual);
    set(LessonFigure::Stayed, 100 * c->stayedOverThreeBeats);
  }
  if (const auto& beat = status.circulation.lastBeat; status.circulation.lumped && beat && beat->edv > 0) {
    const double mL = 1e6;
    set(LessonFigure::Edv, beat->edv * mL);
    set(LessonFigure::Esv, beat->esv * mL);
    set(LessonFigure::Sv, beat->totalStrokeVolume() * mL);
    set(LessonFigure::Ef, 100 * beat->totalStrokeVolume() / beat->edv);
    set(LessonFigure::Sbp, beat->aorticSystolic / kPascalPerMmHg);
    set(LessonFigure::Dbp, beat->aorticDiastolic / kPascalPerMmHg);
    set(LessonFigure::Lvedp, beat->lvEndDiastolic / kPascalPerMmHg);
  }
  return f;
}

std::string checkPlaceholders(std::string_view text, const std::vector<std::string>& marks) {
  std::string error;
  const std::string shape = walk(
      text, [](std::string_view) {},
      [&](std::string_view inside) {
        if (!error.empty()) return;
        const Placeholder p = split(inside);
        if (!figureNamed(p.figure))
          error = "unknown figure '" + std::string(p.figure) + "' in {" + std::string(inside) +
                  "} (figures: " + figureList() + ")";
        else if (inside.find('@') != std::string_view::npos &&
                 std::find(marks.begin(), marks.end(), p.mark) == marks.end())
          error = "{" + std::string(inside) + "}: no earlier step has mark = \"" + std::string(p.mark) + "\"";
      });
  return shape.empty() ? error : shape;
}

std::string fillFigures(std::string_view text, const LessonFigures& now,
                        const std::map<std::string, LessonFigures, std::less<>>& marks) {
  std::string out;
  walk(
      text, [&](std::string_view literal) { out += literal; },
      [&](std::string_view inside) {
        const Placeholder p = split(inside);
        const std::optional<LessonFigure> figure = figureNamed(p.figure);
        const auto marked = marks.find(p.mark);
        const LessonFigures* source = inside.find('@') == std::string_view::npos ? &now
                                      : marked != marks.end()                    ? &marked->second
                                                                                 : nullptr;
        const std::optional<double> value = figure && source ? (*source)[*figure] : std::nullopt;
        if (!value) {
          out += "--";
          return;
        }
        char number[32];
        std::snprintf(number, sizeof number, figureInfo(*figure).format, *value);
        out += number;
      });
  return out;
}

}  // namespace hs::viewer
