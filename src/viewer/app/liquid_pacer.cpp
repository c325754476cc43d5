#include "viewer/app/liquid_pacer.h"

#include <algorithm>
#include <cstdio>

namespace hs::viewer {
namespace {

const char* resolutionName(int downsample) {
  switch (downsample) {
    case 1: return "full";
    case 2: return "1/2";
    default: return "1/3";
  }
}

}  // namespace

void LiquidPacer::observe(double ms, bool liquid) {
  if (!liquid) {
    m_window.clear();  // the spheres' times say nothing about the liquid's
    return;
  }
  if (++m_seen <= kSkipFrames) return;
  m_window.push_back(ms);
  if (int(m_window.size()) < kWindow) return;
  std::nth_element(m_window.begin(), m_window.begin() + kWindow / 2, m_window.end());
  const double median = m_window[std::size_t(kWindow / 2)];
  m_window.clear();
  char text[160];
  const bool lowered = median > kTargetMs && m_downsample < kCoarsest;
  if (lowered) {
    std::snprintf(text, sizeof text, "%.0f ms a frame at %s", median, resolutionName(m_downsample));
    m_reason = text;
    ++m_downsample;
  }
  std::snprintf(text, sizeof text, "liquid look: %s resolution", resolutionName(m_downsample));
  m_note = text;
  if (!m_reason.empty()) m_note += " for 25 fps (" + m_reason + ")";
  if (lowered) return;  // this window's frames were drawn at the finer resolution
  std::snprintf(text, sizeof text, "; now %.0f ms", median);
  m_note += text;
}

}  // namespace hs::viewer
