// Region painting through the viewer's selection code: for a known camera (the front view of
// the default heart-only model) and a brush at the projection of a chosen vertex, the brush
// picks that vertex and exactly the candidate vertices whose projections lie within the
// radius (cross-checked against a brute-force projection with render::Camera::project), with
// occlusion only what the camera sees, and nothing off the heart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "render/scene.h"
#include "viewer/region/beating_selection.h"
#include "viewer/region/brush_selection.h"

namespace hs::viewer {
namespace {

using render::Vec3f;

constexpr int kWidth = 800, kHeight = 600;

class BrushSelection : public ::testing::Test {
 protected:
  void SetUp() override {
    cardiac::Scenario scenario;  // heart-only, thesis scale
    m_sim = std::make_unique<cardiac::HeartSimulation>(scenario, 1);
    const auto& model = m_sim->model();
    for (std::size_t v = 0; v < model.mesh.vertices.size(); ++v)
      m_positions.push_back(m_sim->particles().position[v].cast<float>());
    m_candidate = BeatingSelection(model, {}).selectable();
    m_camera = render::viewCamera(render::View::Front, render::sceneBounds(*m_sim), float(kWidth) / kHeight);
  }

  BrushSurface surface(bool occlusion) const {
    return {&m_positions, &m_candidate, occlusion ? &m_sim->model().surface : nullptr};
  }

  BrushQuery query(const Vec3f& at, float radius) const {
    BrushQuery q;
    q.view = brushView(m_camera, kWidth, kHeight);
    const Vec3f s = m_camera.project(at, kWidth, kHeight);
    q.centreX = s.x();
    q.centreY = s.y();
    q.radius = radius;
    return q;
  }

  // Every candidate whose projection lies within the radius (+ slack, pixels) of the brush centre.
  std::vector<std::uint32_t> bruteForce(const BrushQuery& q, float slack = 0) const {
    std::vector<std::uint32_t> ids;
    for (std::size_t v = 0; v < m_positions.size(); ++v) {
      if (!m_candidate[v]) continue;
      const Vec3f s = m_camera.project(m_positions[v], kWidth, kHeight);
      if (s.z() < 0 || s.z() > 1) continue;
      const float dx = s.x() - q.centreX, dy = s.y() - q.centreY;
      const float r = q.radius + slack;
      if (dx * dx + dy * dy <= r * r) ids.push_back(std::uint32_t(v));
    }
    return ids;
  }

  // The myocardium vertex nearest to a point, on the outside (odd ids) or the cavity side.
  std::uint32_t nearestWallVertex(const Vec3f& point, bool outside) const {
    std::uint32_t best = 0;
    float bestDistance = INFINITY;
    for (std::size_t v = 0; v < m_positions.size(); ++v) {
      if (!m_candidate[v] || (v % 2 == 1) != outside) continue;
      const float d = (m_positions[v] - point).norm();
      if (d < bestDistance) bestDistance = d, best = std::uint32_t(v);
    }
    return best;
  }

