#include "render/valve_leaflets.h"

#include <cmath>
#include <numbers>

#include "cardiac/circulation.h"

namespace hs::render {
namespace {

constexpr int kArcSteps = 12, kRadialSteps = 4;
constexpr float kCommissureGapRadians = 0.04f;  // leaves a visible seam between leaflets
constexpr float kThicknessRadii = 0.05f;        // slab thickness, in annulus radii
constexpr float kDomeRadii = 0.15f;             // a closed leaflet's bulge upstream

void addTriangle(WallMesh& mesh, Vec3f a, Vec3f b, Vec3f c, const Vec3f& outward) {
  Vec3f n = (b - a).cross(c - a);
  if (n.dot(outward) < 0) std::swap(b, c), n = -n;  // counter-clockwise seen from outside
  n = n.squaredNorm() > 0 ? n.normalized() : outward;
  for (const Vec3f& p : {a, b, c}) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(n);
    mesh.colours.push_back(kLeafletColour);
  }
}

}  // namespace

void addLeaflets(const ValveShape& valve, WallMesh& mesh) {
  const Vec3f f = valve.axis.normalized();
  const Vec3f e1 = (valve.first - valve.first.dot(f) * f).normalized();
  const Vec3f e2 = f.cross(e1);
  const float R = valve.radius;
  // Closed, a leaflet spans the annulus's radius; open, its own length.
  const float L = valve.open && valve.length > 0 ? valve.length : R;
  const float phi = valve.open ? valve.openAngleDegrees * std::numbers::pi_v<float> / 180 : 0.0f;
  const float sector = 2 * std::numbers::pi_v<float> / float(valve.leaflets);
  // A point of a leaflet: theta along the annulus, s from the hinge (0) to the free edge (1).
  // The radial line at theta turns about its hinge from pointing inward (closed) toward the
  // axis (open); closed, it bulges upstream by kDomeRadii at mid-length.
  auto point = [&](float theta, float s) {
    const Vec3f u = std::cos(theta) * e1 + std::sin(theta) * e2;
    const Vec3f hinge = valve.centre + R * u;
    const Vec3f along = std::cos(phi) * -u + std::sin(phi) * f;
    const float dome = valve.open ? 0.0f : -kDomeRadii * R * 4 * s * (1 - s);
    return Vec3f(hinge + L * s * along + dome * f);
  };
  for (int leaflet = 0; leaflet < valve.leaflets; ++leaflet) {
    const float t0 = (float(leaflet) - 0.5f) * sector + kCommissureGapRadians / 2;
    const float t1 = (float(leaflet) + 0.5f) * sector - kCommissureGapRadians / 2;
    // The slab's faces: the downstream one offset along +normal, the upstream one along -normal.
    for (const float side : {1.0f, -1.0f}) {
      for (int i = 0; i < kArcSteps; ++i)
        for (int j = 0; j < kRadialSteps; ++j) {
          const float a0 = t0 + (t1 - t0) * float(i) / kArcSteps, a1 = t0 + (t1 - t0) * float(i + 1) / kArcSteps;
          const float s0 = float(j) / kRadialSteps, s1 = float(j + 1) / kRadialSteps;
          Vec3f p00 = point(a0, s0), p10 = point(a1, s0), p01 = point(a0, s1), p11 = point(a1, s1);
          // The surface's normal here (the upstream side's is its opposite).
          Vec3f n = (p10 - p00 + p11 - p01).cross(p01 - p00 + p11 - p10);
          if (n.dot(f) < 0) n = -n;
          n = n.squaredNorm() > 0 ? Vec3f(side * n.normalized()) : Vec3f(side * f);
          const Vec3f offset = n * (kThicknessRadii * R / 2);
          p00 += offset, p10 += offset, p01 += offset, p11 += offset;
          addTriangle(mesh, p00, p10, p11, n);
          addTriangle(mesh, p00, p11, p01, n);
        }
    }
  }
}

void addValveLeaflets(const cardiac::HeartSimulation& sim, WallMesh& mesh) {
  if (!sim.hasHeart()) return;
  const cardiac::LvModel& model = sim.model();
  const std::vector<pbd::Vec3>& x = sim.particles().position;
  const cardiac::ValveStates states = sim.circulation()
                                          ? sim.circulation()->valves.states()
                                          : cardiac::timedValves(sim.scenario().cycle.enabled, sim.lastPhase());
  // The annulus as it is now: the ring's centroid and mean distance from it.
  auto annulus = [&](const std::vector<cardiac::Index>& ring, ValveShape& valve) {
    pbd::Vec3 sum = pbd::Vec3::Zero();
    for (const cardiac::Index v : ring) sum += x[v];
    const pbd::Vec3 centre = sum / pbd::Real(ring.size());
    double radius = 0;
    for (const cardiac::Index v : ring) radius += double((x[v] - centre).norm());
    valve.centre = centre.cast<float>();
    valve.radius = float(radius / double(ring.size()));
  };
  if (model.mitralRing.empty() || model.aorticRing.empty()) return;
  ValveShape mitral, aortic;
  annulus(model.mitralRing, mitral);
  annulus(model.aorticRing, aortic);
  mitral.axis = model.flowPath.mitralValve().forward.cast<float>();
  aortic.axis = model.flowPath.aorticValve().forward.cast<float>();
  // The anterior mitral leaflet faces the aortic valve (the aorto-mitral continuity); the
  // aortic cusps are placed from the direction of the mitral valve.
  mitral.first = aortic.centre - mitral.centre;
  aortic.first = mitral.centre - aortic.centre;
  mitral.leaflets = 2, aortic.leaflets = 3;
  mitral.open = states.mitralOpen, aortic.open = states.aorticOpen;
  if (const float hanging = float(model.flowPath.mitralLeafletLength); hanging > 0)
    mitral.length = hanging, mitral.openAngleDegrees = 90;
  addLeaflets(mitral, mesh);
  addLeaflets(aortic, mesh);
}

}  // namespace hs::render
