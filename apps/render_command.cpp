#include "render_command.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "cardiac/heart_simulation.h"
#include "exit_codes.h"
#include "progress_bar.h"
#include "render/gl_context.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "simulation_setup.h"
#include "viz/image.h"

namespace hs::app {
namespace {

namespace fs = std::filesystem;

// One line on stderr and exit 2: every option is checked before anything is simulated.
struct BadInput {
  std::string message;
};

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');) {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    items.push_back(first == std::string::npos ? "" : item.substr(first, last - first + 1));
  }
  if (!list.empty() && list.back() == ',') items.emplace_back();
  return items;
}

std::vector<render::View> parseViews(const std::string& list) {
  std::vector<render::View> views;
  for (const std::string& name : splitList(list)) {
    const auto view = render::parseView(name);
    if (!view)
      throw BadInput{"--views: unknown view '" + name + "'; valid views: " + render::viewNames()};
    if (std::find(views.begin(), views.end(), *view) == views.end()) views.push_back(*view);
  }
  if (views.empty()) throw BadInput{"--views: no view given; valid views: " + render::viewNames()};
  return views;
}

// Sorted, without duplicates (as written in file names).
std::vector<double> parseTimes(const std::string& list, double duration) {
  std::vector<double> times;
  std::set<std::string> names;
  for (const std::string& text : splitList(list)) {
    char* end = nullptr;
    const double t = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(t))
      throw BadInput{"--times: '" + text + "' is not a time in seconds (give a comma list such as 0,0.08,1)"};
    if (t < 0) throw BadInput{"--times: " + text + " s is negative; times count seconds from the start (>= 0)"};
    if (t > duration * (1 + 1e-9))
      throw BadInput{"--times: " + text + " s is beyond the scenario's duration of " + formatTime(duration) +
                     " s (lengthen it with --set simulation.duration=...)"};
    if (names.insert(formatTime(t)).second) times.push_back(t);
  }
  if (times.empty()) throw BadInput{"--times: no time given (give a comma list such as 0,0.08,1)"};
  std::sort(times.begin(), times.end());
  return times;
}

std::pair<int, int> parseSize(const std::string& text) {
  constexpr int kMin = 16, kMax = 8192;
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < kMin ||
      h < kMin || w > kMax || h > kMax)
    throw BadInput{"--size: '" + text + "' is not WIDTHxHEIGHT in pixels (e.g. 800x600, each " +
                   std::to_string(kMin) + " to " + std::to_string(kMax) + ")"};
  return {w, h};
}

void prepareOutputDir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw BadInput{"--out: cannot create output directory '" + dir.string() + "': " +
                   (ec ? ec.message() : "not a directory")};
  // Permissions alone do not tell (root, read-only mounts): try to write.
  const fs::path probe = dir / ".heartsim-write-test";
  {
    std::ofstream test(probe);
    if (!(test << "x")) throw BadInput{"--out: output directory '" + dir.string() + "' is not writable"};
  }
  fs::remove(probe, ec);
}

// Box-filtered reduction by an integer factor, for the contact sheet's cells.
viz::Image shrink(const viz::Image& image, int factor) {
  if (factor <= 1) return image;
  viz::Image small(image.width() / factor, image.height() / factor);
  for (int y = 0; y < small.height(); ++y)
    for (int x = 0; x < small.width(); ++x) {
      int r = 0, g = 0, b = 0;
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const viz::Rgb c = image.at(x * factor + dx, y * factor + dy);
          r += c.r, g += c.g, b += c.b;
        }
      const int n = factor * factor;
      small.set(x, y, {std::uint8_t(r / n), std::uint8_t(g / n), std::uint8_t(b / n)});
    }
  return small;
}

const char* viewCaption(render::View view) {
  switch (view) {
    case render::View::Front: return "front (anterior)";
    case render::View::Left: return "left (from -x, septal side)";
    case render::View::Right: return "right (from +x, lateral side)";
    case render::View::Top: return "top (onto the base)";
  }
  return "";
}

std::string fitText(std::string text, int width, int scale) {
  while (text.size() > 3 && viz::Image::textWidth(text, scale) > width) text = text.substr(0, text.size() - 4) + "...";
  return text;
}

