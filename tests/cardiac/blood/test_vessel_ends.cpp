// The vessels' ends (vessel_ends.h): the inflow's plug moves into the heart at the lumped mitral
// flow over the lumen's area plus the base's descent, and only the plug moves; the plug keeps its
// height along the vessel but not its place across it; the outflow's plug lets out the lumped
// aortic flow while the column under it is at rest density, and does not run ahead of a column
// that has not arrived (what it holds back it owes the aorta).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/blood/vessel_ends.h"

namespace hs::cardiac {
namespace {

using pbd::Real;

constexpr Real kSpacing = Real(0.0036), kH = 2 * kSpacing, kDt = Real(0.001);

FlowPath twoVessels() {
  FlowPath path;
  path.mitral = Orifice{Vec3(Real(-0.015), 0, 0), -Vec3::UnitY(), Real(0.0125)};  // blood flows down, in
  path.aortic = Orifice{Vec3(Real(0.015), 0, 0), Vec3::UnitY(), Real(0.010)};     // and up, out
  path.inflowTop = path.outflowTop = Real(0.034);
  return path;
}

BloodSettings blood() {
  BloodSettings b;
  b.spacing = kSpacing;
  b.radius = kSpacing / 2;
  b.supportRadius = kH;
  return b;
}

// Rest-density blood filling a vessel from `bottom` to a radius under `top`.
void fillColumn(pbd::Particles& p, const Orifice& lumen, Real bottom, Real top) {
  int layer = 0;
  for (Real y = bottom; y <= top - kSpacing / 2; y = bottom + Real(++layer) * kSpacing)
    for (const Vec3& x : lumenDiscSites(lumen, y, lumen.radius - kSpacing / 2, kSpacing, layer % 2 == 1))
      p.add(x, 1, pbd::ParticleKind::Fluid);
}

TEST(VesselEnds, TheInflowPlugMovesInAtTheMitralFlowAndOnlyThePlugMoves) {
  const FlowPath path = twoVessels();
  pbd::Particles p;
  fillColumn(p, path.mitral, Real(0.002), path.inflowTop);
  p.predicted = p.position;
  VesselEnds ends(path, blood());
  const double q = 300e-6, w = 0.02;  // m^3/s, m/s
  ends.setFlows(q, 0, w);
  const double area = std::numbers::pi * double(path.mitral.radius) * double(path.mitral.radius);
  EXPECT_NEAR(double(ends.inflowSpeed()), q / area + w, 1e-6 * (q / area + w));  // Real is a float
  ends.drive(p, 0, kDt);
  std::size_t plug = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 moved = p.predicted[i] - p.position[i];
    if (ends.inBuffer(p.position[i])) {
      ++plug;
      EXPECT_NEAR(double(moved.y()), -double(ends.inflowSpeed() * kDt), 1e-8) << "the plug moves down, into the heart";
      EXPECT_EQ(moved.x(), 0);
    } else {
      EXPECT_EQ(moved, Vec3::Zero()) << "below the plug the blood is the solver's";
    }
  }
  EXPECT_GT(plug, 50u);
  EXPECT_LT(plug, p.size());

  // Moved across and along the vessel by a solver, the plug comes back to its height only.
  std::vector<Vec3> points(p.predicted);
  std::vector<Index> ids(p.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = Index(i);
  for (Vec3& x : points) x += Vec3(Real(1e-4), Real(2e-4), 0);
  ends.hold(points, ids);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(double(points[i].x()), double(p.predicted[i].x() + Real(1e-4)), 1e-8);
    if (ends.inBuffer(p.position[i]))
      EXPECT_EQ(points[i].y(), p.predicted[i].y());
    else
      EXPECT_NEAR(double(points[i].y()), double(p.predicted[i].y() + Real(2e-4)), 1e-8);
  }
}

TEST(VesselEnds, TheOutflowPlugLetsOutTheAorticFlowButNeverRunsAheadOfItsColumn) {
  const FlowPath path = twoVessels();
  const double q = 400e-6;
  const double area = std::numbers::pi * double(path.aortic.radius) * double(path.aortic.radius);

  // A column at rest density up to the plug: the plug moves at the lumped speed.
  pbd::Particles full;
  fillColumn(full, path.aortic, Real(0.002), path.outflowTop);
  full.predicted = full.position;
  VesselEnds ends(path, blood());
  ends.setFlows(0, q, 0);
  ends.drive(full, 0, kDt);
  EXPECT_NEAR(double(ends.outflowSpeed()), q / area, 0.02 * q / area);
  EXPECT_NEAR(ends.outflowOwed(), 0, 0.02 * q * double(kDt));

  // Nothing under the plug yet: it stays (or follows the column down), and owes the aorta
  // what it did not let out.
  pbd::Particles onlyPlug;
  for (std::size_t i = 0; i < full.size(); ++i)
    if (ends.inBuffer(full.position[i])) onlyPlug.add(full.position[i], 1, pbd::ParticleKind::Fluid);
  onlyPlug.predicted = onlyPlug.position;
  VesselEnds waiting(path, blood());
  waiting.setFlows(0, q, 0);
  waiting.drive(onlyPlug, 0, kDt);
  EXPECT_LE(double(waiting.outflowSpeed()), 0.0);
  EXPECT_GE(waiting.outflowOwed(), q * double(kDt));
  for (std::size_t i = 0; i < onlyPlug.size(); ++i)
    EXPECT_LE(onlyPlug.predicted[i].y(), onlyPlug.position[i].y());
}

}  // namespace
}  // namespace hs::cardiac
