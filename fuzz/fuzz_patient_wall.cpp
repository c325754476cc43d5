// A patient's wall from arbitrary surfaces: the first byte picks the format (its value mod 4:
// obj, stl, ply, off) and the resolution (its value / 4 mod 3: coarse, default, fine), the rest
// is the file; a surface that reads is made into a wall (cardiac::buildPatientWall) in the unit
// its size suggests. Anything but the one-line std::invalid_argument of the reader or of the
// wall is a bug, and so is a wall with an inverted tet. Seeded with biv-me's endocardium
// (fuzz/seeds/fuzz_patient_wall/).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "cardiac/patient/patient_wall.h"
#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "io/mesh/patient_surfaces.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[4] = {"obj", "stl", "ply", "off"};
  static const char* const kResolutions[3] = {"coarse", "default", "fine"};
  const std::string extension = kExtensions[data[0] % 4];
  try {
    const hs::io::ImportedMesh mesh =
        hs::io::parseSurface(std::string_view(reinterpret_cast<const char*>(data + 1), size - 1), extension, "fuzz." + extension);
    const hs::io::MeshSummary summary = hs::io::summarizeMesh(mesh);
    hs::cardiac::PatientWallSettings settings;
    settings.file = "fuzz." + extension;
    settings.units = summary.unitGuess == "m" ? hs::cardiac::LengthUnit::Metre : hs::cardiac::LengthUnit::Millimetre;
    settings.resolution = hs::cardiac::wallResolution(kResolutions[(data[0] / 4) % 3]);
    const hs::io::PatientSurfaces surfaces = hs::io::patientSurfaces(mesh, settings.file);
    const hs::cardiac::PatientWall wall = hs::cardiac::buildPatientWall(surfaces.endocardium, nullptr, settings);
    if (wall.quality.invertedTets != 0) __builtin_trap();
  } catch (const std::invalid_argument& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
