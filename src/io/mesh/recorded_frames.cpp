#include "io/mesh/recorded_frames.h"

#include <stdexcept>

#include "io/mesh/mesh_import.h"
#include "io/mesh/patient_surfaces.h"

namespace hs::io {

std::string framePath(const std::string& pattern, int frame) {
  const auto fail = [&](const std::string& why) {
    return std::invalid_argument("\"" + pattern + "\": " + why +
                                 "; expected one {frame} or {frame:0Nd} (e.g. \"lv_{frame:03d}.obj\")");
  };
  const std::size_t open = pattern.find('{');
  if (open == std::string::npos) throw fail("no {frame} in the file name");
  const std::size_t close = pattern.find('}', open);
  if (close == std::string::npos) throw fail("a { without its }");
  if (pattern.find('{', close) != std::string::npos || pattern.find('}', close + 1) != std::string::npos)
    throw fail("more than one placeholder");
  const std::string field = pattern.substr(open + 1, close - open - 1);
  std::size_t width = 0;
  if (field != "frame") {
    // frame:0Nd, N a single digit 1-9.
    if (field.size() != 9 || field.compare(0, 7, "frame:0") != 0 || field[7] < '1' || field[7] > '9' ||
        field[8] != 'd')
      throw fail("the placeholder {" + field + "}");
    width = std::size_t(field[7] - '0');
  }
  std::string number = std::to_string(frame);
  if (number.size() < width) number.insert(0, width - number.size(), '0');
  return pattern.substr(0, open) + number + pattern.substr(close + 1);
}

std::vector<cardiac::Surface> readRecordedFrames(const std::string& pattern, int count,
                                                 const cardiac::Surface& endocardium,
                                                 const std::string& endocardiumFile,
                                                 const std::string& markerEndocardium) {
  std::vector<cardiac::Surface> frames;
  frames.reserve(std::size_t(count));
  for (int f = 0; f < count; ++f) {
    const std::string file = framePath(pattern, f);
    cardiac::Surface frame = patientSurfaces(readMesh(file), file, PatientMarkers{markerEndocardium, ""}).endocardium;
    if (frame.vertices.size() != endocardium.vertices.size() || frame.triangles != endocardium.triangles)
      throw std::invalid_argument(file + ": frame " + std::to_string(f) + " has " +
                                  std::to_string(frame.vertices.size()) + " vertices and " +
                                  std::to_string(frame.triangles.size()) + " triangles; expected the endocardium " +
                                  endocardiumFile + " moved: " + std::to_string(endocardium.vertices.size()) +
                                  " vertices and the same " + std::to_string(endocardium.triangles.size()) +
                                  " triangles");
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace hs::io
