#pragma once
// A synthetic recorded beat for the [motion] tests: frames of an endocardium scaled about its
// vertex centroid, so that the volume they enclose follows a known curve (a linear map scales
// every volume by its determinant, the flat caps over the annuli too): V_f = V_0 r(f / count)
// with each frame scaled by cbrt(r). r is 1 at end-diastole (phase 0), 1 - ejection at
// end-systole (phase `systole`), a half cosine each way.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "cardiac/patient/patient_wall.h"

namespace hs::testing {

inline double volumeRatio(double phase, double ejection, double systole) {
  const double pi = std::numbers::pi;
  const double fall = phase < systole ? 0.5 * (1 - std::cos(pi * phase / systole))
                                      : 0.5 * (1 + std::cos(pi * (phase - systole) / (1 - systole)));
  return 1 - ejection * fall;
}

inline std::vector<cardiac::Surface> scaledFrames(const cardiac::Surface& endocardium, int count, double ejection,
                                                  double systole) {
  pbd::Vec3d centre = pbd::Vec3d::Zero();
  for (const pbd::Vec3& v : endocardium.vertices) centre += v.cast<double>();
  centre /= double(endocardium.vertices.size());
  std::vector<cardiac::Surface> frames;
  for (int f = 0; f < count; ++f) {
    const double scale = std::cbrt(volumeRatio(double(f) / count, ejection, systole));
    cardiac::Surface frame = endocardium;
    for (pbd::Vec3& v : frame.vertices) v = (centre + scale * (v.cast<double>() - centre)).cast<pbd::Real>();
    frames.push_back(std::move(frame));
  }
  return frames;
}

// Wavefront OBJ, 1-based faces, full precision.
inline void writeObj(const std::filesystem::path& file, const cardiac::Surface& s) {
  std::ofstream out(file);
  out.precision(9);
  for (const pbd::Vec3& v : s.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const pbd::Triangle& t : s.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

// Frames 0..count-1 written as dir/frame_000.obj ...; returns the pattern "dir/frame_{frame:03d}.obj".
inline std::string writeFrames(const std::filesystem::path& dir, const std::vector<cardiac::Surface>& frames) {
  std::filesystem::create_directories(dir);
  char name[32];
  for (std::size_t f = 0; f < frames.size(); ++f) {
    std::snprintf(name, sizeof name, "frame_%03zu.obj", f);
    writeObj(dir / name, frames[f]);
  }
  return (dir / "frame_{frame:03d}.obj").string();
}

}  // namespace hs::testing
