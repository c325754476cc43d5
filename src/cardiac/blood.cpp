#include "cardiac/blood.h"

#include "cardiac/heart_sites.h"

#include <unistd.h>

#include <algorithm>
#include <memory>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hs::cardiac {
namespace {

using pbd::Real;
using pbd::Vec3;

std::string str(double value) {
  std::ostringstream s;
  s.precision(4);
  s << value;
  return s.str();
}

std::string vec(const Vec3& v) { return "[" + str(v.x()) + ", " + str(v.y()) + ", " + str(v.z()) + "]"; }

// The box [lower, upper] as 12 triangles (two per face), wound with normals pointing into
// the box, where the blood is.
std::shared_ptr<const pbd::StaticMeshCollider> boxMesh(const Vec3& lower, const Vec3& upper, Real cellSize) {
  std::vector<Vec3> v;
  for (int k = 0; k < 8; ++k)
    v.emplace_back((k & 1) ? upper.x() : lower.x(), (k & 2) ? upper.y() : lower.y(), (k & 4) ? upper.z() : lower.z());
  // Corners by bits (x, y, z); each face listed counter-clockwise seen from inside.
  const std::vector<pbd::Triangle> t = {{0, 1, 3}, {0, 3, 2},   // z = lower
                                        {4, 6, 7}, {4, 7, 5},   // z = upper
                                        {0, 4, 5}, {0, 5, 1},   // y = lower
                                        {2, 3, 7}, {2, 7, 6},   // y = upper
                                        {0, 2, 6}, {0, 6, 4},   // x = lower
                                        {1, 5, 7}, {1, 7, 3}};  // x = upper
  return std::make_shared<const pbd::StaticMeshCollider>(std::move(v), t, cellSize);
}

// Lattice sites of the LV cavity: the half prolate spheroid of the endocardium (lv_model.h,
// y <= 0) shrunk by one spacing, so that no particle starts in the wall (the mesh's flat
// triangles lie inside the smooth surface by less than that).
std::vector<Vec3> chamberLattice(const Scenario& scenario) {
  const Real d = scenario.blood.spacing;
  const Real a = scenario.geometry.endoRadius - d, c = scenario.geometry.endoLongAxis - d;
  std::vector<Vec3> x;
  if (!(a > 0 && c > 0)) return x;
  for (const Vec3& p : pbd::fluidBlock(Vec3(-a, -c, -a), Vec3(a, -d, a), d)) {
    const Real e = (p.x() / a) * (p.x() / a) + (p.y() / c) * (p.y() / c) + (p.z() / a) * (p.z() / a);
    if (e <= 1) x.push_back(p);
  }
  return x;
}

// Lattice sites of the inflow vessel's lumen (a cylinder of the mitral radius from the base
// plane y = 0 up to the vessel's far end), one spacing in from its wall, lowest first; then
// the cavity's sites from the base down, for blood the vessel cannot hold.
std::vector<Vec3> vesselLattice(const Scenario& scenario, const LvModel& model) {
  const Real d = scenario.blood.spacing;
  const LvGeometryParams& g = scenario.geometry;
  Vec3 centre = Vec3::Zero();
  for (Index v : model.mitralRing) centre += model.mesh.vertices[v];
  centre /= Real(model.mitralRing.size());
  const Real reach = g.mitralRadius - d;
  const Real top = centre.y() + g.baseThickness + g.inflowVesselLength;
  std::vector<Vec3> x;
  if (reach > 0) {
    const Vec3 lower(centre.x() - g.mitralRadius, centre.y(), centre.z() - g.mitralRadius);
    const Vec3 upper(centre.x() + g.mitralRadius, top, centre.z() + g.mitralRadius);
    for (const Vec3& p : pbd::fluidBlock(lower, upper, d)) {
      const Real dx = p.x() - centre.x(), dz = p.z() - centre.z();
      if (dx * dx + dz * dz <= reach * reach) x.push_back(p);
    }
  }
  std::stable_sort(x.begin(), x.end(), [](const Vec3& p, const Vec3& q) { return p.y() < q.y(); });
  std::vector<Vec3> cavity = chamberLattice(scenario);
  std::stable_sort(cavity.begin(), cavity.end(), [](const Vec3& p, const Vec3& q) { return p.y() > q.y(); });
  x.insert(x.end(), cavity.begin(), cavity.end());
  return x;
}

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? double(pages) * double(size) : 0.0;
}

}  // namespace

