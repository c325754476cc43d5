#pragma once
// A patient's left ventricle from its endocardial surface (CT/MRI segmentation), with an
// epicardium or an assumed wall thickness: the wall as tetrahedra in the procedural heart's
// frame (cardiac/anatomy/lv_model.h: metres, long axis y, base plane y = 0, apex at -y, the septum toward
// kSeptal and anterior toward kAnterior of cardiac/anatomy/aha_segments.h, so the front view, along -z,
// looks onto the three-chamber plane with the outflow tract on the right), the mitral and
// aortic annuli found among the surface's boundary loops, and the AHA segments.
//
// The steps (docs/patient-meshes.md, "From a surface to a wall"):
//  1. units: the file's unit to metres; a heart outside 3-30 cm is refused (checkHeartSize);
//  2. a closed surface loses its largest flat face (a truncated ventricle's base);
//  3. loops: 2 are the annuli (the mitral the larger cap, or as overridden); 1 is the rim of a
//     truncated ventricle, whose base is closed flat with the two orifices cut in it, placed
//     and sized as in the procedural heart (mitral toward -x, aortic toward +x);
//  4. frame: the long axis from the apex (the vertex farthest from the base along the principal
//     axis) to the base centre; the septum from the settings, else from the right ventricle
//     when the epicardium encloses both ventricles (its centroid lies off the left ventricle's
//     axis, toward the right ventricle), else between two annuli from the mitral-to-aortic
//     direction turned 45 degrees about the long axis (the aortic root lies anteroseptally,
//     between the mitral annulus and the septum, anterior of mid-septum), else (a truncated,
//     axisymmetric ventricle) the file axis most across the long axis;
//  5. the surface remeshed to the edge length (pbd::remeshIsotropic) and extruded in layers
//     (pbd::extrudeWall) by the thickness or up to an epicardium of the left ventricle alone
//     (through a biventricular one the rays would cross the right ventricle's cavity).
#include <optional>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace hs::cardiac {

using pbd::Index;
using pbd::Vec3;
using pbd::Vec3d;

enum class LengthUnit { Millimetre, Metre };
double metresPer(LengthUnit unit);
const char* unitName(LengthUnit unit);

// Throws std::invalid_argument with one line naming `file` when a heart `extent` file units
// across (its largest bounding-box extent) is outside 3-30 cm in `unit`, suggesting the other
// unit when the heart fits it.
void checkHeartSize(double extent, LengthUnit unit, const std::string& file);

struct Surface {
  std::vector<Vec3> vertices;
  std::vector<pbd::Triangle> triangles;
};

// Wall resolution: the surface's edge length and the tets across the wall.
struct WallResolution {
  double edgeLength = 0.005;  // m
  int layers = 2;
};
// "coarse" (6 mm, 1 layer: real time; at 8 mm the strip of wall between two annuli as close
// as biv-me's is one sliver wide, docs/patient-meshes.md), "default" (5 mm, 2 layers), "fine"
// (3 mm, 3 layers);
// std::invalid_argument for another name.
WallResolution wallResolution(const std::string& name);

struct PatientWallSettings {
  std::string file;  // names the input in errors
  LengthUnit units = LengthUnit::Millimetre;
  double wallThickness = 0.010;  // m, without an epicardium
  WallResolution resolution;
  // Loop numbers (1-based, in the order of pbd::boundaryLoopVertices) of the annuli; 0: found
  // by size (the mitral is the larger).
  int mitralLoop = 0, aorticLoop = 0;
  std::optional<Vec3d> septum;  // direction toward the septum, in the file's frame
  // How errors name the loop numbers and the septum: heartsim mesh's words, or a scenario's keys.
  std::string mitralLoopName = "mitral loop", aorticLoopName = "aortic loop", septumName = "the septum direction";
};

// The rigid placement: heart = rotation * (metres * file - origin).
struct HeartFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // rows: the heart's x, y, z in the file frame
  Vec3d origin = Vec3d::Zero();                            // the base centre, metres, file axes
  double metresPerUnit = 1;
  Vec3d toHeart(const Vec3d& file) const { return rotation * (metresPerUnit * file - origin); }
};

struct PatientWall {
  pbd::TetMesh mesh;                          // metres, heart frame; positive tets
  std::size_t endoVertices = 0;               // ids [0, n): the endocardium (layer 0)
  std::vector<pbd::Triangle> endocardium;     // facing out of the cavity (into the wall)
  std::vector<bool> basePlate;                // per endocardial vertex: on a flat base made here
  std::vector<Index> mitralRing, aorticRing;  // endocardial ids, in loop order
  bool baseOpened = false;                    // a truncated ventricle whose base was made here
  HeartFrame frame;
  double cavityLength = 0;  // m, base plane to the endocardial apex
  double cavityVolume = 0;  // m^3, the annuli closed by flat caps
  pbd::MeshQuality quality;
  int shrunkVertices = 0;  // where the thickness had to give way
  // "setting", "right ventricle" (a biventricular epicardium), "aortic annulus" or "file axis".
  std::string septumFrom;
  bool thicknessFromEpicardium = false;  // false: the settings' wallThickness
  std::vector<std::uint8_t> segment;     // per vertex: AHA 1..17, 0 on the base plate
};

// Builds the wall; throws std::invalid_argument with one line naming settings.file for input
// that cannot make one: size for the units; a surface that is non-manifold, inconsistently
// wound, in several pieces or holds no cavity (under 1% of its extent cubed); no or too many
// boundary loops; a base that is not flat; annulus overrides out of range. Self-intersections
// are not looked for.
PatientWall buildPatientWall(const Surface& endocardium, const Surface* epicardium,
                             const PatientWallSettings& settings);

// The regions' landmarks back in the file's frame and units: the apex (the endocardial point
// lowest along the long axis), the base centre (on the base plane, y = 0), the long axis (unit,
// base-ward; the base plane's normal) and the septum's direction (unit, across the axis).
struct VentricleLandmarks {
  Vec3d apex, baseCentre, longAxis, septum;
};
VentricleLandmarks landmarksInFile(const PatientWall& wall);

}  // namespace hs::cardiac