  std::unique_ptr<cardiac::HeartSimulation> m_sim;
  std::vector<Vec3f> m_positions;
  std::vector<std::uint8_t> m_candidate;
  render::Camera m_camera;
};

bool contains(const std::vector<std::uint32_t>& ids, std::uint32_t v) {
  return std::find(ids.begin(), ids.end(), v) != ids.end();
}

TEST_F(BrushSelection, PicksExactlyTheVerticesWhoseProjectionsAreWithinTheRadius) {
  // The anterior wall's outside halfway down, facing the front camera.
  const std::uint32_t chosen = nearestWallVertex({0, -2.0f, 3.0f}, true);
  for (const float radius : {4.0f, 25.0f, 60.0f}) {
    SCOPED_TRACE("radius " + std::to_string(radius));
    const BrushQuery q = query(m_positions[chosen], radius);
    const std::vector<std::uint32_t> picked = verticesInBrush(surface(false), q);
    EXPECT_TRUE(contains(picked, chosen));
    // The same set; the two projections may round differently by far less than 0.01 pixel, so
    // a vertex that close to the rim may go either way.
    const std::vector<std::uint32_t> inner = bruteForce(q, -0.01f), outer = bruteForce(q, 0.01f);
    EXPECT_TRUE(std::includes(picked.begin(), picked.end(), inner.begin(), inner.end()));
    EXPECT_TRUE(std::includes(outer.begin(), outer.end(), picked.begin(), picked.end()));
  }
  EXPECT_GT(verticesInBrush(surface(false), query(m_positions[chosen], 60)).size(), 20u);
}

TEST_F(BrushSelection, PicksOnlyTheWallTheCameraSees) {
  const std::uint32_t chosen = nearestWallVertex({0, -2.0f, 3.0f}, true);
  const BrushQuery q = query(m_positions[chosen], 60);
  const std::vector<std::uint32_t> all = bruteForce(q);
  const std::vector<std::uint32_t> picked = verticesInBrush(surface(true), q);
  EXPECT_TRUE(contains(picked, chosen));
  EXPECT_FALSE(contains(picked, chosen ^ 1u)) << "its partner on the cavity side is hidden";
  // Behind the anterior wall the brush also covers the cavity side and the posterior wall...
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](std::uint32_t v) { return m_positions[v].z() < 0; }));
  // ...but only the anterior outside is seen: a subset of the brute force, all outside (odd
  // ids) and in front (z > 0).
  EXPECT_GT(picked.size(), 5u);
  for (const std::uint32_t v : picked) {
    EXPECT_TRUE(contains(all, v));
    EXPECT_EQ(v % 2, 1u) << "vertex " << v << " lies on the cavity side";
    EXPECT_GT(m_positions[v].z(), 0) << "vertex " << v << " lies on the posterior wall";
  }
}

TEST_F(BrushSelection, TheCutOpensTheWallToTheCavitySideBehind) {
  // The clipping plane z = 0 removes the anterior half: the front camera looks onto the
  // cavity side of the posterior wall.
  const std::uint32_t chosen = nearestWallVertex({0, -2.0f, -2.0f}, false);
  ASSERT_LT(m_positions[chosen].z(), -1);
  BrushQuery q = query(m_positions[chosen], 30);
  const std::vector<std::uint32_t> hidden = verticesInBrush(surface(true), q);
  EXPECT_FALSE(contains(hidden, chosen)) << "without the cut the anterior wall hides it";
  q.clip.enabled = true;
  q.clip.normal = Vec3f(0, 0, 1);
  q.clip.offset = 0;
  const std::vector<std::uint32_t> picked = verticesInBrush(surface(true), q);
  EXPECT_TRUE(contains(picked, chosen));
  EXPECT_FALSE(contains(picked, chosen ^ 1u)) << "its partner on the outside is hidden";
  for (const std::uint32_t v : picked) {
    EXPECT_LE(m_positions[v].z(), 0) << "vertex " << v << " was cut away";
    EXPECT_EQ(v % 2, 0u) << "vertex " << v << " lies on the outside";
  }
}

TEST_F(BrushSelection, NothingWhenTheBrushIsOffTheHeart) {
  BrushQuery q = query(Vec3f::Zero(), 30);
  q.centreX = 20;
  q.centreY = 20;
  EXPECT_TRUE(verticesInBrush(surface(true), q).empty());
  EXPECT_TRUE(verticesInBrush(surface(false), q).empty());
  // On the top of the outflow vessel: pinned, not myocardium.
  const std::uint32_t pinned = m_sim->model().pinned.back();
  EXPECT_TRUE(verticesInBrush(surface(false), query(m_positions[pinned], 10)).empty());
  // Zero radius picks nothing either.
  EXPECT_TRUE(verticesInBrush(surface(false), query(m_positions[1], 0)).empty());
}

TEST_F(BrushSelection, ProjectionMatchesTheRenderersCamera) {
  const BrushView view = brushView(m_camera, kWidth, kHeight);
  for (std::size_t v = 0; v < m_positions.size(); v += 37) {
    float x = 0, y = 0;
    ASSERT_TRUE(projectToScreen(view, m_positions[v], x, y));
    const Vec3f s = m_camera.project(m_positions[v], kWidth, kHeight);
    EXPECT_NEAR(x, s.x(), 1e-2f);
    EXPECT_NEAR(y, s.y(), 1e-2f);
  }
  float x = 0, y = 0;
  EXPECT_FALSE(projectToScreen(view, m_camera.eye + (m_camera.eye - m_camera.target), x, y))
      << "behind the eye";
}

}  // namespace
}  // namespace hs::viewer
