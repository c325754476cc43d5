// Importing and tetrahedralising a patient's ventricle (issue 16: under 5 s for biv-me at the
// default resolution): the read (Assimp, OBJ) and buildPatientWall (remesh, frame, extrusion,
// quality, segments) at each resolution, for biv-me's frame 0 and the idealized LV.
#include <benchmark/benchmark.h>

#include <string>

#include "cardiac/patient/patient_wall.h"
#include "io/mesh/mesh_import.h"
#include "io/mesh/patient_surfaces.h"

namespace hs::io {
namespace {

const char* const kResolutions[] = {"coarse", "default", "fine"};

void buildFrom(benchmark::State& state, const std::string& file, cardiac::LengthUnit units) {
  cardiac::PatientWallSettings settings;
  settings.file = file;
  settings.units = units;
  settings.resolution = cardiac::wallResolution(kResolutions[state.range(0)]);
  std::size_t tets = 0;
  double minDihedral = 0, maxAspect = 0;
  for (auto _ : state) {
    const PatientSurfaces s = patientSurfaces(readMesh(file), file);
    const cardiac::PatientWall w =
        cardiac::buildPatientWall(s.endocardium, s.epicardium ? &*s.epicardium : nullptr, settings);
    tets = w.mesh.tets.size();
    minDihedral = w.quality.minDihedralDeg;
    maxAspect = w.quality.maxAspectRatio;
    benchmark::DoNotOptimize(w.mesh.vertices.data());
  }
  state.counters["tets"] = double(tets);
  state.counters["min_dihedral_deg"] = minDihedral;
  state.counters["max_aspect"] = maxAspect;
  state.SetLabel(kResolutions[state.range(0)]);
}

void BM_PatientWallBivme(benchmark::State& state) {
  buildFrom(state, std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj",
            cardiac::LengthUnit::Millimetre);
}
BENCHMARK(BM_PatientWallBivme)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_PatientWallIdealizedLv(benchmark::State& state) {
  buildFrom(state, std::string(HS_TEST_DATA_DIR) + "/meshes/arostica2025_idealized_lv/ellipsoid_0.005.node",
            cardiac::LengthUnit::Metre);
}
BENCHMARK(BM_PatientWallIdealizedLv)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hs::io
