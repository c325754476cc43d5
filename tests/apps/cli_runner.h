#pragma once
// Runs the heartsim executable as a user would and captures exit code, stdout and stderr.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hs::testing {

struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// `args` is passed through the shell; quote as needed.
inline CliResult runHeartsim(const std::string& args, const std::filesystem::path& workDir) {
  std::filesystem::create_directories(workDir);
  const auto outFile = workDir / "stdout.txt";
  const auto errFile = workDir / "stderr.txt";
  // ctest runs two tests at once on two cores, and heartsim starts one OpenMP thread per core:
  // with spinning waits, oversubscribed barriers cost a time slice each (a 10k-particle run fell
  // 20-fold). Passive waiting keeps the tests' run time steady; results do not depend on it.
  const std::string command = "cd '" + workDir.string() + "' && OMP_WAIT_POLICY=PASSIVE '" + HS_HEARTSIM_EXE + "' " + args + " >'" +
                              outFile.string() + "' 2>'" + errFile.string() + "'";
  const int status = std::system(command.c_str());
  CliResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(outFile);
  r.err = readFile(errFile);
  return r;
}

// One column of a CSV file with a header row (metrics.csv), as numbers; empty when the column
// is missing.
inline std::vector<double> csvColumn(const std::filesystem::path& file, const std::string& name) {
  std::istringstream csv(readFile(file));
  std::string line, field;
  std::getline(csv, line);
  std::istringstream header(line);
  int index = -1;
  for (int k = 0; std::getline(header, field, ','); ++k)
    if (field == name) index = k;
  std::vector<double> values;
  if (index < 0) return values;
  while (std::getline(csv, line)) {
    std::istringstream row(line);
    for (int k = 0; std::getline(row, field, ','); ++k)
      if (k == index) values.push_back(std::stod(field));
  }
  return values;
}

inline std::filesystem::path scratchDir(const std::string& name) {
  auto dir = std::filesystem::path(::testing::TempDir()) / ("heartsim_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace hs::testing
