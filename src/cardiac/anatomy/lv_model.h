#pragma once
// Procedural left-ventricle model (thesis Fig. 5.1): a truncated prolate-ellipsoid myocardial
// shell closed at the base by a plate with a mitral (inflow) and an aortic (outflow) orifice,
// each continued by a thin-walled vessel. Coordinates: y is the long axis (apex at -y, base at
// the plane y = 0, vessels rise toward +y); the front view looks along -z, so the viewer's left
// is -x: the mitral orifice and inflow vessel sit at x < 0, blood enters from the viewer's left,
// and leaves at x > 0 through the outflow tract on the septal side (aha_segments.h).
#include <array>
#include <string>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "pbd/core/tet_mesh.h"

namespace hs::cardiac {

using pbd::Index;
using pbd::Real;
using pbd::Vec3;

// Where a vertex belongs. Myocardium vertices carry their AHA 17-segment number (1..17):
// 1-6 basal (anterior, anteroseptal, inferoseptal, inferior, inferolateral, anterolateral),
// 7-12 mid (same order), 13-16 apical (anterior, septal, inferior, lateral), 17 apex.
// Orientation (aha_segments.h): the front view's plane is the three-chamber plane, the
// anteroseptal wall toward +x beside the outflow tract, the inferolateral toward -x behind the
// mitral valve.
enum class Region : std::uint8_t {
  Myocardium = 0,  // see `segment`
  BasePlate = 1,   // the fibrous plate between the orifices
  InflowVessel = 2,
  OutflowVessel = 3,
};

// Defaults: the thesis-scale model (docs/thesis-deviations.md): sized for the thesis's blood
// (1,000 particles of radius 0.08 m) and its beating constants (0.64 m of systolic travel).
struct LvGeometryParams {
  // Endocardium: half prolate spheroid x^2/a^2 + y^2/c^2 + z^2/a^2 = 1, y <= 0.
  Real endoRadius = Real(2.0);            // a (m), short-axis radius of the cavity at the base plane
  Real endoLongAxis = Real(4.0);          // c (m), base plane to endocardial apex
  Real wallThickness = Real(0.5);         // (m) myocardium, also at the apex
  Real baseThickness = Real(0.3);        // (m) base plate
  Real mitralRadius = Real(0.75);         // (m) inflow orifice / vessel lumen radius
  Real aorticRadius = Real(0.55);         // (m) outflow orifice / vessel lumen radius (smaller than mitral)
  Real vesselWallThickness = Real(0.12);  // (m) thin vessel walls
  Real inflowVesselLength = Real(2.0);    // (m) above the base plate
  Real outflowVesselLength = Real(2.0);   // (m)
  // An anatomical heart's vessels (vessel_shape.h); 0 leaves them straight vertical tubes of the
  // orifice's radius (the thesis's model).
  Real aorticSinusRadius = 0;  // (m) lumen radius at the sinuses of Valsalva, > aorticRadius
  Real atriumRadius = 0;       // (m) lumen radius of the left atrium at its widest, > mitralRadius
  Real vesselLeanDeg = 0;      // (degrees) each vessel's steepest lean away from the other
  // The open mitral valve's leaflets (flow_path.h, valves.h): how far they hang into the cavity;
  // 0 leaves the open valve a bare disc (the thesis's model).
  Real mitralLeafletLength = 0;  // (m)
  // Resolution in [0.25, 8]: 1 gives the thesis-like model (1,100 vertices, 3,237 tets at the
  // default sizes; the thesis's has 1,061 and 3,345);
  // the element edge length is 0.21 * endoRadius / resolution, so the number of elements grows
  // roughly with resolution^2 (it is a shell one tet thick).
  Real resolution = Real(1.0);
};

// A vertex of a patient's vessel and the annulus vertex it rises from (patient_vessels.h): a
// motion that moves the annulus carries it by `share` of the annulus vertex's displacement, 1 at
// the ring and 0 at the pinned far end, as the procedural vessels descend less toward theirs.
struct VesselFollower {
  Index vertex;
  Index root;
  Real share;
};

// The mesh is a shell one tet thick: vertices come in pairs, 2i on the cavity / lumen side
// (inner layer) and 2i+1 its partner on the outer side, and every vertex lies on the surface.
struct LvModel {
  pbd::TetMesh mesh;
  std::vector<pbd::Triangle> surface;  // boundary faces, outward oriented
  std::vector<Region> region;          // per vertex
  std::vector<std::uint8_t> segment;   // per vertex: AHA segment 1..17, 0 if not myocardium
  std::vector<Index> pinned;           // vertices held fixed: the far rings of both vessels
  std::vector<VesselFollower> vesselFollowers;  // a patient's vessels below their far rings
  // The cavity: endocardial triangles (cup and base plate underside) oriented with normals
  // pointing out of the cavity (into the wall), plus the rings of the two orifices at the
  // base plate's cavity side, ordered so that a fan from the ring's centroid closes the cavity
  // with outward (+y) normals: triangle (centroid, ring[k], ring[k+1]).
  std::vector<pbd::Triangle> cavitySurface;
  std::vector<Index> mitralRing;
  std::vector<Index> aorticRing;
  Vec3 centre = Vec3::Zero();  // contraction centre: centroid of the myocardium vertices
  Real longAxisLength = 0;     // (m) base plane to epicardial apex
  FlowPath flowPath;           // the orifices, the vessels' ends, the cavity test
  LvGeometryParams params;
};

// Builds the model; throws std::invalid_argument with a one-line message for bad parameters.
LvModel buildLvModel(const LvGeometryParams& params);

// The edge length (m) the model's wall is meshed at: 0.21 endo_radius / resolution.
double nominalEdgeLength(const LvGeometryParams& params);

// Cavity volume (m^3) for the current vertex positions: cavitySurface plus a fan over each
// orifice ring, by the divergence theorem.
Real cavityVolume(const LvModel& model, const std::vector<Vec3>& positions);

// The cavity closed over both annuli: appends to `vertices` (indexed as the model's) each
// ring's centroid and returns the cavity surface with a fan over each ring (centroid, r_k,
// r_k+1), outward oriented. With the rest positions it is the endocardium closed flat; with
// others (a mid-wall surface) the same topology.
std::vector<pbd::Triangle> closedOverAnnuli(const LvModel& model, std::vector<Vec3>& vertices);

// Share of the myocardium's cavity-side vertices (inner layer, even ids) among `vertices`
// (model vertex ids, each at most once): how much of the wall they are, as the lumped
// circulation weighs contractility.
double myocardiumShare(const LvModel& model, const std::vector<Index>& vertices);

}  // namespace hs::cardiac
