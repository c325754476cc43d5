#pragma once
// Names along one row (a chart's phase band): each wants to sit at its own place, in order, and
// none may cover another. spreadLabelRow moves the fewest pixels it needs: a forward pass pushes
// each name right of the one before it (gap apart), a backward pass pulls them back left of the
// row's end, and the first stays right of its start. Only when the names together are wider
// than the row do they still touch.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace hs::viewer {

// x[i]: where name i's left edge wants to be (in order along the row); width[i] its width. On
// return x holds positions with x[i] + width[i] + gap <= x[i + 1] when the row is wide enough.
inline void spreadLabelRow(std::vector<float>& x, const std::vector<float>& width, float rowStart, float rowEnd,
                           float gap) {
  const std::size_t n = x.size();
  if (n == 0) return;
  for (std::size_t i = 1; i < n; ++i) x[i] = std::max(x[i], x[i - 1] + width[i - 1] + gap);
  x[n - 1] = std::min(x[n - 1], rowEnd - width[n - 1]);
  for (std::size_t i = n - 1; i-- > 0;) x[i] = std::min(x[i], x[i + 1] - gap - width[i]);
  x[0] = std::max(x[0], rowStart);
  for (std::size_t i = 1; i < n; ++i) x[i] = std::max(x[i], x[i - 1] + width[i - 1] + gap);
}

}  // namespace hs::viewer