pbd::FluidSettings bloodFluidSettings(const BloodSettings& b) {
  pbd::FluidSettings f;
  f.restDensity = b.restDensity;
  f.particleMass = pbd::particleMassFor(b.restDensity, b.spacing);
  f.supportRadius = b.supportRadius;
  f.relaxation = b.relaxation * pbd::latticeGradientSum(pbd::makeSphKernels(b.supportRadius), b.spacing,
                                                         f.particleMass, b.restDensity);
  f.tensileCorrection = b.tensileCorrection;
  f.tensileK = b.tensileK;
  f.tensileN = b.tensileN;
  f.tensileDeltaQRatio = b.tensileDeltaQ;
  f.unilateralDensity = true;
  f.collisionRadius = b.particleCollision ? b.radius : Real(0);
  f.xsphViscosity = b.xsph * f.particleMass / b.restDensity;  // c = gamma m / rho0
  f.kinematicViscosity = b.viscosity / b.restDensity;         // nu = mu / rho0
  f.vorticityConfinement = b.vorticity;
  f.maxCorrection = Real(0.5) * b.spacing;  // see fluid.h; inactive in the box scenarios
  return f;
}

pbd::FluidStepSettings bloodSolverSettings(const Scenario& scenario) {
  const BloodSettings& b = scenario.blood;
  pbd::FluidStepSettings s;
  const Real dt = scenario.simulation.dt;
  s.iterations = b.iterations;
  s.fluid = bloodFluidSettings(b);
  const pbd::FluidSettings& f = s.fluid;
  s.particleRadius = b.radius;
  if (scenario.container.enabled && !scenario.container.mesh)
    s.walls = pbd::boxWalls(scenario.container.min, scenario.container.max);
  if (scenario.container.enabled && scenario.container.mesh)
    s.mesh = boxMesh(scenario.container.min, scenario.container.max, 4 * b.radius);

  // Explicit viscosity is stable for dt <= 0.125 h^2 / nu (Monaghan 2005, section 6.3).
  const double nu = double(f.kinematicViscosity);
  const double limit = 0.125 * double(b.supportRadius) * double(b.supportRadius) / std::max(nu, 1e-300);
  if (nu > 0 && double(dt) > limit)
    throw std::invalid_argument("blood.viscosity: " + str(b.viscosity) + " Pa s is too viscous for simulation.dt = " +
                                str(dt) + " s at support radius " + str(b.supportRadius) +
                                " m; expected dt <= 0.125 h^2 rho0 / mu = " + str(limit) + " s");
  if (b.particleCollision && 2 * b.radius > b.spacing * Real(1.0001))
    throw std::invalid_argument("blood.radius: with particle_collision, two radii (" + str(2 * b.radius) +
                                " m) must not exceed blood.spacing (" + str(b.spacing) +
                                " m), or the particles overlap at rest");
  return s;
}

std::size_t bloodBytesPerParticle(std::size_t neighbours) {
  // Particle state ~41 B, solver slot arrays ~130 B, grid ~40 B, neighbour lists and the
  // per-thread buffers 2 x 4 B per neighbour, the measurement's grid and lists again.
  return 256 + 12 * neighbours;
}

