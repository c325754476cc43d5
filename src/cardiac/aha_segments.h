#pragma once
// AHA 17-segment classification of left-ventricle myocardium (Cerqueira et al. 2002) for the
// procedural model's frame: long axis y (base plane y = 0, apex at -y), anterior = +z,
// septum = -x, inferior = -z, lateral = +x.
#include <Eigen/Core>
#include <cstdint>

namespace hs::cardiac {

// Share of the endocardial cavity length (from the base plane) below which a point is apex
// cap (segment 17).
inline constexpr double kApexCapDepth = 0.9;

// Angle around the long axis in degrees [0, 360): 0 anterior (+z), 90 septal (-x),
// 180 inferior (-z), 270 lateral (+x).
double ahaAngleDeg(const Eigen::Vector3d& p);

// Segment 1..17 of a point on (or transmurally above) the endocardium, classified by its
// endocardial position p and the cavity length c (base plane to endocardial apex):
// depth -y/c in [0, 1/3) basal 1-6, [1/3, 2/3) mid 7-12 (60-degree sectors centred on
// anterior, anteroseptal, inferoseptal, inferior, inferolateral, anterolateral), [2/3, 0.9)
// apical 13-16 (90-degree sectors: anterior, septal, inferior, lateral), beyond: apex 17.
std::uint8_t ahaSegment(const Eigen::Vector3d& p, double cavityLength);

}  // namespace hs::cardiac
