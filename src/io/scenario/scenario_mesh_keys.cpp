// [model] keys of a patient's heart from CT/MRI meshes (kind = "mesh", issue 16 item 6): the
// rows of the key table after the procedural model's (scenario_keys.cpp). The paths are
// resolved against the scenario file's folder and the files read in scenario_file.cpp.
#include <string>
#include <utility>
#include <vector>

#include "io/scenario/scenario_internal.h"
#include "io/scenario/scenario_key_builders.h"

namespace hs::io::detail {
namespace {

using namespace builders;  // NOLINT(google-build-using-namespace): the row vocabulary
using cardiac::Scenario;

// clang-format off
#define HS_FIELD(expr) [](Scenario& s) -> auto& { return s.expr; }
// clang-format on

// A surface group of the file, by name or number: a string, or a whole number >= 0 kept as its
// decimal text.
template <class F>
KeySpec markerKey(std::string name, F field, std::string doc) {
  KeySpec k = makeSpec(std::move(name), "string or integer", "", "a group's name or number; \"\" = recognised",
                       std::move(doc));
  k.expect = "a surface group's name (a string) or number (an integer >= 0)";
  k.stringLike = true;
  k.set = [field, expect = k.expect](Scenario& s, const toml::node& n) {
    if (const auto* str = n.as_string()) {
      field(s) = str->get();
      return;
    }
    if (const auto* i = n.as_integer(); i && i->get() >= 0) {
      field(s) = std::to_string(i->get());
      return;
    }
    throw ValueError{"expected " + expect + ", got " + describeNode(n)};
  };
  k.get = [field](const Scenario& s) { return quoteString(fieldOf(field, s)); };
  addExactValue(k, field);
  return k;
}

}  // namespace

std::vector<KeySpec> meshModelKeys() {
  using cardiac::LengthUnit;
  using cardiac::ModelKind;
  const std::vector<std::pair<std::string, ModelKind>> kinds = {{"procedural", ModelKind::Procedural},
                                                               {"mesh", ModelKind::Mesh}};
  const std::vector<std::pair<std::string, LengthUnit>> units = {{"mm", LengthUnit::Millimetre},
                                                                {"m", LengthUnit::Metre}};
  const std::vector<std::pair<std::string, std::string>> resolutions = {
      {"coarse", "coarse"}, {"default", "default"}, {"fine", "fine"}};
  return {
      choiceKey("model.kind", HS_FIELD(patient.kind), kinds,
                "The heart: \"procedural\" (the shape from the sizes above) or \"mesh\" (a patient's ventricle "
                "from the files below; docs/patient-meshes.md)."),
      stringKey("model.endocardium", HS_FIELD(patient.endocardium), false,
                "kind = \"mesh\": the endocardial surface (.obj .stl .ply .off), relative to the scenario file."),
      stringKey("model.epicardium", HS_FIELD(patient.epicardium), false,
                "kind = \"mesh\", optional: the epicardial surface; without it the wall is model.wall_thickness "
                "thick."),
      stringKey("model.volume_mesh", HS_FIELD(patient.volumeMesh), false,
                "kind = \"mesh\", instead of the surfaces: a volume mesh (.msh .vtu .vtk .node) whose marked "
                "surfaces give the endocardium and epicardium."),
      choiceKey("model.units", HS_FIELD(patient.units), units,
                "kind = \"mesh\": the files' length unit; a heart outside 3-30 cm in it is refused."),
      choiceKey("model.mesh_resolution", HS_FIELD(patient.resolution), resolutions,
                "kind = \"mesh\": the wall's edge length: \"coarse\" 6 mm (real time), \"default\" 5 mm, "
                "\"fine\" 3 mm; one tet across the wall."),
      vec3Key("model.septum", HS_FIELD(patient.septum), between(-1, 1), "",
              "kind = \"mesh\": direction toward the septum in the file's frame; [0, 0, 0] = found (from a "
              "biventricular epicardium, the aortic annulus or a file axis)."),
      intKey("model.mitral_loop", HS_FIELD(patient.mitralLoop), 0, "",
             "kind = \"mesh\": the mitral annulus's boundary loop number as `heartsim mesh` lists them; 0 = the "
             "larger.", 1000),
      intKey("model.aortic_loop", HS_FIELD(patient.aorticLoop), 0, "",
             "kind = \"mesh\": the aortic annulus's boundary loop number; 0 = the other one.", 1000),
      markerKey("model.markers.endocardium", HS_FIELD(patient.markerEndocardium),
                "The volume mesh's endocardial surface group; \"\" = ENDO, ENDOCARDIUM or 1."),
      markerKey("model.markers.epicardium", HS_FIELD(patient.markerEpicardium),
                "The volume mesh's epicardial surface group; \"\" = EPI, EPICARDIUM or 2."),
      markerKey("model.markers.base", HS_FIELD(patient.markerBase),
                "The volume mesh's base surface group; \"\" = BASE or 3 (the wall is rebuilt from the "
                "endocardium, so the base is not read)."),
  };
}

// [motion]: a recorded beat driving a patient's wall (issue 16 item 5); the frames are read in
// scenario_file.cpp.
std::vector<KeySpec> motionKeys() {
  return {
      stringKey("motion.frames", HS_FIELD(motion.frames), false,
                "model.kind = \"mesh\", optional: a recorded beat, the endocardium's file pattern with {frame} or "
                "{frame:03d} (relative to the scenario file); each frame is the endocardium moved (its vertices and "
                "triangles), frame 0 at end-diastole. The endocardium follows them; \"\" = heartsim's own cycle."),
      intKey("motion.count", HS_FIELD(motion.count), 0, "",
             "Frames in the recorded beat, numbered from 0 (at least 2 with motion.frames).", 1000),
      realKey("motion.period", HS_FIELD(motion.period), between(0, 3), "s",
              "The recorded beat's length; it sets the heart rate (at least 0.24 s with motion.frames, 250 bpm; at "
              "most 3 s, 20 bpm, as cycle.heart_rate_bpm)."),
  };
}

}  // namespace hs::io::detail
