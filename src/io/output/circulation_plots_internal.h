#pragma once
// Shared by circulation_plots.cpp and wiggers_diagram.cpp: clinical units and input checks.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "cardiac/circulation/circulation_trace.h"
#include "cardiac/circulation/clinical_units.h"
#include "viz/plot.h"

namespace hs::io {

// The figures speak mmHg and mL (clinical units at the edges, SI inside).
using cardiac::kCubicMetresPerMl;
using cardiac::kPascalPerMmHg;
inline double toMmHg(double pascal) { return pascal / kPascalPerMmHg; }
inline double toMl(double cubicMetres) { return cubicMetres / kCubicMetresPerMl; }

// Throws std::invalid_argument("<what>: no samples") or ("<what>: sample <i> has a non-finite
// <field> (<value>)").
void validateCirculationSamples(const std::vector<cardiac::CirculationSample>& samples,
                                const std::string& what);

// Picks the top corner for the legend and raises the top of spec.yRange (which must be set) so
// that the series [first, end) pass below the legend with a pad to spare: of the two top
// corners the one that needs the smaller raise. Nothing without labelled series.
void makeRoomForLegend(viz::PlotSpec& spec, std::size_t first, std::size_t end);

// A series without points yet (designated initialisers that skip members trip
// -Wmissing-field-initializers).
inline viz::Series plotSeries(std::string label, viz::Rgb colour,
                              viz::Series::Style style = viz::Series::Style::Line) {
  viz::Series series;
  series.label = std::move(label);
  series.colour = colour;
  series.style = style;
  return series;
}

}  // namespace hs::io
