// Scratch folder and input files of the fuzz targets (fuzz_support.h).
#include "fuzz_support.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <pthread.h>
#include <sanitizer/common_interface_defs.h>
#include <string>
#include <system_error>
#include <unistd.h>

namespace swept::fuzz {

namespace fs = std::filesystem;

namespace {

fs::path make_scratch_dir() {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/swept-fuzz-XXXXXX";
  if (!::mkdtemp(pattern.data())) {
    std::perror("swept fuzz: mkdtemp");
    std::abort();  // without a folder no input can be read: not a finding of the target
  }
  return pattern;
}

void remove_scratch_dir() {
  std::error_code ec;
  fs::remove_all(scratch_dir(), ec);
}

// In a child the readers fork (ImportOptions::isolate_readers), libFuzzer's crash handling
// would report the child's crash as a finding of this process and write the input as an
// artifact, although the parent survives it by design. The child drops it: a fatal signal then
// ends the child as in a user's process, and a sanitizer report in the child ends only the child.
void child_without_fuzzer_handlers() {
  __sanitizer_set_death_callback(nullptr);
  for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE, SIGINT, SIGTERM, SIGXFSZ, SIGUSR1, SIGUSR2})
    std::signal(sig, SIG_DFL);
}

// Registered before main() runs the fuzzer, so that every fork of the process gets it.
[[maybe_unused]] const bool kChildHandlerRegistered = pthread_atfork(nullptr, nullptr, child_without_fuzzer_handlers) == 0;

}  // namespace

const fs::path& scratch_dir() {
  static const fs::path dir = [] {
    fs::path d = make_scratch_dir();
    std::atexit(remove_scratch_dir);
    return d;
  }();
  return dir;
}

void copy_seed_meshes() {
  for (const fs::directory_entry& e : fs::directory_iterator(SWEPT_FUZZ_DATA))
    if (e.is_regular_file())
      fs::copy_file(e.path(), scratch_dir() / e.path().filename(), fs::copy_options::overwrite_existing);
}

InputFile::InputFile(const std::uint8_t* data, std::size_t size, std::string_view extension) {
  // Inputs run one after another in a process; the counter keeps a name from being reused
  // while the reader of a previous input might still hold it (it never should).
  static unsigned long long counter = 0;
  path_ = scratch_dir() / ("input-" + std::to_string(counter++) + std::string(extension));
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "swept fuzz: cannot write %s\n", path_.c_str());
    std::abort();
  }
}

InputFile::~InputFile() {
  std::error_code ec;
  fs::remove(path_, ec);
}

}  // namespace swept::fuzz
