#pragma once
// Turns a tetrahedral mesh into particles and constraints: a volume constraint per tet
// (thesis 4.1.1), an area constraint per surface triangle (thesis 4.1.2) and, optionally, a
// distance constraint per edge. Generic: knows nothing about hearts.
#include <vector>

#include "pbd/core/particles.h"
#include "pbd/core/solver.h"
#include "pbd/core/tet_mesh.h"

namespace hs::pbd {

struct SoftBodySettings {
  Real density = 1000;  // kg/m^3: vertex mass = density * (sum of adjacent tet volumes) / 4
  Real stiffness = 1;        // PBD stiffness k of the area and edge constraints
  Real volumeStiffness = 1;  // PBD stiffness k of the tet volume constraints
  Real volumeCompliance = 0;
  Real areaCompliance = 0;
  Real edgeCompliance = 0;
  bool edges = true;
  bool areas = true;  // area constraints on the surface triangles
};

// Appends the mesh's vertices as Tissue particles and its constraints to `constraints`.
// Returns the index of the first particle; mesh vertex v becomes particle first + v.
Index addSoftBody(Particles& particles, ConstraintSet& constraints, const TetMesh& mesh,
                  const std::vector<Triangle>& surface, const SoftBodySettings& settings);

// Builds the parallel Gauss-Seidel schedule (block_schedule.h) from the rest positions;
// call once after adding bodies.
void finalizeConstraints(ConstraintSet& constraints, const std::vector<Vec3>& positions);

}  // namespace hs::pbd
