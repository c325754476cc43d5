// metrics.csv: every row has as many fields as the header names, for each set of columns, and
// the numbers read back as written; the file reports a directory it cannot write to.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/output/metrics_csv.h"

namespace hs::io {
namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string field; std::getline(s, field, ',');) out.push_back(field);
  return out;
}

cardiac::StepSample sample() {
  cardiac::StepSample s;
  s.step = 7;
  s.time = 0.035;
  s.phase = cardiac::Phase::Diastole;
  s.heartPhase = cardiac::HeartPhase::Filling;
  s.cavity = 1.25e-4;
  s.tissue.volumeErrorMean = cardiac::Real(0.002);
  s.tissue.volumeErrorMax = cardiac::Real(0.03);
  s.tissue.invertedTets = 0;
  s.restDeviation = cardiac::Real(0.015);
  cardiac::BloodStats blood;
  blood.lost = 2;
  blood.densityErrorMean = 0.011;
  blood.densityErrorMax = 0.09;
  blood.maxSpeed = 0.75;
  blood.insideWall = 1;
  s.blood = blood;
  s.circulation = true;
  s.flows.mitralForward = 2e-6;
  s.flowStep.valves.mitralOpen = true;
  s.flowStep.valves.aorticOpen = false;
  s.flowStep.count[std::size_t(cardiac::FlowRegion::Ventricle)] = 900;
  s.flowStep.pressure[std::size_t(cardiac::FlowRegion::Ventricle)] = 1333.0;
  return s;
}

// Header name -> value of one written row.
std::map<std::string, std::string> writeOne(const MetricsColumns& columns) {
  std::ostringstream csv;
  writeMetricsHeader(csv, columns);
  csv.precision(9);
  writeMetricsRow(csv, columns, sample());
  std::istringstream in(csv.str());
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const auto names = fields(header), values = fields(row);
  EXPECT_EQ(names.size(), values.size()) << header << '\n' << row;
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < std::min(names.size(), values.size()); ++i) out[names[i]] = values[i];
  return out;
}

TEST(MetricsCsv, RowsMatchTheHeaderForEveryColumnSet) {
  for (const bool heart : {false, true})
    for (const bool blood : {false, true})
      for (const bool flows : {false, true}) writeOne({heart, blood, flows});
  EXPECT_EQ(writeOne({}).size(), 4u) << "step, time, phase, wall_phase";
  EXPECT_EQ(writeOne({false, false, false}).at("phase"), "none") << "no heart, no phase";
  EXPECT_EQ(writeOne({false, false, false}).at("wall_phase"), "none") << "no heart, no wall";
}

TEST(MetricsCsv, ValuesReadBackAsWritten) {
  const auto row = writeOne({true, true, true});
  EXPECT_EQ(row.at("step"), "7");
  EXPECT_DOUBLE_EQ(std::stod(row.at("time_s")), 0.035);
  EXPECT_EQ(row.at("phase"), "filling") << "the heart's phase, from the valves";
  EXPECT_EQ(row.at("wall_phase"), "diastole") << "the wall's own clock";
  EXPECT_DOUBLE_EQ(std::stod(row.at("cavity_volume_m3")), 1.25e-4);
  EXPECT_DOUBLE_EQ(std::stod(row.at("cavity_volume_ml")), 125.0);
  EXPECT_NEAR(std::stod(row.at("volume_error_max")), 0.03, 1e-7);
  EXPECT_NEAR(std::stod(row.at("rest_deviation_rel")), 0.015, 1e-7);
  EXPECT_EQ(row.at("blood_lost"), "2");
  EXPECT_DOUBLE_EQ(std::stod(row.at("blood_density_error_max")), 0.09);
  EXPECT_EQ(row.at("blood_inside_wall"), "1");
  EXPECT_EQ(row.at("mitral_open"), "1");
  EXPECT_EQ(row.at("aortic_open"), "0");
  EXPECT_EQ(row.at("particles_lv"), "900");
  EXPECT_DOUBLE_EQ(std::stod(row.at("mitral_forward_ml")), 2.0);
  EXPECT_DOUBLE_EQ(std::stod(row.at("pressure_lv_pa")), 1333.0);
}

TEST(MetricsCsv, FileWritesHeaderAndRowsOrNamesItself) {
  const auto path = std::filesystem::path(::testing::TempDir()) / "metrics_test.csv";
  {
    MetricsCsvFile file(path, {true, false, false});
    file.add(sample());
    file.add(sample());
    file.close();
  }
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 3);
  const auto bad = std::filesystem::path(::testing::TempDir()) / "no-such-dir" / "metrics.csv";
  try {
    MetricsCsvFile file(bad, {});
    FAIL() << "opened " << bad;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hs::io