// Rows = times, columns = views (thesis figures 5.2-5.17), a title and a colour key below.
viz::Image contactSheet(const std::string& title, const std::vector<std::string>& rowLabels,
                        const std::vector<render::View>& views, const std::vector<std::vector<viz::Image>>& cells,
                        const std::string& footer) {
  const int cellW = cells[0][0].width(), cellH = cells[0][0].height();
  const int scale = 2, gap = 8, margin = 16;
  const int labelW = viz::Image::textWidth("t = 00.000 s", scale) + gap;
  const int titleH = viz::Image::lineHeight(3) + gap, headerH = viz::Image::lineHeight(scale) + gap;
  const int footerH = viz::Image::lineHeight(scale) + gap;
  const int cols = int(views.size()), rows = int(rowLabels.size());
  const int width = std::max(2 * margin + labelW + cols * cellW + (cols - 1) * gap, 480);
  const int height = 2 * margin + titleH + headerH + rows * cellH + (rows - 1) * gap + footerH;
  viz::Image sheet(width, height, {255, 255, 255});
  const viz::Rgb ink{30, 30, 40};
  sheet.drawText(margin, margin, fitText(title, width - 2 * margin, 3), 3, ink);
  const int top = margin + titleH + headerH, left = margin + labelW;
  for (int c = 0; c < cols; ++c) {
    const std::string caption = fitText(viewCaption(views[c]), cellW, scale);
    const int x = left + c * (cellW + gap) + (cellW - viz::Image::textWidth(caption, scale)) / 2;
    sheet.drawText(x, margin + titleH, caption, scale, ink);
  }
  for (int r = 0; r < rows; ++r) {
    const int y = top + r * (cellH + gap);
    sheet.drawText(margin, y + cellH / 2 - viz::Image::capHeight(scale) / 2, rowLabels[r], scale, ink);
    for (int c = 0; c < cols; ++c) {
      sheet.blit(cells[r][c], left + c * (cellW + gap), y);
      sheet.strokeRect({left + c * (cellW + gap) - 1, y - 1, cellW + 2, cellH + 2}, {170, 175, 185});
    }
  }
  sheet.drawText(margin, height - margin - viz::Image::lineHeight(scale) + gap, fitText(footer, width - 2 * margin, scale),
                 scale, {80, 80, 90});
  return sheet;
}

}  // namespace

std::string formatTime(double seconds) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", seconds);
  std::string s = buffer;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