std::vector<Vec3> bloodStartPositions(const Scenario& scenario, const LvModel* model) {
  const BloodSettings& b = scenario.blood;
  if (b.start == BloodSettings::Start::Chamber && !scenario.heart)
    throw std::invalid_argument("blood.start: \"chamber\" needs a heart (model.enabled = true); use \"block\"");
  if ((b.start == BloodSettings::Start::Vessel || b.start == BloodSettings::Start::Heart) && (!scenario.heart || !model))
    throw std::invalid_argument(std::string("blood.start: \"") +
                                (b.start == BloodSettings::Start::Heart ? "heart" : "vessel") +
                                "\" needs a heart (model.enabled = true); use \"block\"");
  // Count the sites before making any: a tiny spacing must fail here, not in the allocator.
  double sites = 1;
  if (b.start != BloodSettings::Start::Block) {  // cavity and vessel bounding boxes, an upper bound
    const LvGeometryParams& g = model ? model->params : scenario.geometry;  // a patient's are measured
    const double a = 2 * double(g.endoRadius) / double(b.spacing);
    const double r = 2 * double(g.mitralRadius) / double(b.spacing);
    sites = a * a * double(g.endoLongAxis) / double(b.spacing) +
            r * r * double(g.baseThickness + g.inflowVesselLength) / double(b.spacing);
  } else {
    for (int a = 0; a < 3; ++a) sites *= std::floor(double(b.blockMax[a] - b.blockMin[a]) / double(b.spacing) + 1e-4);
  }
  const double wanted = b.particles > 0 ? double(b.particles) : sites;
  const double neighbours = double(pbd::latticeNeighbourCount(b.supportRadius, b.spacing));
  const double bytes = wanted * double(bloodBytesPerParticle(std::size_t(std::min(neighbours, 1e6))));
  const double memory = physicalMemoryBytes();
  if (memory > 0 && bytes > 0.8 * memory)
    throw std::invalid_argument("blood: " + str(wanted) + " particles (spacing " + str(b.spacing) + " m, " +
                                str(neighbours) + " neighbours each) need about " + str(bytes / 1e9) +
                                " GB, more than 80% of this machine's " + str(memory / 1e9) +
                                " GB; lower blood.particles or raise blood.spacing");
  if (b.start == BloodSettings::Start::Block && b.particles > 0 && sites < wanted)
    throw std::invalid_argument("blood.particles: the start block " + vec(b.blockMin) + " - " + vec(b.blockMax) +
                                " m holds " + str(sites) + " particles at spacing " + str(b.spacing) +
                                " m, expected at least " + str(wanted) + "; enlarge blood.block_max");
  if (scenario.container.enabled && b.start == BloodSettings::Start::Block) {
    const auto& c = scenario.container;
    for (int a = 0; a < 3; ++a)
      if (b.blockMin[a] < c.min[a] || b.blockMax[a] > c.max[a])
        throw std::invalid_argument("blood.block_min: the start block " + vec(b.blockMin) + " - " + vec(b.blockMax) +
                                    " m must lie inside the container " + vec(c.min) + " - " + vec(c.max) + " m");
  }
  if (b.start == BloodSettings::Start::Vessel || b.start == BloodSettings::Start::Heart) {
    std::vector<Vec3> x =
        b.start == BloodSettings::Start::Heart ? heartSites(scenario, *model) : vesselLattice(scenario, *model);
    if (b.particles > 0) {
      // With the closed loop the rest waits in the body and enters through the inflow vessel
      // (HeartSimulation); without it every particle needs a site.
      if (x.size() < std::size_t(b.particles) && !scenario.circulation.loop)
        throw std::invalid_argument("blood.particles: the inflow vessel and the chamber hold " +
                                    str(double(x.size())) + " particles at spacing " + str(b.spacing) +
                                    " m, expected at least " + str(double(b.particles)) +
                                    "; lower blood.particles or blood.spacing");
      x.resize(std::min(x.size(), std::size_t(b.particles)));  // the vessel from its bottom up, then the cavity
    }
    return x;
  }
  std::vector<Vec3> x = b.start == BloodSettings::Start::Chamber ? chamberLattice(scenario)
                                                                 : pbd::fluidBlock(b.blockMin, b.blockMax, b.spacing);
  if (b.particles > 0) {
    // With a heart and the closed loop, blood the chamber cannot hold waits in the body and
    // enters through the inflow vessel, as for "vessel" and "heart" (HeartSimulation).
    const bool restWaits = b.start == BloodSettings::Start::Chamber && model && scenario.circulation.loop;
    if (x.empty() || (x.size() < std::size_t(b.particles) && !restWaits))
      throw std::invalid_argument("blood.particles: the chamber holds " + str(double(x.size())) +
                                  " particles at spacing " + str(b.spacing) + " m, expected at least " +
                                  str(double(b.particles)) + "; lower blood.particles or blood.spacing");
    // Lowest layers first, so a partial fill is a pool at the bottom of the block.
    std::stable_sort(x.begin(), x.end(), [](const Vec3& p, const Vec3& q) { return p.y() < q.y(); });
    x.resize(std::min(x.size(), std::size_t(b.particles)));
  }
  return x;
}

BloodStats measureBlood(const pbd::Particles& particles, const pbd::FluidStats& f, const Vec3& domainMin,
                        const Vec3& domainMax) {
  BloodStats stats;
  stats.particles = f.fluidCount;
  stats.densityErrorMean = double(f.densityErrorMean);
  stats.densityErrorMax = double(f.densityErrorMax);
  stats.fullNeighbourhood = f.fullCount;
  stats.maxSpeed = double(f.maxSpeed);
  stats.meanNeighbours = double(f.meanNeighbours);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.kind[i] != pbd::ParticleKind::Fluid) continue;
    // Parked blood waits outside the model to re-enter (blood_loop.h): not lost.
    if (!particles.active(i)) continue;
    const Vec3& x = particles.position[i];
    bool out = !x.allFinite() || !particles.velocity[i].allFinite();
    for (int a = 0; a < 3 && !out; ++a) out = x[a] < domainMin[a] || x[a] > domainMax[a];
    if (out && stats.lost++ == 0) stats.firstLostAt = x;
  }
  return stats;
}

void BloodStats::save(pbd::StateWriter& w) const {
  w.fields(particles, lost, densityErrorMean, densityErrorMax, fullNeighbourhood, maxSpeed, meanNeighbours, insideWall);
}

void BloodStats::load(pbd::StateReader& r) {
  r.fields(particles, lost, densityErrorMean, densityErrorMax, fullNeighbourhood, maxSpeed, meanNeighbours, insideWall);
}

}  // namespace hs::cardiac
