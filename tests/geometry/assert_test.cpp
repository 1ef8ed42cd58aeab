// SWEPT_ASSERT and its handler (swept/geometry/assert.h).
#include "swept/geometry/assert.h"

#include <gtest/gtest.h>

#include <string>

namespace swept {
namespace {

int g_failures = 0;
std::string g_message;

void record(const char*, const char* message, const char*, int) {
  ++g_failures;
  g_message = message;
}

TEST(Assert, HandlerSeesFailuresWhenAssertsAreOn) {
  const AssertHandler previous = set_assert_handler(&record);
  g_failures = 0;
  SWEPT_ASSERT(1 + 1 == 2, "never reported");
  SWEPT_ASSERT(1 + 1 == 3, "arithmetic");
  set_assert_handler(previous);
#if SWEPT_ASSERTS_ENABLED
  EXPECT_EQ(g_failures, 1);
  EXPECT_EQ(g_message, "arithmetic");
#else
  EXPECT_EQ(g_failures, 0);  // compiled out in release builds
#endif
}

TEST(Assert, DefaultHandlerAborts) {
#if SWEPT_ASSERTS_ENABLED
  EXPECT_DEATH(SWEPT_ASSERT(false, "a broken precondition"), "a broken precondition");
#else
  GTEST_SKIP() << "asserts are compiled out in this build";
#endif
}

}  // namespace
}  // namespace swept
