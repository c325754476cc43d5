#include "cardiac/blood/filling_vortex.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hs::cardiac {

LongAxisCut longAxisCut(const LvModel& model, const FlowPath& path, std::span<const pbd::Vec3> positions) {
  LongAxisCut cut;
  cut.mitralCentre = path.mitral.centre.cast<double>();
  cut.mitralRadius = double(path.mitral.radius);
  cut.leafletLength = double(path.mitralLeafletLength);
  // The model's y axis is the long axis (lv_model.h; a patient's wall is placed so, too).
  cut.down = -Vec3d::UnitY();
  const Vec3d origin = path.apexAxisOrigin.cast<double>();
  cut.axisAtMitralPlane = Vec3d(origin.x(), cut.mitralCentre.y(), origin.z());
  const Vec3d toAxis = cut.axisAtMitralPlane - cut.mitralCentre;
  // A mitral orifice on the axis leaves the cut free to turn about it: the front view's plane.
  cut.across = toAxis.norm() > 1e-6 ? Vec3d(toAxis.normalized()) : Vec3d::UnitX();
  for (const pbd::Triangle& t : model.cavitySurface)
    for (const pbd::Index v : t) cut.longAxis = std::max(cut.longAxis, cut.depth(positions[v].cast<double>()));
  return cut;
}

pbd::PlaneGrid longAxisGrid(const LongAxisCut& cut, const LvModel& model, std::span<const pbd::Vec3> positions,
                            double nodeSpacing) {
  // The cavity's extent across the axis, within the cut's frame: the cavity surface's vertices
  // projected on `across` (the cavity is nearly round about its axis, so its widest vertex
  // anywhere bounds the cut's width).
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const pbd::Triangle& t : model.cavitySurface)
    for (const pbd::Index v : t) {
      const double a = cut.across.dot(positions[v].cast<double>() - cut.mitralCentre);
      lo = std::min(lo, a), hi = std::max(hi, a);
    }
  constexpr int kAbove = 4;  // nodes above the mitral plane: the jet entering through the orifice
  pbd::PlaneGrid g;
  g.spacing = nodeSpacing;
  g.u = cut.across;
  g.v = cut.down;
  g.origin = cut.mitralCentre + (lo - nodeSpacing) * cut.across - kAbove * nodeSpacing * cut.down;
  g.columns = int(std::ceil((hi - lo) / nodeSpacing)) + 3;
  g.rows = int(std::ceil(cut.longAxis / nodeSpacing)) + kAbove + 2;
  return g;
}

EVortexView readEVortex(const LongAxisCut& cut, pbd::PlaneField field, double time, double mitralFlow) {
  EVortexView view;
  view.cut = cut;
  view.omega = pbd::planeVorticity(field);
  // Cores that swirl (the plane's lambda-2, vortex_cores.h): the jet's shear layers, whose
  // vorticity is as strong, are not the ring.
  const std::vector<double> swirl = pbd::planeSwirl(field);
  view.cores = pbd::findVortexCores(field.grid, view.omega, kVortexMinPeak, &swirl);
  view.field = std::move(field);
  EVortexSample& s = view.sample;
  s.time = time;
  s.mitralFlow = mitralFlow;
  s.longAxis = cut.longAxis;
  // The ring's two cores: the strongest circulation of each sign whose centre lies below the
  // mitral plane (cores are sorted by |Gamma|).
  for (int k = 0; k < int(view.cores.size()); ++k) {
    const pbd::VortexCore& c = view.cores[std::size_t(k)];
    const int sign = c.circulation > 0 ? 0 : 1;
    if (view.ring[std::size_t(sign)] < 0 && cut.depth(c.position) > 0) view.ring[std::size_t(sign)] = k;
  }
  // A ring cut through its axis shows two equal cores; a partner with less than kPartnerShare of
  // the other's circulation is an eddy of the particle noise elsewhere in the cavity, not the
  // ring's other side: the ring is read from the stronger core alone.
  if (view.ring[0] >= 0 && view.ring[1] >= 0) {
    const double g0 = std::abs(view.cores[std::size_t(view.ring[0])].circulation);
    const double g1 = std::abs(view.cores[std::size_t(view.ring[1])].circulation);
    if (std::min(g0, g1) < kPartnerShare * std::max(g0, g1)) view.ring[g0 < g1 ? 0 : 1] = -1;
  }
  int found = 0;
  for (int sign = 0; sign < 2; ++sign) {
    if (view.ring[std::size_t(sign)] < 0) continue;
    const pbd::VortexCore& c = view.cores[std::size_t(view.ring[std::size_t(sign)])];
    s.coreDepth[std::size_t(sign)] = cut.depth(c.position);
    s.coreCirculation[std::size_t(sign)] = std::abs(c.circulation);
    s.depth += s.coreDepth[std::size_t(sign)];
    s.circulation += s.coreCirculation[std::size_t(sign)];
    ++found;
  }
  s.found = found > 0;
  if (s.found) {
    s.depth /= found;
    s.circulation /= found;
    s.position = cut.longAxis > 0 ? s.depth / cut.longAxis : 0.0;
  }
  return view;
}

bool FillingVortex::step(bool earlyFilling, double mitralFlow) {
  if (!earlyFilling) {
    if (m_open) {
      m_beats.push_back({m_count, m_complete, m_best.value_or(EVortexSample{})});
      m_lastView = std::move(m_view);
      m_view.reset();
      m_open = false;
    }
    m_seenOutside = true;
    return false;
  }
  if (!m_open) {
    m_open = true;
    ++m_count;
    m_complete = m_seenOutside;
    m_peakFlow = -std::numeric_limits<double>::infinity();
    m_best.reset();
    m_view.reset();
  }
  if (!(mitralFlow > m_peakFlow)) return false;
  m_peakFlow = mitralFlow;
  return true;
}

void FillingVortex::keep(EVortexView view) {
  m_best = view.sample;
  m_view = std::move(view);
}

void EVortexSample::save(pbd::StateWriter& w) const {
  w.fields(time, mitralFlow, found, position, depth, longAxis, circulation, coreDepth, coreCirculation);
}

void EVortexSample::load(pbd::StateReader& r) {
  r.fields(time, mitralFlow, found, position, depth, longAxis, circulation, coreDepth, coreCirculation);
}

void EVortexBeat::save(pbd::StateWriter& w) const { w.fields(beat, complete, sample); }

void EVortexBeat::load(pbd::StateReader& r) { r.fields(beat, complete, sample); }

void FillingVortex::save(pbd::StateWriter& w) const {
  w.fields(m_open, m_seenOutside, m_complete, m_count, m_peakFlow, m_best, m_beats);
}

void FillingVortex::load(pbd::StateReader& r) {
  r.fields(m_open, m_seenOutside, m_complete, m_count, m_peakFlow, m_best, m_beats);
  m_view.reset();
  m_lastView.reset();
}

}  // namespace hs::cardiac
