#pragma once
// The STEP / IGES / OCCT .brep reader is a module of its own (libswept_cad.so, OpenCASCADE),
// loaded by import_mesh() the first time it reads such a file, so that programs that never read
// CAD do not load OpenCASCADE. Searched, in order: $SWEPT_CAD_MODULE alone when set; for a binary
// inside swept's build tree, that tree's module; next to the shared object or executable that
// holds swept, and next to the running executable; <each of those folders>/../<libdir>/swept (an
// installed swept, wherever its prefix was moved); the configured install path; the build
// tree's.
#include <filesystem>
#include <string>
#include <vector>

namespace swept {

struct CadReaderStatus {
  std::filesystem::path path;                     ///< the module in use; empty when none loads
  std::string error;                              ///< why none loads (each place tried)
  std::vector<std::filesystem::path> candidates;  ///< where it is looked for, in order
};

/// Loads the CAD reader module if it is not loaded yet, and says which one is in use.
CadReaderStatus cad_reader_status();

}  // namespace swept
