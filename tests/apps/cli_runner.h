#pragma once
// Runs the heartsim executable as a user would and captures exit code, stdout and stderr.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

inline std::filesystem::path scratchDir(const std::string& name) {
  auto dir = std::filesystem::path(::testing::TempDir()) / ("heartsim_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace hs::testing
