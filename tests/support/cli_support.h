#pragma once
// Running the built `swept` command line from tests (SWEPT_CLI is its path).
#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace swept::test {

struct CliRun {
  int code = -1;    ///< exit code (-1: did not exit normally)
  std::string out;  ///< stdout, and stderr too when `with_stderr`
};

/// Runs a shell command line and captures its stdout.
inline CliRun run_shell(const std::string& cmd) {
  CliRun r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// Runs `swept ARGS` and captures its output.
inline CliRun run_cli(const std::string& args, bool with_stderr = true) {
  return run_shell(std::string(SWEPT_CLI) + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null"));
}

/// Lines in a command's output (its newlines).
inline std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace swept::test
