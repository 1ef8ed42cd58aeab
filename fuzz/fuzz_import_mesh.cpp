// Fuzz target body of every mesh and CAD format: the input as a file ending in
// SWEPT_FUZZ_EXTENSION, read by swept::import_mesh() (and, for the formats an OMPL.app .cfg can
// name, by swept::ompl_app_center(), which reads them through assimp's own post-processing).
// An Error is a fine outcome; a crash, a sanitizer report, a leak or a hang is a finding.
#include "fuzz_support.h"

#include "swept/io/mesh_io.h"

#include <filesystem>

namespace {

constexpr bool kOmplCenter = SWEPT_FUZZ_OMPL_CENTER;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // The readers' one-time set-up (OpenCASCADE's reader registries, assimp's importer tables)
  // happens here on a valid seed mesh, so that it is not reported as a leak of the first input.
  swept::fuzz::copy_seed_meshes();
  for (const auto& e : std::filesystem::directory_iterator(swept::fuzz::scratch_dir()))
    if (e.path().extension() == SWEPT_FUZZ_EXTENSION) {
      (void)swept::import_mesh(e.path());
      if (kOmplCenter) (void)swept::ompl_app_center(e.path());
      break;
    }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const swept::fuzz::InputFile input(data, size, SWEPT_FUZZ_EXTENSION);
  (void)swept::import_mesh(input.path());
  if (kOmplCenter) (void)swept::ompl_app_center(input.path());
  return 0;
}
