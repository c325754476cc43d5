#pragma once
// A box of n x n x n cubes, each split into 6 tets around its main diagonal (Kuhn
// subdivision; conforming because every cube uses the same diagonal direction).
#include "pbd/core/tet_mesh.h"

namespace hs::pbd::testing {

inline TetMesh makeBoxMesh(int n, Real h) {
  TetMesh mesh;
  auto id = [n](int i, int j, int k) { return static_cast<Index>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(Real(i) * h, Real(j) * h, Real(k) * h);
  // The 6 monotone paths from corner 000 to 111 through the cube.
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& path : paths) {
          int c[3] = {i, j, k};
          Tet t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[path[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          const auto& v = mesh.vertices;
          if (signedTetVolume(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) < 0) std::swap(t[2], t[3]);
          mesh.tets.push_back(t);
        }
  return mesh;
}

}  // namespace hs::pbd::testing
