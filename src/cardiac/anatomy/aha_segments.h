#pragma once
// AHA 17-segment classification of left-ventricle myocardium (Cerqueira et al. 2002) in the
// heart's frame: long axis y (base plane y = 0, apex at -y), and the front view's plane (x, y) the
// three-chamber plane of echocardiography, which holds the long axis, the mitral valve and the
// left ventricular outflow tract: the anteroseptal wall (60 degrees below) toward +x, beside the
// outflow tract and the aortic valve; the inferolateral wall (240 degrees) toward -x, behind the
// mitral valve. Anterior (0 degrees) is then kAnterior = (1/2, 0, -sqrt 3/2), the mid-septum (90)
// kSeptal = (sqrt 3/2, 0, 1/2), and the front view, from +z, looks at the wall from 150 degrees
// (between inferoseptal and inferior). Looking from the apex toward the base (+y), anterior turns
// to septal clockwise, as in the bull's-eye: a heart, not its mirror image.
#include <Eigen/Core>
#include <cstdint>

namespace hs::cardiac {

// Share of the endocardial cavity length (from the base plane) below which a point is apex
// cap (segment 17).
inline constexpr double kApexCapDepth = 0.9;

inline const Eigen::Vector3d kAnterior(0.5, 0, -0.8660254037844386);
inline const Eigen::Vector3d kSeptal(0.8660254037844386, 0, 0.5);

// Angle around the long axis in degrees [0, 360): 0 anterior (kAnterior), 90 septal (kSeptal),
// 180 inferior, 270 lateral: atan2(p . kSeptal, p . kAnterior).
double ahaAngleDeg(const Eigen::Vector3d& p);

// Segment 1..17 of a point on (or transmurally above) the endocardium, classified by its
// endocardial position p and the cavity length c (base plane to endocardial apex):
// depth -y/c in [0, 1/3) basal 1-6, [1/3, 2/3) mid 7-12 (60-degree sectors centred on
// anterior, anteroseptal, inferoseptal, inferior, inferolateral, anterolateral), [2/3, 0.9)
// apical 13-16 (90-degree sectors: anterior, septal, inferior, lateral), beyond: apex 17.
std::uint8_t ahaSegment(const Eigen::Vector3d& p, double cavityLength);

}  // namespace hs::cardiac
