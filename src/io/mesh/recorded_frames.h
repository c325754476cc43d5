#pragma once
// The frames of a recorded beat ([motion], issue 16 item 5): file names from a pattern, and the
// endocardial surfaces read from them (cardiac/motion/recorded_beat.h replays them).
#include <string>
#include <vector>

#include "cardiac/patient/patient_wall.h"

namespace hs::io {

// `pattern` with its one {frame} placeholder replaced by `frame`: "{frame}" gives 7,
// "{frame:03d}" gives 007 (a width of 1-9 digits, zero-padded as Python's format does).
// Throws std::invalid_argument (one line, naming the pattern; the caller names the key) for a pattern without exactly
// one placeholder or with another format than {frame} or {frame:0Nd}.
std::string framePath(const std::string& pattern, int frame);

// Frames 0..count-1 of `pattern`, each read as the endocardium is (io::patientSurfaces: a
// surface file's triangles, or a volume mesh's endocardial group, with `markerEndocardium`),
// and each required to be `endocardium` moved: the same vertex count and triangles. Throws
// std::invalid_argument with one line naming the frame's file.
std::vector<cardiac::Surface> readRecordedFrames(const std::string& pattern, int count,
                                                 const cardiac::Surface& endocardium,
                                                 const std::string& endocardiumFile,
                                                 const std::string& markerEndocardium);

}  // namespace hs::io
