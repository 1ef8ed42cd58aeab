// The STEP / IGES / OCCT .brep reader lives in a module of its own, libswept_cad.so (src/cad/),
// loaded the first time a CAD file is read: OpenCASCADE's data-exchange libraries (XDE and the
// visualisation libraries they pull in) took ~60 % of every swept command's start-up, CAD file
// or not. This file finds and loads that module (cad_module.h).
#include "cad_module.h"

#include "swept/io/cad_reader.h"
#include "swept/io/install_paths.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <string_view>

#ifndef SWEPT_CAD_MODULE_BUILD_PATH
#define SWEPT_CAD_MODULE_BUILD_PATH ""
#endif
#ifndef SWEPT_CAD_MODULE_INSTALL_PATH
#define SWEPT_CAD_MODULE_INSTALL_PATH ""
#endif
#ifndef SWEPT_CAD_MODULE_FROM_BINDIR
#define SWEPT_CAD_MODULE_FROM_BINDIR ""
#endif
#ifndef SWEPT_BUILD_DIR
#define SWEPT_BUILD_DIR ""
#endif

namespace swept::io_detail {
namespace {

namespace fs = std::filesystem;

using EntryFn = void (*)(const ReadContext*, std::vector<TriangleSoup>*, Result<bool>*);
using AbiFn = const char* (*)();

/// The folders of the binaries that hold this code: the shared object (such as the Python
/// module) or the executable that swept_io is linked into, and the running executable. (For the
/// executable dladdr answers argv[0], which is a bare name when the program was found on PATH;
/// /proc/self/exe is its real path.)
std::vector<fs::path> own_directories() {
  std::vector<fs::path> out;
  auto add = [&out](const fs::path& file) {
    std::error_code ec;
    if (!file.is_absolute() && !file.has_parent_path()) return;  // a bare name: not a location
    const fs::path real = fs::canonical(file, ec);
    if (ec) return;
    const fs::path dir = real.parent_path();
    if (std::find(out.begin(), out.end(), dir) == out.end()) out.push_back(dir);
  };
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&own_directories), &info) != 0 && info.dli_fname != nullptr)
    add(fs::path(info.dli_fname));
  add(fs::path("/proc/self/exe"));
  return out;
}


CadModule load() {
  CadModule m;
  m.candidates = cad_module_candidates();
  std::ostringstream tried;
  for (const fs::path& p : m.candidates) {
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) {
      tried << (tried.tellp() > 0 ? "; " : "") << p.string() << " (not there)";
      continue;
    }
    void* handle = dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      tried << (tried.tellp() > 0 ? "; " : "") << p.string() << " (" << (why ? why : "dlopen failed") << ")";
      continue;
    }
    auto abi = reinterpret_cast<AbiFn>(dlsym(handle, "swept_cad_abi"));
    auto entry = reinterpret_cast<EntryFn>(dlsym(handle, "swept_cad_read"));
    if (abi == nullptr || entry == nullptr || std::string_view(abi()) != cad_module_abi()) {
      tried << (tried.tellp() > 0 ? "; " : "") << p.string() << " (built for another version of swept: "
            << (abi ? abi() : "no version") << ", this one is " << cad_module_abi() << ")";
      dlclose(handle);
      continue;
    }
    m.path = p;
    m.entry = reinterpret_cast<void*>(entry);
    return m;
  }
  m.error = "swept's OpenCASCADE reader libswept_cad.so could not be loaded; tried " + tried.str() +
            "; set SWEPT_CAD_MODULE to its path, or reinstall swept";
  return m;
}

}  // namespace

std::vector<fs::path> cad_module_candidates() {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("SWEPT_CAD_MODULE"); env != nullptr && *env != '\0') {
    out.emplace_back(env);
    return out;  // an explicit choice: nothing else
  }
  const std::vector<fs::path> dirs = own_directories();
  const std::string build_path = SWEPT_CAD_MODULE_BUILD_PATH, install_path = SWEPT_CAD_MODULE_INSTALL_PATH;
  const bool in_build_tree =
      std::any_of(dirs.begin(), dirs.end(), [](const fs::path& d) { return path_inside(d, SWEPT_BUILD_DIR); });
  // A binary in its build tree loads that tree's module first, whatever is installed.
  if (in_build_tree && !build_path.empty()) out.emplace_back(build_path);
  for (const fs::path& dir : dirs) {
    out.push_back(dir / "libswept_cad.so");
    // An installed binary, wherever its prefix was moved: <prefix>/bin → <prefix>/<libdir>/swept.
    if (const std::string rel = SWEPT_CAD_MODULE_FROM_BINDIR; !rel.empty()) out.push_back((dir / rel).lexically_normal());
  }
  if (!install_path.empty()) out.emplace_back(install_path);
  if (!build_path.empty() && !in_build_tree) out.emplace_back(build_path);
  return out;
}

const CadModule& cad_module() {
  static std::once_flag once;
  static CadModule module;
  std::call_once(once, [] { module = load(); });
  return module;
}

Result<bool> read_cad(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
  const CadModule& m = cad_module();
  if (m.entry == nullptr) return file_error(ctx.display, "cannot read STEP, IGES or OCCT .brep files: " + m.error);
  Result<bool> out = true;
  reinterpret_cast<EntryFn>(m.entry)(&ctx, &parts, &out);
  return out;
}

}  // namespace swept::io_detail

namespace swept {

CadReaderStatus cad_reader_status() {
  const io_detail::CadModule& m = io_detail::cad_module();
  return {m.path, m.error, m.candidates};
}

}  // namespace swept
