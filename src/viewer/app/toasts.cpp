#include "viewer/app/toasts.h"

#include <algorithm>

namespace hs::viewer {

double Toasts::secondsFor(const std::string& text) {
  const auto words = 1 + std::count(text.begin(), text.end(), ' ');
  return std::min(kMinSeconds + kSecondsPerWord * double(words), kMaxSeconds);
}

void Toasts::push(std::string text, ToastKind kind, double now) {
  if (text.empty()) return;
  const double until = now + secondsFor(text);
  for (Toast& t : m_toasts)
    if (t.text == text && t.until > now) {
      t.until = until, t.kind = kind;
      return;
    }
  m_toasts.push_back({std::move(text), kind, now, until});
  while (m_toasts.size() > kMaxShown) m_toasts.pop_front();
}

std::vector<Toast> Toasts::visible(double now) {
  std::erase_if(m_toasts, [&](const Toast& t) { return t.until <= now; });
  return {m_toasts.begin(), m_toasts.end()};
}

}  // namespace hs::viewer
