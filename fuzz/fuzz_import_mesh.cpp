// Fuzz target body of every mesh and CAD format: the input as a file ending in
// SWEPT_FUZZ_EXTENSION, read by swept::import_mesh() (and, for the formats an OMPL.app .cfg can
// name, by swept::ompl_app_center(), which reads them through assimp's own post-processing).
// An Error is a fine outcome; a crash, a sanitizer report, a leak or a hang is a finding.
#include "fuzz_support.h"

#include "swept/io/mesh_io.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

constexpr bool kOmplCenter = SWEPT_FUZZ_OMPL_CENTER;

// The readers as users get them: assimp and OpenCASCADE in a child process (isolate_readers),
// stopped after 3 s: an input is read twice (import_mesh, ompl_app_center), and two stopped
// reads must stay well inside libFuzzer's -timeout=10. SWEPT_FUZZ_IN_PROCESS=1 reads in this
// process instead, to fuzz those libraries with coverage (their own crashes are then findings).
swept::ImportOptions options() {
  swept::ImportOptions o;
  o.reader_timeout = 3.0;
  const char* in_process = std::getenv("SWEPT_FUZZ_IN_PROCESS");
  o.isolate_readers = !(in_process && std::string(in_process) == "1");
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // The readers' one-time set-up (OpenCASCADE's reader registries, assimp's importer tables)
  // happens here on a valid seed mesh, so that it is not reported as a leak of the first input.
  swept::fuzz::copy_seed_meshes();
  for (const auto& e : std::filesystem::directory_iterator(swept::fuzz::scratch_dir()))
    if (e.path().extension() == SWEPT_FUZZ_EXTENSION) {
      (void)swept::import_mesh(e.path(), options());
      if (kOmplCenter) (void)swept::ompl_app_center(e.path(), options());
      break;
    }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const swept::fuzz::InputFile input(data, size, SWEPT_FUZZ_EXTENSION);
  static const swept::ImportOptions o = options();
  (void)swept::import_mesh(input.path(), o);
  if (kOmplCenter) (void)swept::ompl_app_center(input.path(), o);
  return 0;
}
