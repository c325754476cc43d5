#pragma once
// The shape of a procedural vessel above its orifice (lv_model.h): where its lumen's axis is and
// how wide the lumen is at each height. Today's vessels are straight vertical tubes of the
// orifice's radius; an anatomical heart's are not:
//  * the aortic root bulges into three sinuses of Valsalva above the annulus (lumen diameter
//    30-34 mm in an adult, against a 20-24 mm annulus) before the ascending aorta;
//  * the inflow widens into a left atrium over the mitral annulus;
//  * the two lean apart over their lower half, as the aorta and the atrium do, so that the
//    sinuses and the atrium clear each other above a base too narrow for both side by side.
// Both the mesh (lv_mid_surface.cpp) and the flow path (flow_path.h: which region blood is in,
// where its first sites go) read the shape from here, so they agree exactly.
//
// Heights are shares u of the vessel: 0 at the orifice, 1 at the far end. The mesh's rows are
// evenly spaced in height, and a wall moved by the lumped circulation carries a vessel vertex by
// a share of its ring's descent that falls linearly to 0 at the pinned far end, so a point keeps
// its u as the base moves (FlowPath::descended).
//
//   axis(u)        = orifice centre + offset S((u - bendFrom) / (bendEnd - bendFrom)) away,
//                    S(t) = 3t^2 - 2t^3 on [0, 1], 0 before, 1 after
//   radius(u, th)  = R + (R_bulge - R) B(u) L(th),
//   B(u)           = sin^2(pi (u - from) / (to - from)) on [from, to], else 0,
//   L(th)          = 1 (a round bulb) or (1 + cos(lobes (th - lobePhase))) / 2 (the sinuses)
// th is the azimuth about the axis in the base plane, (x, z) = r (cos th, sin th). The axis
// rises vertically from the orifice to bendFrom, leans (S'(0) = 0: no kink) and ends vertical, its
// steepest lean atan(1.5 offset / ((bendEnd - bendFrom) L)) halfway, L the vessel's height. The
// lean and the bulges begin above the base plate's top: the mesh's first row, from the orifice in
// the plate's underside to the plate's top, is sheared already and must not also flare or lean.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace hs::cardiac {

struct VesselShape {
  double awayX = 0, awayZ = 0;  // unit direction of the lean in the base plane
  double offset = 0;            // m: the axis's sideways shift, reached at u = bendEnd
  double bendFrom = 0, bendEnd = 0.5;  // the u range over which the axis leans
  double bulgeRadius = 0;       // m: the lumen's radius at the bulge's widest; 0: no bulge
  double bulgeFrom = 0, bulgeTo = 1;  // u range of the bulge
  int lobes = 0;                // 0: a round bulb; 3: the aortic sinuses
  double lobePhase = 0;         // rad: the azimuth of the first lobe's centre

  [[nodiscard]] bool straight() const { return offset == 0 && bulgeRadius == 0; }

  // The axis's sideways shift at u (m).
  [[nodiscard]] double shift(double u) const {
    if (offset == 0) return 0;
    const double t = std::clamp((u - bendFrom) / (bendEnd - bendFrom), 0.0, 1.0);
    return offset * t * t * (3 - 2 * t);
  }
  // The bulge's weight B(u) in [0, 1].
  [[nodiscard]] double bulge(double u) const {
    if (bulgeRadius == 0 || !(u > bulgeFrom && u < bulgeTo)) return 0;
    const double s = std::sin(std::numbers::pi * (u - bulgeFrom) / (bulgeTo - bulgeFrom));
    return s * s;
  }
  // The lumen's radius at u and azimuth theta, for an orifice of radius R (m).
  [[nodiscard]] double radius(double u, double theta, double R) const {
    const double b = bulge(u);
    if (b == 0) return R;
    const double lobe = lobes > 0 ? 0.5 * (1 + std::cos(lobes * (theta - lobePhase))) : 1.0;
    return R + (bulgeRadius - R) * b * lobe;
  }
  // The lumen's mean cross-section over the vessel's height, as a multiple of the orifice's
  // pi R^2: (1 / pi R^2) int_0^1 int_0^2pi r(u, th)^2 / 2 dth du (midpoint sums, 1 exactly for a
  // straight vessel). A vessel stretched along its height by the descending base (its vertices
  // carried by a share 1 - u of the descent) gains volume at w times this mean area.
  [[nodiscard]] double meanAreaShare(double R) const {
    if (bulgeRadius == 0) return 1;
    constexpr int kHeights = 400, kAzimuths = 360;
    double sum = 0;
    for (int i = 0; i < kHeights; ++i)
      for (int j = 0; j < kAzimuths; ++j) {
        const double r = radius((i + 0.5) / kHeights, 2 * std::numbers::pi * (j + 0.5) / kAzimuths, R) / R;
        sum += r * r;
      }
    return sum / (double(kHeights) * kAzimuths);
  }
  // The lumen's largest radius at u (m).
  [[nodiscard]] double maxRadius(double u, double R) const { return R + (std::max(bulgeRadius, R) - R) * bulge(u); }
};

}  // namespace hs::cardiac
