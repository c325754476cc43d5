// VTK output round trip: what writeVtu writes, readVtu reads back identically.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/output/vtk_writer.h"

namespace hs::io {
namespace {

TEST(VtkWriter, RoundTripKeepsPointsCellsAndArrays) {
  VtuFrame frame;
  frame.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(Real(0.125), Real(-2.5), Real(3e-4))};
  frame.tets = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  frame.intArrays = {{"aha_segment", {1, 2, 3, 17, 0}}};
  frame.vectorArrays = {{"velocity", {Vec3(1, 2, 3), Vec3::Zero(), Vec3(-1, 0, Real(0.5)), Vec3(0, 0, 1), Vec3(Real(1e-6), 0, 0)}}};
  const auto file = std::filesystem::path(::testing::TempDir()) / "roundtrip.vtu";
  writeVtu(file, frame);
  const VtuFrame back = readVtu(file);
  ASSERT_EQ(back.points.size(), frame.points.size());
  for (std::size_t i = 0; i < frame.points.size(); ++i) EXPECT_EQ(back.points[i], frame.points[i]) << i;
  EXPECT_EQ(back.tets, frame.tets);
  ASSERT_EQ(back.intArrays.size(), 1u);
  EXPECT_EQ(back.intArrays[0], frame.intArrays[0]);
  ASSERT_EQ(back.vectorArrays.size(), 1u);
  EXPECT_EQ(back.vectorArrays[0].first, "velocity");
  for (std::size_t i = 0; i < frame.points.size(); ++i)
    EXPECT_EQ(back.vectorArrays[0].second[i], frame.vectorArrays[0].second[i]) << i;
}

TEST(VtkWriter, UnwritablePathIsAClearError) {
  VtuFrame frame;
  try {
    writeVtu("/nonexistent-dir/x.vtu", frame);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.vtu"), std::string::npos);
  }
}

TEST(VtkWriter, NotAVtuFileIsAClearError) {
  const auto file = std::filesystem::path(::testing::TempDir()) / "garbage.vtu";
  std::ofstream(file) << "hello";
  EXPECT_THROW(readVtu(file), std::runtime_error);
}

TEST(VtkWriter, PvdListsEveryFrame) {
  const auto file = std::filesystem::path(::testing::TempDir()) / "series.pvd";
  PvdSeries series(file);
  series.add(0, "a.vtu");
  series.add(0.5, "b.vtu");
  series.write();
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("timestep=\"0.5\" part=\"0\" file=\"b.vtu\""), std::string::npos);
  EXPECT_NE(text.find("file=\"a.vtu\""), std::string::npos);
}

}  // namespace
}  // namespace hs::io
