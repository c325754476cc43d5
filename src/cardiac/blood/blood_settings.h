#pragma once
// The blood's settings ([blood] and [container] of a scenario): the particles, their solver and
// where they start.
#include "pbd/core/types.h"

namespace hs::cardiac {

using pbd::Index;
using pbd::Real;
using pbd::Vec3;

// Blood as Position Based Fluid particles (thesis 4.2, Table 5.2). Defaults: the thesis's
// values, except the particle mass, which follows from the rest density and the spacing
// (docs/thesis-deviations.md).
struct BloodSettings {
  bool enabled = false;
  // Particle count; 0 = one particle per lattice site of the start block. When > 0, the block's
  // sites are filled bottom layer first (lowest y) and the block must hold that many.
  int particles = 1000;
  Real radius = Real(0.08);         // m, kept from walls and other particles (thesis: 0.08 m)
  Real spacing = Real(0.16);        // m, lattice spacing at rest = 2 radii; mass = rho0 spacing^3
  Real supportRadius = Real(0.32);  // m, SPH kernel support h (thesis: 0.32 m)
  Real restDensity = 1000;          // kg/m^3 (thesis: 1000; blood: 1060)
  Real viscosity = Real(0.04);      // Pa s, dynamic (thesis: 0.04; blood: 0.0035)
  // gamma of thesis eq. 4.11, dimensionless XSPH smoothing: c = gamma m / rho0 (fluid.h).
  Real xsph = Real(0.5);
  int iterations = 4;               // density solver iterations per step
  // PBF eps (eq. 11) relative to sum |grad C|^2 of a particle at rest in the lattice, so the
  // same value works at any spacing.
  Real relaxation = Real(0.1);
  // Thesis eq. 4.6 between blood particles. Off by default: with 2 radii = spacing it fights the
  // density constraint (fluid-at-rest: density error 3.6% with it, 0.27% without).
  bool particleCollision = false;
  // The heart wall lends density to the blood beside it (pbd/fluid/wall_density.h): without it blood
  // packs about a fifth tighter along walls than inside, so a contracting cavity holds more
  // particles per volume at end-systole than at end-diastole.
  bool wallDensity = false;
  // How blood is kept out of the heart wall after the wall's constraints (docs/heart-blood.md):
  // Thesis: the push-out of particles found inside a tet at the end of the step (thesis eq.
  // 4.12-4.20, pbd/contact/particle_tet_collision.h) alone. Continuous: that push-out, then the swept
  // check of each particle's whole step against the moving wall surface (pbd/contact/swept_contact.h),
  // so no step, however fast, crosses a wall however thin.
  enum class WallContact { Continuous, Thesis } wallContact = WallContact::Continuous;
  bool tensileCorrection = false;   // PBF s_corr (eq. 13-14)
  Real tensileK = Real(0.1);
  int tensileN = 4;
  Real tensileDeltaQ = Real(0.2);   // deltaQ / h
  Real vorticity = 0;               // m/s, PBF eq. 16 epsilon; 0 = off
  // Where the particles start: a lattice block (blockMin..blockMax), or the heart's chamber
  // (the LV cavity, at least one spacing from its wall).
  // "heart": the cavity and both vessels full (a particle radius from their walls), for the
  // lumped circulation, which needs the heart full from the first step.
  enum class Start { Block, Chamber, Vessel, Heart } start = Start::Block;
  Vec3 blockMin = Vec3(Real(-0.8), Real(-2.4), Real(-0.8));  // m, the block the particles start in
  Vec3 blockMax = Vec3(Real(0.8), Real(-0.8), Real(0.8));
  // Particles that may leave the domain before a run fails (exit 3): 0, any loss is a failure;
  // a scenario whose blood is meant to spill says how much it expects.
  int lossAllowed = 0;
};

// A closed box the blood cannot leave (dam break, column at rest). Its walls are planes
// (thesis eq. 4.5) or, with `mesh`, the same box as a static triangle mesh.
struct ContainerSettings {
  bool enabled = false;
  Vec3 min = Vec3(-1, -1, -1);  // m
  Vec3 max = Vec3(1, 1, 1);     // m
  bool mesh = false;
};

}  // namespace hs::cardiac
