#pragma once
// `heartsim view` tests under a virtual X server: a fixture that starts one Xvfb per test
// process on a display number Xvfb chooses itself, and runs heartsim with DISPLAY set to it
// (test_cli_view.cpp, test_cli_lesson.cpp).
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "cli_runner.h"

namespace hs::testing {

namespace fs = std::filesystem;

inline std::optional<std::string> findXvfb() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"}) {
    const fs::path candidate = fs::path(dir) / "Xvfb";
    if (fs::exists(candidate)) return candidate.string();
  }
  return std::nullopt;
}

// DISPLAY for the child processes, set and restored around one call.
class ScopedDisplay {
 public:
  explicit ScopedDisplay(const std::optional<std::string>& display) {
    if (const char* old = std::getenv("DISPLAY")) m_old = old;
    if (display)
      setenv("DISPLAY", display->c_str(), 1);
    else
      unsetenv("DISPLAY");
  }
  ~ScopedDisplay() {
    if (m_old)
      setenv("DISPLAY", m_old->c_str(), 1);
    else
      unsetenv("DISPLAY");
  }
  ScopedDisplay(const ScopedDisplay&) = delete;
  ScopedDisplay& operator=(const ScopedDisplay&) = delete;

 private:
  std::optional<std::string> m_old;
};

// One Xvfb server per test process, on a display number Xvfb chooses.
class XvfbFixture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::optional<std::string> xvfb = findXvfb();
    if (!xvfb) {
      s_setupError = "Xvfb is not installed (apt-get install xvfb, see scripts/install-deps.sh)";
      return;
    }
    // Xvfb picks a free display itself and writes its number to a pipe (-displayfd): ctest
    // runs tests in parallel processes, and choosing a number here would race.
    int fds[2];
    if (pipe(fds) != 0) {
      s_setupError = "could not create a pipe for Xvfb";
      return;
    }
    const pid_t pid = fork();
    if (pid == 0) {
      close(fds[0]);
      freopen("/dev/null", "w", stdout);
      freopen("/dev/null", "w", stderr);
      const std::string fd = std::to_string(fds[1]);
      execl(xvfb->c_str(), "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    pollfd poller{fds[0], POLLIN, 0};
    char c = 0;
    while (poll(&poller, 1, 10000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (!number.empty()) {
      s_pid = pid;
      s_display = ":" + number;
    } else if (pid > 0) {
      kill(pid, SIGTERM);
      waitpid(pid, nullptr, 0);
    }
    if (s_pid <= 0) s_setupError = "could not start Xvfb (no display number reported within 10 s)";
  }
  static void TearDownTestSuite() {
    if (s_pid > 0) {
      kill(s_pid, SIGTERM);
      waitpid(s_pid, nullptr, 0);
      s_pid = -1;
    }
  }
  void SetUp() override {
    // scripts/install-deps.sh installs xvfb: without a server the set-up is broken, and the
    // viewer tests fail rather than pass unseen.
    if (!s_setupError.empty()) FAIL() << s_setupError;
  }
  static CliResult view(const std::string& args, const fs::path& dir) {
    ScopedDisplay display(s_display);
    return runHeartsim("view " + args, dir);
  }

  static inline pid_t s_pid = -1;
  static inline std::string s_display;
  static inline std::string s_setupError;
};

}  // namespace hs::testing
