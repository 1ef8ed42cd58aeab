#include "tools_path.h"

#include "swept/io/install_paths.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <system_error>

#ifndef SWEPT_TOOLS_BUILD_PATH
#define SWEPT_TOOLS_BUILD_PATH ""
#endif
#ifndef SWEPT_TOOLS_INSTALL_PATH
#define SWEPT_TOOLS_INSTALL_PATH ""
#endif
#ifndef SWEPT_TOOLS_FROM_BINDIR
#define SWEPT_TOOLS_FROM_BINDIR ""
#endif
#ifndef SWEPT_BUILD_DIR
#define SWEPT_BUILD_DIR ""
#endif

namespace swept::cli {
namespace fs = std::filesystem;

std::vector<fs::path> tools_candidates() {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("SWEPT_TOOLS"); env != nullptr && *env != '\0') {
    out.emplace_back(env);
    return out;  // an explicit choice: nothing else
  }
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  const fs::path dir = ec ? fs::path() : exe.parent_path();
  const std::string build_path = SWEPT_TOOLS_BUILD_PATH, install_path = SWEPT_TOOLS_INSTALL_PATH;
  const bool in_build_tree = path_inside(dir, SWEPT_BUILD_DIR);
  if (in_build_tree && !build_path.empty()) out.emplace_back(build_path);
  if (!dir.empty()) {
    out.push_back(dir / "swept-tools");
    if (const std::string rel = SWEPT_TOOLS_FROM_BINDIR; !rel.empty()) out.push_back((dir / rel).lexically_normal());
  }
  if (!install_path.empty()) out.emplace_back(install_path);
  if (!build_path.empty() && !in_build_tree) out.emplace_back(build_path);
  std::vector<fs::path> unique;
  for (const fs::path& p : out)
    if (std::find(unique.begin(), unique.end(), p) == unique.end()) unique.push_back(p);
  return unique;
}

ToolsLookup find_tools() {
  ToolsLookup out;
  std::ostringstream tried;
  for (const fs::path& p : tools_candidates()) {
    std::error_code ec;
    const char* why = !fs::is_regular_file(p, ec) ? "not there" : ::access(p.c_str(), X_OK) != 0 ? "not executable" : nullptr;
    if (why == nullptr) {
      out.path = p;
      break;
    }
    tried << (tried.tellp() > 0 ? "; " : "") << p.string() << " (" << why << ")";
  }
  out.tried = tried.str();
  return out;
}

int exec_tools(char** argv) {
  ToolsLookup tools = find_tools();
  if (!tools.path.empty()) {
    ::execv(tools.path.c_str(), argv);
    tools.tried += (tools.tried.empty() ? "" : "; ") + tools.path.string() + " (" + std::strerror(errno) + ")";
  }
  std::cerr << "swept: error: `swept " << argv[1] << "` runs swept-tools (the scene generators and the benchmarks), "
            << "which could not be run; tried " << tools.tried << "; set SWEPT_TOOLS to its path, or reinstall swept\n";
  return 1;
}

}  // namespace swept::cli
