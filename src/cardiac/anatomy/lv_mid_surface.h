#pragma once
// Internal building blocks of the LV model (lv_model.cpp): a triangulated mid-surface whose
// vertices each carry an inner (blood side) and an outer position, and its extrusion into a
// shell one tetrahedron thick. Everything is in double; lv_model.cpp converts to Real.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/anatomy/vessel_shape.h"

namespace hs::cardiac::detail {

using Vec3d = Eigen::Vector3d;
using Vec2d = Eigen::Vector2d;  // (x, z) in the base plane y = 0

// Model dimensions in metres (double), derived from LvGeometryParams.
struct ShellDims {
  double a = 0;              // endocardial short-axis radius
  double c = 0;              // endocardial long axis (base plane to endocardial apex)
  double t = 0;              // wall thickness
  double baseThickness = 0;  // base plate thickness
  double vesselWall = 0;     // vessel wall thickness
  double h = 0;              // target element edge length
  double plateH = 0;         // edge length on the base plate (<= h; smaller in narrow gaps)
  struct Orifice {
    Vec2d centre = Vec2d::Zero();
    double radius = 0;
    double length = 0;  // vessel length above the base plate
    Region region = Region::InflowVessel;
    VesselShape shape;  // straight unless the heart is anatomical
  };
  Orifice mitral;
  Orifice aortic;
};

// A closed ring of mid-surface vertices with increasing azimuths in [phi0, phi0 + 2 pi);
// azimuth phi is measured in the base plane as (x, z) = r (cos phi, sin phi) about `centre`.
struct Ring {
  std::vector<Index> ids;
  std::vector<double> angles;
};

struct MidSurface {
  std::vector<Vec3d> inner;  // cavity / lumen side
  std::vector<Vec3d> outer;
  std::vector<Region> region;
  // Per vertex: rank in the vertex order that picks the prisms' quad diagonals (extrudeShell).
  std::vector<int> rank;
  std::vector<pbd::Triangle> triangles;
  std::vector<std::uint8_t> cavity;  // per triangle: 1 if its inner face bounds the cavity

  Index addVertex(const Vec3d& in, const Vec3d& out, Region r, int vertexRank);
  void addTriangle(Index a, Index b, Index c, bool bindsCavity);
};

// Triangulates the band between two coaxial rings, merging them by azimuth.
void zipRings(MidSurface& s, const Ring& lower, const Ring& upper, bool bindsCavity);

// The half-spheroid cup (apex pole, rings up to the base plane); returns its top ring.
Ring addCup(MidSurface& s, const ShellDims& d);

// A tube over an orifice, straight or shaped (vessel_shape.h); returns its bottom ring (the
// orifice edge in the base plane) and stores its far ring in `top`.
Ring addVessel(MidSurface& s, const ShellDims& d, const ShellDims::Orifice& o, Ring& top);

// The base plate between the cup's top ring (`rim`) and the two orifice rings.
void addBasePlate(MidSurface& s, const ShellDims& d, const Ring& rim, const Ring& mitral, const Ring& aortic);

// Winds every triangle so its normal points from the inner toward the outer layer.
void orientTriangles(MidSurface& s);

// Vertex ranks for the order that picks the prisms' quad diagonals (extrudeShell). A quad
// between mid-surface vertices X and Y is cut along X_inner-Y_outer when X comes first; with
// the layer shift s = outer - inner that diagonal is the shorter one when (Y - X) . s < 0, so
// the vertex further along the shift should come first. Within a rank vertices are ordered by
// decreasing key inner . s, which does that on the cup (shift down-out, up-out near the rim)
// and the plate (shift up, out toward the rim and the vessel walls). Vessels come after the
// plate (their bottom rings shift up), ranked from the top ring down.
inline constexpr int kRankCup = 0;
inline constexpr int kRankPlate = 0;
inline constexpr int kRankVesselTop = 1;  // + rows - row for vessel ring `row`

// Mid-surface vertex i becomes tet-mesh vertices 2i (inner) and 2i+1 (outer); each triangle
// becomes a prism split into three positive tets (Dompierre et al. 1999), comparing vertices by
// (rank, key, mid-surface id, layer) so shared quads are cut alike. Throws
// std::logic_error if a tet comes out inverted or nearly flat.
pbd::TetMesh extrudeShell(const MidSurface& s);

// Smallest normalised tet volume accepted by extrudeShell: 6 sqrt(2) V / L^3 with L the
// longest edge (1 for a regular tet).
inline constexpr double kMinNormalisedVolume = 1e-3;

}  // namespace hs::cardiac::detail
