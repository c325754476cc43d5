#pragma once
// metrics.csv of `heartsim run`: one row per step. Columns: step, time and phase; with a heart
// the cavity volume, the wall's volume errors, inverted tets and rest deviation; with blood its
// loss, density error, speed and wall penetration; with both, the flow path (valves, particles
// per region, volume through each orifice in mL, mean pressure per region); with the lumped
// circulation its pressures (mmHg), volume, flows (mL/s), valves and activations, the wall's
// contraction and base descent, and the vessels' fill.
#include <filesystem>
#include <fstream>
#include <ostream>

#include "cardiac/run_monitor.h"

namespace hs::io {

struct MetricsColumns {
  bool heart = false, blood = false, flows = false, lumped = false;
};

void writeMetricsHeader(std::ostream& csv, const MetricsColumns& columns);
// `sample` from a RunMonitor that gathers every column.
void writeMetricsRow(std::ostream& csv, const MetricsColumns& columns, const cardiac::StepSample& sample);

// The file: opened (and the header written) on construction, one row per add(). Throws
// std::runtime_error naming the file when it cannot be opened or written.
class MetricsCsvFile {
 public:
  MetricsCsvFile(const std::filesystem::path& path, const MetricsColumns& columns);
  void add(const cardiac::StepSample& sample) { writeMetricsRow(m_csv, m_columns, sample); }
  // Flushes; throws when anything written was lost (a full disk).
  void close();

 private:
  std::filesystem::path m_path;
  MetricsColumns m_columns;
  std::ofstream m_csv;
};

}  // namespace hs::io
