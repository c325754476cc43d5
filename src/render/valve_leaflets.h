#pragma once
// The valves drawn as leaflets, kinematic (no mechanics): the mitral valve's two leaflets and
// the aortic valve's three cusps, hinged on their annulus as it is now (the centroid and mean
// radius of the model's orifice ring, at the current positions) and opening and closing with
// the valves' state in the simulation (the circulation's valves; without blood, the phase's
// timing). Closed, each leaflet lies across the orifice, the leaflets meeting at its centre
// (slightly domed back toward where the blood pushes them from); open, each is swung
// downstream about its hinge by kOpenAngleDegrees, so the valve becomes a funnel the blood
// passes through. A mitral valve whose leaflets the blood meets (model.mitral_leaflet_length,
// cardiac/circulation/valves.h) is drawn as the blood meets them: open, they hang straight down
// that far, a tube of the annulus's radius. Leaflets are thin slabs (both faces lit), split
// between commissures.
#include "cardiac/heart_simulation.h"
#include "render/renderer.h"

namespace hs::render {

inline constexpr float kOpenAngleDegrees = 70;
// Pale yellow-white, the colour of valve tissue, apart from the wall's reds and the vessels'
// and plate's pale pinks and creams.
inline const Vec3f kLeafletColour(0.98f, 0.94f, 0.60f);

// One valve's leaflets: the annulus (centre, radius, unit axis pointing downstream, a unit
// direction in its plane where the first leaflet is centred), how many leaflets, open or not.
struct ValveShape {
  Vec3f centre = Vec3f::Zero(), axis = Vec3f::UnitY(), first = Vec3f::UnitX();
  float radius = 0;
  int leaflets = 2;
  bool open = false;
  float length = 0;                         // hinge to free edge; 0: the annulus's radius
  float openAngleDegrees = kOpenAngleDegrees;  // open, from the annulus's plane
};

// Adds the valve's leaflets to `mesh` as triangles (positions, normals, colours).
void addLeaflets(const ValveShape& valve, WallMesh& mesh);

// Both valves of the simulation's heart; nothing without a heart.
void addValveLeaflets(const cardiac::HeartSimulation& sim, WallMesh& mesh);

}  // namespace hs::render
