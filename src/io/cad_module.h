#pragma once
// Internal to swept_io: the CAD reader module (libswept_cad.so, src/cad/), loaded on first use by
// read_cad() (import_detail.h), searched in the order that swept/io/cad_reader.h documents.
#include "import_detail.h"

#include <filesystem>
#include <string>
#include <vector>

namespace swept::io_detail {

struct CadModule {
  std::filesystem::path path;                     ///< the module loaded, empty when none
  void* entry = nullptr;                          ///< its swept_cad_read, null when none
  std::string error;                              ///< why none was loaded
  std::vector<std::filesystem::path> candidates;  ///< where it was looked for, in order
};

/// The module, loaded once per process (thread-safe). Never throws; a failure is kept in `error`.
const CadModule& cad_module();

/// Where the module is looked for, in order (cad_module.h's header comment).
std::vector<std::filesystem::path> cad_module_candidates();

/// The interface both sides are built against: swept's version and a hash of the headers of the
/// types passed across (src/CMakeLists.txt). A module answering another is not used.
inline const char* cad_module_abi() { return SWEPT_CAD_ABI; }

}  // namespace swept::io_detail
