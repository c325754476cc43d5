#pragma once
// The run's report on the heart as a pump: per-step flow columns of metrics.csv (valves,
// particles per region, volume through each orifice, mean pressure per region) and the
// per-beat clinical figures of the JSON summary.
#include <nlohmann/json.hpp>
#include <ostream>

#include "cardiac/beat_metrics.h"
#include "cardiac/circulation.h"

namespace hs::app {

void writeFlowHeader(std::ostream& csv);
void writeFlowRow(std::ostream& csv, const cardiac::Circulation& circulation);

// "heart": beats and the means over complete beats after the first, in mL, L/min.
nlohmann::ordered_json heartPumpReport(const cardiac::BeatTracker& beats);

}  // namespace hs::app
