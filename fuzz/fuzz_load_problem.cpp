// Fuzz target body of the problem formats (SWEPT_FUZZ_EXTENSION ".toml" or ".cfg"): the input
// as a problem file in the scratch folder, beside copies of fuzz/data's small meshes, which
// the seed problems name ("tet.stl", "box.brep"); read by swept::load_problem(). A .cfg reads
// its robot mesh there too (ompl_app_center()). An Error is a fine outcome.
#include "fuzz_support.h"

#include "swept/plan/problem.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  swept::fuzz::copy_seed_meshes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const swept::fuzz::InputFile input(data, size, SWEPT_FUZZ_EXTENSION);
  (void)swept::load_problem(input.path());
  return 0;
}
