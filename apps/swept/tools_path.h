#pragma once
/// `swept scene` and `swept bench` run in a program of their own, swept-tools (tools_main.cpp).
/// Looked for, in order: $SWEPT_TOOLS alone when set; for a `swept` inside its build tree, that
/// tree's; next to the running `swept`; <its folder>/../<libexecdir>/swept (an installed swept,
/// wherever its prefix was moved); the configured install path; the build tree's.
#include <filesystem>
#include <string>
#include <vector>

namespace swept::cli {

std::vector<std::filesystem::path> tools_candidates();

/// The first candidate that is an executable file (empty when none), and what was tried.
struct ToolsLookup {
  std::filesystem::path path;
  std::string tried;  ///< each candidate passed over, and why
};
ToolsLookup find_tools();

/// Runs swept-tools in place of this process with the same arguments (argv[0] kept, so that
/// usage lines still read `swept scene ...`). Returns only when no candidate could be run:
/// prints why on stderr and returns exit code 1.
int exec_tools(char** argv);

}  // namespace swept::cli
