// Fuzz target body of the path formats (SWEPT_FUZZ_EXTENSION ".json" for ours, ".path" for
// OMPL's): the input as a path file read by swept::read_path(). An Error is a fine outcome.
#include "fuzz_support.h"

#include "swept/plan/problem.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const swept::fuzz::InputFile input(data, size, SWEPT_FUZZ_EXTENSION);
  (void)swept::read_path(input.path());
  return 0;
}
