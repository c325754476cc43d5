#include "pbd/fluid/fluid_setup.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hs::pbd {

std::vector<Vec3> fluidBlock(const Vec3& lower, const Vec3& upper, Real spacing) {
  std::array<int, 3> count{};
  for (int a = 0; a < 3; ++a) {
    // Whole cells only; the small tolerance keeps (upper - lower) = k d from losing a cell
    // to rounding.
    const Real cells = (upper[a] - lower[a]) / spacing;
    count[std::size_t(a)] = std::max(0, int(std::floor(cells + Real(1e-4))));
  }
  std::vector<Vec3> x;
  x.reserve(std::size_t(count[0]) * std::size_t(count[1]) * std::size_t(count[2]));
  for (int k = 0; k < count[2]; ++k)
    for (int j = 0; j < count[1]; ++j)
      for (int i = 0; i < count[0]; ++i)
        x.push_back(lower + spacing * Vec3(Real(i) + Real(0.5), Real(j) + Real(0.5), Real(k) + Real(0.5)));
  return x;
}

std::vector<Plane> boxWalls(const Vec3& lower, const Vec3& upper) {
  std::vector<Plane> walls;
  for (int a = 0; a < 3; ++a) {
    Plane low, high;
    low.normal = Vec3::Unit(a);  // n.x >= lower
    low.offset = lower[a];
    high.normal = -Vec3::Unit(a);  // -n.x >= -upper
    high.offset = -upper[a];
    walls.push_back(low);
    walls.push_back(high);
  }
  return walls;
}

}  // namespace hs::pbd
