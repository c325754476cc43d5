#pragma once
// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#include <unistd.h>

#include <cstdio>

namespace hs::app {

class ProgressBar {
 public:
  explicit ProgressBar(long total) : m_total(total), m_enabled(isatty(STDERR_FILENO) != 0) {}
  ~ProgressBar() { finish(); }

  void update(long done, double simTime) {
    if (!m_enabled || m_total <= 0) return;
    const int percent = static_cast<int>(100 * done / m_total);
    if (percent == m_lastPercent && done != m_total) return;
    m_lastPercent = percent;
    constexpr int kWidth = 40;
    const int filled = kWidth * percent / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%  t = %.3f s", filled,
                 "########################################", kWidth - filled, "", percent, simTime);
    std::fflush(stderr);
  }
  void finish() {
    if (m_enabled && m_lastPercent >= 0) std::fprintf(stderr, "\n");
    m_lastPercent = -1;
    m_enabled = false;
  }

 private:
  long m_total;
  bool m_enabled;
  int m_lastPercent = -1;
};

}  // namespace hs::app