int renderCommand(const RenderOptions& options) {
  std::optional<cardiac::Scenario> loaded = loadScenarioOrReport(options.scenario, options.overrides);
  if (!loaded) return kExitBadInput;
  const cardiac::Scenario& scenario = *loaded;
  const double duration = double(scenario.simulation.duration);
  const double dt = double(scenario.simulation.dt);

  std::vector<render::View> views;
  std::vector<double> times;
  int width = 0, height = 0;
  const fs::path outDir =
      options.outDir.empty() ? fs::path("results") / scenario.name / "render" : fs::path(options.outDir);
  try {
    views = parseViews(options.views);
    times = parseTimes(options.times.empty() ? "0," + formatTime(duration) : options.times, duration);
    std::tie(width, height) = parseSize(options.size);
    if (!(options.wallOpacity > 0 && options.wallOpacity <= 1))
      throw BadInput{"--wall-opacity: must be in (0, 1], got " + formatTime(options.wallOpacity)};
    if (!(options.speedMax >= 0) || !std::isfinite(options.speedMax))
      throw BadInput{"--speed-max: must be a finite speed >= 0 (m/s; 0 = from the scenario)"};
    if (!(options.pressureMax >= 0) || !std::isfinite(options.pressureMax))
      throw BadInput{"--pressure-max: must be a finite pressure >= 0 (Pa; 0 = from the scenario)"};
    if (!render::parseBloodColour(options.bloodColour))
      throw BadInput{"--blood-colour: unknown colour '" + options.bloodColour + "'; valid: speed, pressure, origin"};
    if (!std::isfinite(options.clipZ)) throw BadInput{"--clip-z: must be a finite position (m)"};
    prepareOutputDir(outDir);
  } catch (const BadInput& e) {
    std::cerr << "heartsim: error: " << e.message << '\n';
    return kExitBadInput;
  }

  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  int setupError = kExitOk;
  const std::unique_ptr<cardiac::HeartSimulation> simPtr = makeSimulation(scenario, threads, options.scenario, setupError);
  if (!simPtr) return setupError;
  cardiac::HeartSimulation& sim = *simPtr;

  std::optional<render::GlContext> gl;
  std::optional<render::FrameTarget> target;
  std::optional<render::Renderer> renderer;
  try {
    gl.emplace();
    target.emplace(width, height);
    renderer.emplace();
  } catch (const std::runtime_error& e) {
    std::cerr << "heartsim: error: cannot render: " << e.what() << '\n';
    return kExitFailure;
  }

  render::SceneOptions sceneOptions;
  sceneOptions.clip = options.clip.value_or(sim.hasHeart());
  sceneOptions.clipZ = float(options.clipZ);
  sceneOptions.wallOpacity = float(options.wallOpacity);
  sceneOptions.speedMax = options.speedMax;
  sceneOptions.pressureMax = options.pressureMax;
  sceneOptions.bloodColour = *render::parseBloodColour(options.bloodColour);
  // One scale for every time and view of the sheet.
  const double scaleMax = render::colourScaleMax(sceneOptions, scenario);
  const float aspect = float(width) / float(height);
  const int shrinkFactor = std::max(1, (width + 399) / 400);

  const auto totalSteps = static_cast<long>(std::llround(times.back() / dt));
  ProgressBar progress(totalSteps);
  std::vector<std::vector<viz::Image>> cells;
  std::vector<std::string> rowLabels;
  try {
    for (const double t : times) {
      const auto stepsToTime = static_cast<std::int64_t>(std::llround(t / dt));
      while (sim.stepCount() < stepsToTime) {
        sim.step();
        progress.update(static_cast<long>(sim.stepCount()), sim.time());
      }
      const cardiac::TissueStats tissue = sim.tissueStats();
      if (!tissue.finite) {
        progress.finish();
        std::cerr << "heartsim: error: simulation became invalid before t = " << formatTime(t) << " s: particle "
                  << tissue.firstNonFinite << " has a non-finite position or velocity\n";
        return kExitInvalidSimulation;
      }
      render::Scene scene = render::buildScene(sim, sceneOptions);
      const std::string label = "t = " + formatTime(t) + " s";
      rowLabels.push_back(label);
      cells.emplace_back();
      for (const render::View view : views) {
        render::applyView(scene, sceneOptions, view);
        target->bind();
        renderer->draw(scene, render::viewCamera(view, scene.bounds, aspect), width, height);
        viz::Image image = target->read();
        if (sim.hasBlood()) render::drawBloodLegend(image, sceneOptions.bloodColour, scaleMax);
        const int textScale = std::max(1, std::min(width, height) / 300);
        image.drawText(6 * textScale, 6 * textScale, std::string(render::viewName(view)) + ", " + label, textScale,
                       {40, 40, 50});
        image.savePng((outDir / ("t" + formatTime(t) + "_" + render::viewName(view) + ".png")).string());
        cells.back().push_back(shrink(image, shrinkFactor));
      }
    }
    progress.finish();
    std::string title = scenario.name;
    if (!scenario.description.empty()) title += ": " + scenario.description;
    std::string footer;
    if (sim.hasHeart())
      footer += "wall: red = myocardium, orange = chosen beating region, light = base plate and vessels, "
                "dark = cut face" +
                std::string(sceneOptions.clip ? " (front view cut open at z = " + formatTime(options.clipZ) + " m)" : "");
    if (sim.hasBlood()) {
      footer += footer.empty() ? "" : "; ";
      switch (sceneOptions.bloodColour) {
        case render::BloodColour::Speed:
          footer += "blood coloured by speed, blue 0 to yellow " + formatTime(scaleMax) + " m/s";
          break;
        case render::BloodColour::Pressure:
          footer += "blood coloured by pressure, blue 0 to yellow " + formatTime(scaleMax) + " Pa";
          break;
        case render::BloodColour::Origin:
          footer += "blood coloured by where it started:";
          for (const render::OriginKeyRow& row : render::originKey())
            footer += std::string(" ") + row.colourName + " " + row.label + ",";
          footer.pop_back();
          break;
      }
    }
    contactSheet(title, rowLabels, views, cells, footer).savePng((outDir / "contact_sheet.png").string());
  } catch (const std::runtime_error& e) {
    progress.finish();
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitFailure;
  }
  std::cerr << "heartsim: " << scenario.name << ": " << times.size() * views.size() << " views and a contact sheet in "
            << outDir.string() << " (" << gl->description() << ")\n";
  return kExitOk;
}

}  // namespace hs::app
