#include "cardiac/anatomy/aha_segments.h"

#include <cmath>
#include <numbers>

namespace hs::cardiac {

double ahaAngleDeg(const Eigen::Vector3d& p) {
  const double deg = std::atan2(p.dot(kSeptal), p.dot(kAnterior)) * 180.0 / std::numbers::pi;
  return deg < 0 ? deg + 360.0 : deg;
}

std::uint8_t ahaSegment(const Eigen::Vector3d& p, double cavityLength) {
  const double depth = -p.y() / cavityLength;
  if (depth >= kApexCapDepth) return 17;
  const double angle = ahaAngleDeg(p);
  if (depth >= 2.0 / 3.0) {
    // Apical ring: 90-degree sectors centred on 0, 90, 180, 270.
    const auto sector = static_cast<int>(std::fmod(angle + 45.0, 360.0) / 90.0) % 4;
    return static_cast<std::uint8_t>(13 + sector);
  }
  // Basal and mid rings: 60-degree sectors centred on 0, 60, ..., 300.
  const auto sector = static_cast<int>(std::fmod(angle + 30.0, 360.0) / 60.0) % 6;
  return static_cast<std::uint8_t>((depth < 1.0 / 3.0 ? 1 : 7) + sector);
}

}  // namespace hs::cardiac
