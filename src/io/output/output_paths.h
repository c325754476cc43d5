#pragma once
// Where a run's files go by default. A scenario's name comes from its file or from
// `--set scenario.name=...` and may hold anything; the folder and file names made from it
// hold only letters, digits, '-' and '_', so results stay inside results/ (never "..", an
// absolute path, a quote or a newline).
#include <filesystem>
#include <string>
#include <string_view>

namespace hs::io {

// `name` with every character other than A-Z, a-z, 0-9, '-' and '_' replaced by '_';
// "scenario" when nothing is left (an empty name).
std::string safeFileStem(std::string_view name);

// results/<safeFileStem(scenarioName)>
std::filesystem::path defaultOutputFolder(std::string_view scenarioName);

}  // namespace hs::io
