#pragma once
// `heartsim render`'s contact sheet: rows = times, columns = views (thesis figures 5.2-5.17),
// a title above and a colour key below, from the views shrunk to thumbnails.
#include <string>
#include <vector>

#include "render/renderer.h"
#include "viz/image.h"

namespace hs::app {

// Box-filtered reduction by an integer factor, for the sheet's cells.
viz::Image shrink(const viz::Image& image, int factor);

viz::Image contactSheet(const std::string& title, const std::vector<std::string>& rowLabels,
                        const std::vector<render::View>& views, const std::vector<std::vector<viz::Image>>& cells,
                        const std::string& footer);

}  // namespace hs::app
