#pragma once
// A tetrahedral wall from a triangle surface: the surface offset along smoothed vertex normals
// in layers, each prism between two layers cut into three tetrahedra. Knows no hearts.
//
// Conforming cut (Dompierre, Labbe, Vallet & Camarero 1999, "How to subdivide pyramids,
// prisms and hexahedra into tetrahedra", IMR): each quadrilateral side of a prism is cut by the
// diagonal through its vertex of smallest id. Two prisms sharing a side see the same four ids,
// so they cut it the same way and the tets conform; and the three diagonals of one prism can
// never run round in a cycle (the smallest id of the prism has two diagonals), so every prism
// can be cut into three tets with them.
#include <vector>

#include "mesh/surface_mesh.h"

namespace hs::pbd {

struct ExtrusionSettings {
  int layers = 2;            // prisms across the wall
  int normalSmoothing = 10;  // smoothNormals iterations for the offset directions
  // Each offset direction is turned toward the faces at its vertex until d . n_f >= this for
  // every one of them (cos 60 degrees): a prism's side never lies along its direction.
  double minFaceCosine = 0.5;
  // If a tet comes out inverted or flat, or an edge turned (minEdgeScale), the thickness at its surface
  // vertices is scaled by `shrink` and the wall rebuilt, up to `maxShrinkRounds` times (where the surface is
  // curved more sharply than the wall is thick, offsets along the normals would cross).
  double shrink = 0.8;
  int maxShrinkRounds = 30;
  // A tet is flat when 6V < flatVolume * (its longest edge)^3 (a regular tet: 0.707).
  double flatVolume = 1e-3;
  // An outermost-layer edge must keep this share of its length along its surface direction
  // (e_outer . e_0 > minEdgeScale |e_0|^2): no edge turns round or shrinks to nothing.
  double minEdgeScale = 0.2;
  // Sweeps of smart Laplacian smoothing of the layers above the surface (wall_extrusion.cpp:
  // a vertex moves across its offset direction only when its worst tet gets better).
  int smoothingSweeps = 3;
};

struct ExtrudedWall {
  TetMesh mesh;                     // vertex k * n + i is surface vertex i at layer k (0: the surface itself)
  std::size_t surfaceVertices = 0;  // n
  std::vector<Triangle> innerSurface, outerSurface;  // layer 0 (as given) and the last layer
  std::vector<double> thickness;                     // per surface vertex, after any shrinking
  std::vector<Vec3d> directions;                     // per surface vertex: the unit offset direction
  int shrunkVertices = 0;                            // surface vertices whose thickness was reduced
};

// Offsets surface vertex i to x_i + (k / layers) t_i d_i for k = 0..layers, where d_i is its
// smoothed normal (the side the triangles face: (b - a) x (c - a)) and t_i = thickness[i];
// cuts each prism by the rule above; then smooths the layers above the surface (smoothingSweeps).
// Every tet is positive (checked: std::runtime_error if
// shrinking could not make it so). Throws std::invalid_argument for sizes that do not match.
ExtrudedWall extrudeWall(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                         const std::vector<double>& thickness, const ExtrusionSettings& settings);

// The offset directions extrudeWall uses: smoothed vertex normals, each turned toward the faces
// at its vertex that it sees at a grazing angle (settings.minFaceCosine).
std::vector<Vec3d> offsetDirections(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                    const ExtrusionSettings& settings);

// The three tets of the prism (a, b, c) below (a', b', c') = (a + n, b + n, c + n), with
// (b - a) x (c - a) pointing toward the primed layer, positively oriented, cut by the
// smallest-id rule.
std::array<Tet, 3> splitPrism(const Triangle& bottom, Index layerOffset);
// The same cut for any ids: the prism (bottom) below (top), top[k] over bottom[k], with
// (b - a) x (c - a) of the bottom pointing toward the top. Conforms with every other prism cut
// by this rule over the same ids, whichever of its triangles holds the smallest id.
std::array<Tet, 3> splitPrism(const Triangle& bottom, const Triangle& top);

// Thickness per surface vertex from the distance along each direction to another surface (an
// epicardium around an endocardium): the first hit of the ray x_i + t d_i, t > 0; where the
// ray misses, the distance to the closest point of the other surface.
std::vector<double> thicknessToSurface(const std::vector<Vec3>& vertices,
                                       const std::vector<Vec3d>& directions,
                                       const std::vector<Vec3>& otherVertices,
                                       const std::vector<Triangle>& otherTriangles);

}  // namespace hs::pbd
