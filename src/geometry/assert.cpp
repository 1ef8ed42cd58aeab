// The assert handler behind SWEPT_ASSERT (assert.h): print and abort unless replaced.
#include "swept/geometry/assert.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace swept {
namespace {

void print_and_abort(const char* condition, const char* message, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: swept assertion failed: %s (%s)\n", file, line, message, condition);
  std::fflush(stderr);
  std::abort();
}

std::atomic<AssertHandler> g_handler{&print_and_abort};

}  // namespace

AssertHandler set_assert_handler(AssertHandler handler) {
  return g_handler.exchange(handler ? handler : &print_and_abort);
}

void assert_failed(const char* condition, const char* message, const char* file, int line) {
  g_handler.load()(condition, message, file, line);
}

}  // namespace swept
