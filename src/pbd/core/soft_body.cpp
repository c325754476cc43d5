#include "pbd/core/soft_body.h"

namespace hs::pbd {

Index addSoftBody(Particles& particles, ConstraintSet& constraints, const TetMesh& mesh,
                  const std::vector<Triangle>& surface, const SoftBodySettings& settings) {
  const auto first = static_cast<Index>(particles.size());
  std::vector<Real> mass(mesh.vertices.size(), Real(0));
  for (const Tet& t : mesh.tets) {
    const Real v = signedTetVolume(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                   mesh.vertices[t[2]], mesh.vertices[t[3]]);
    for (Index i : t) mass[i] += settings.density * v / Real(4);
    constraints.volumes.constraints.push_back({{first + t[0], first + t[1], first + t[2], first + t[3]}, v});
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Real w = mass[i] > Real(0) ? Real(1) / mass[i] : Real(0);
    particles.add(mesh.vertices[i], w, ParticleKind::Tissue);
  }
  for (const Triangle& f : settings.areas ? surface : std::vector<Triangle>{}) {
    const Vec3& a = mesh.vertices[f[0]];
    const Real area = Real(0.5) * (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).norm();
    constraints.areas.constraints.push_back({{first + f[0], first + f[1], first + f[2]}, area});
  }
  if (settings.edges) {
    for (const Edge& e : uniqueEdges(mesh.tets)) {
      const Real length = (mesh.vertices[e[1]] - mesh.vertices[e[0]]).norm();
      constraints.distances.constraints.push_back({{first + e[0], first + e[1]}, length});
    }
  }
  constraints.volumes.compliance = settings.volumeCompliance;
  constraints.areas.compliance = settings.areaCompliance;
  constraints.distances.compliance = settings.edgeCompliance;
  constraints.volumes.stiffness = settings.volumeStiffness;
  constraints.areas.stiffness = settings.stiffness;
  constraints.distances.stiffness = settings.stiffness;
  return first;
}

void finalizeConstraints(ConstraintSet& constraints, const std::vector<Vec3>& positions) {
  constraints.schedule = buildBlockSchedule(constraints, positions);
}

}  // namespace hs::pbd
