#pragma once
// Messages shown as toasts inside the scene, where the student is looking: a saved
// screenshot's full path, a region applied and the restart it caused, why a request was
// refused, a simulation that stopped. Each stays for a few seconds (longer when it is long to
// read) and the newest few are shown. Pure bookkeeping, no ImGui: scene_overlays draws them.
#include <deque>
#include <string>
#include <vector>

namespace hs::viewer {

enum class ToastKind { Info, Warning };

struct Toast {
  std::string text;
  ToastKind kind = ToastKind::Info;
  double shownAt = 0;  // s, the app's clock
  double until = 0;    // s
};

class Toasts {
 public:
  static constexpr std::size_t kMaxShown = 3;
  static constexpr double kMinSeconds = 4, kSecondsPerWord = 0.3, kMaxSeconds = 12;

  // A new message at time `now` (s). The same text again while it is shown only renews it.
  void push(std::string text, ToastKind kind, double now);
  // The messages to show at `now`, oldest first (at most kMaxShown); expired ones are dropped.
  std::vector<Toast> visible(double now);
  // How long a message stays: kMinSeconds plus reading time, at most kMaxSeconds.
  static double secondsFor(const std::string& text);

 private:
  std::deque<Toast> m_toasts;
};

}  // namespace hs::viewer
