#pragma once
// From a simulation to a render::Scene: the heart wall's surface at the current particle
// positions (crease-aware smooth normals, coloured by region), blood particles coloured by
// speed, the container as a wireframe box, and the speed legend drawn into a finished image.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "cardiac/blood/flow_components.h"
#include "cardiac/heart_simulation.h"
#include "render/pathlines.h"
#include "render/renderer.h"
#include "viz/image.h"

namespace hs::render {

// What the blood's colour shows: speed, pressure, where it started, its flow component in the
// beat (4D-flow MRI's, cardiac/blood/flow_components.h), or how long it has stayed.
enum class BloodColour { Speed, Pressure, Origin, Components, Stay };

// The flow view: none, short pathline streaks (pathlines.h), or arrows of the smoothed
// velocity. With either, the lines carry the speed colours and the blood is drawn pale and
// see-through behind them.
enum class FlowView { Off, Streaks, Arrows };

struct SceneOptions {
  // Cut the wall open: remove what lies at z > clipZ (anterior of the plane, toward the
  // front camera), so the cavity and the blood inside are visible.
  bool clip = false;
  float clipZ = 0;        // m
  float wallOpacity = 1;  // < 1: see-through wall
  double speedMax = 0;    // m/s at the top of the colour scale; 0: defaultSpeedScale(scenario)
  BloodColour bloodColour = BloodColour::Speed;
  double pressureMax = 0;  // mmHg at the top of the pressure scale; 0: defaultPressureScale(scenario)
  BloodLook bloodLook = BloodLook::Liquid;
  int liquidDownsample = 1;  // the liquid look at 1/n of the screen's resolution (the viewer's speed)
  FlowView flow = FlowView::Off;
  // The streaks' trajectories (flow = Streaks); none: no streaks are drawn.
  const PathlineRecorder* pathlines = nullptr;
  float flowLineWidth = 2;  // pixels at a streak's head or an arrow's shaft
  bool valves = true;       // the valves' leaflets (valve_leaflets.h), with a heart
  // The beating region drawn in beatingColour (thesis 4.3.3, Fig. 4.7): per model vertex,
  // nonzero = tinted. Unset: the region the scenario chose (cycle.segments, vertices or
  // sphere) while its cycle is on; a scenario where the whole myocardium beats singles nothing
  // out, so its pictures look as they always did. The viewer passes its live selection.
  std::optional<std::vector<std::uint8_t>> beating;
  // The segments the inconsistent pattern beats out of step drawn in outOfStepColour.
  bool markOutOfStep = true;
  // Components and Stay: per blood particle by identity (id - firstBloodParticle), from the
  // run's VentricleBlood; none (or a size that does not match) draws every particle neutral.
  const std::vector<cardiac::FlowComponent>* components = nullptr;
  const std::vector<cardiac::Stay>* stays = nullptr;
  // < 1: the blood drawn see-through over the wall (the viewer while a region is chosen, so
  // the region on the far wall shows through the blood in front of it).
  float bloodOpacity = 1;
};

// Region colours (linear RGB in [0, 1]): myocardium red-pink, base plate and vessels lighter.
Vec3f regionColour(cardiac::Region region);
// A beating vertex's colour: the wall's colour turned orange, distinct from the red
// myocardium at rest and from the pale vessels.
Vec3f beatingColour(const Vec3f& base);
// A vertex that beats out of step (the inconsistent pattern): the wall's colour turned violet.
Vec3f outOfStepColour(const Vec3f& base);
// Per model vertex, 1 = in a segment the inconsistent pattern beats out of step; empty for the
// other patterns, without a heart or with the cycle off.
std::vector<std::uint8_t> outOfStepRegion(const cardiac::HeartSimulation& sim);
// Per model vertex, 1 = in the region the scenario chose to beat; empty when it chose none
// (the whole myocardium beats), has no heart, or its cycle is off.
std::vector<std::uint8_t> chosenBeatingRegion(const cardiac::HeartSimulation& sim);
// Slow (blue) to fast (yellow) through cyan and green; fraction is clamped to [0, 1].
Vec3f speedColour(double fraction);
viz::Rgb toRgb(const Vec3f& colour);

// The speed at the top of the colour scale when none is given: the free-fall speed
// sqrt(2 g H) over the height H of the blood's start block, rounded up to 1, 1.5, 2, 3, 4, 5,
// 6 or 8 times a power of ten; blood cannot go much faster than that.
double defaultSpeedScale(const cardiac::Scenario& scenario);

// The pressure (mmHg) at the top of the colour scale when none is given: four times the
// hydrostatic pressure over the same height as defaultSpeedScale (rho0 g H), in mmHg, rounded
// up the same way. Systolic pressures above it are drawn at the top colour.
double defaultPressureScale(const cardiac::Scenario& scenario);
// Origin colours: blood that started in the inflow vessel (blue), in the ventricle (violet),
// or outside the model, entering through the loop (green).
Vec3f originColour(cardiac::FlowRegion origin);

// The 4D-flow papers' colours (Bolger et al. 2007; Eriksson et al. 2010): direct flow green,
// retained inflow blue, delayed ejection yellow, residual volume red; blood that was not in the
// ventricle at end-diastole light grey.
Vec3f componentColour(cardiac::FlowComponent component);
// Blood that has stayed more than three beats dark red, the rest of the ventricle's pale blue,
// blood outside it light grey.
Vec3f stayColour(cardiac::Stay stay);

// The top of the blood's colour scale for options.bloodColour: speedMax (m/s) or pressureMax
// (mmHg), or the scenario's default where it is 0; 0 for origin colours, which have no scale.
double colourScaleMax(const SceneOptions& options, const cardiac::Scenario& scenario);

// What the cameras frame: the wall's rest shape (so every time is seen from the same place)
// and the container, or the blood's start block when there is neither.
Box sceneBounds(const cardiac::HeartSimulation& sim);

Scene buildScene(const cardiac::HeartSimulation& sim, const SceneOptions& options);

// The identities (id - firstBloodParticle) of the blood particles buildScene draws, in its
// order; and a built scene's blood coloured by component from them, for a picture whose
// colours are known only later (`heartsim render` colours the blood at a time by the
// component it ends up in when that beat's systole is over).
std::vector<std::size_t> drawnBloodIdentities(const cardiac::HeartSimulation& sim);
void colourByComponent(Scene& scene, std::span<const std::size_t> identities,
                       std::span<const cardiac::FlowComponent> components);

// Sets the cut and the wall's opacity for one view. The cut is made only in views that look
// at the cutting plane (front, for z = const): in the others it would be seen edge-on and
// only halve the heart, so they show the whole wall, see-through (opacity at most 0.45) when
// there is blood to see inside.
void applyView(Scene& scene, const SceneOptions& options, View view);

// What each blood colour mode is called ("speed", "pressure", "origin"), and back; nullopt
// for an unknown name. The same for looks ("liquid", "spheres") and flow views ("off",
// "streaks", "arrows").
const char* bloodColourName(BloodColour colour);
std::optional<BloodColour> parseBloodColour(std::string_view name);
const char* bloodLookName(BloodLook look);
std::optional<BloodLook> parseBloodLook(std::string_view name);
const char* flowViewName(FlowView flow);
std::optional<FlowView> parseFlowView(std::string_view name);

// Under speed colours, the blood in the vessels' far-end buffers (HeartSimulation::
// bloodInVesselEnd): the lumped model's boundary, whose speed is what the lumped flows (and the
// outflow's repayment of what it fell behind) impose, not the blood's own flow. Grey.
inline const Vec3f kVesselEndColour(0.62f, 0.62f, 0.64f);

// The pale colour of the blood behind the flow lines, and its opacity.
inline const Vec3f kFlowBackdropColour(0.93f, 0.80f, 0.80f);
inline constexpr float kFlowBackdropOpacity = 0.35f;

// Segments of the flow lines coloured by speed on the scale [0, speedMax]: streaks from the
// recorder (tapering from `width` pixels at the head to a third of it at the tail), or an arrow
// per `stride`-th blood particle along its smoothed velocity, as long as the distance it covers
// in 10 ms.
void addStreaks(FlowLines& lines, const PathlineRecorder& pathlines, double speedMax, float width);
void addArrows(FlowLines& lines, const std::vector<Vec3f>& positions, const std::vector<Vec3f>& velocities,
               double speedMax, float width, int stride = 3);

// The components a key lists, in order, with what each means and its colour in words.
struct ComponentKeyRow {
  cardiac::FlowComponent component;
  const char* label;
  const char* colourName;
  const char* shortLabel;  // the component's name alone, for the viewer's narrow key
};
std::span<const ComponentKeyRow> componentKey();
struct StayKeyRow {
  cardiac::Stay stay;
  const char* label;
  const char* colourName;
};
std::span<const StayKeyRow> stayKey();
// The rule the live colours follow, for the keys' tooltips and footers.
inline constexpr const char* kComponentRule =
    "from each end-diastole on, the blood then in the ventricle is new (entered in that diastole) or "
    "earlier, and turns direct or delayed ejection once it leaves; the colours hold until the next "
    "end-diastole";

// The origins a key lists, in order, with what each means.
struct OriginKeyRow {
  cardiac::FlowRegion origin;
  const char* label;
  const char* colourName;  // originColour's, in words
};
std::span<const OriginKeyRow> originKey();

// The blood's colour key in the image's lower right corner, text scaled with the image: a bar
// "blood speed (m/s)" or "blood pressure (mmHg)" from 0 to scaleMax, or the origin, component or
// stay key.
[[nodiscard]] viz::Rect drawBloodLegend(viz::Image& image, BloodColour colour, double scaleMax);

}  // namespace hs::render
