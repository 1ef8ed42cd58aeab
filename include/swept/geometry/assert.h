#pragma once
/// SWEPT_ASSERT: checks of programmer errors (a broken precondition, an impossible state), on in
/// debug builds (`!NDEBUG`) and in the sanitizer build (`SWEPT_SANITIZE`), compiled out in
/// release builds. Bad input — files, configurations, NaN coordinates — is never asserted: it is
/// reported as an `Error` (result.h).
///
/// A failed check calls the assert handler: by default it prints the condition, the message and
/// the place to stderr and aborts. Tests and embedding applications may install their own
/// (Jolt's `AssertFailed` hook is the model); a handler that returns lets the caller carry on with
/// its documented fallback.

namespace swept {

/// Called with the failed condition's text, the message, the file and the line.
using AssertHandler = void (*)(const char* condition, const char* message, const char* file, int line);

/// Installs `handler` (nullptr: the default, print and abort) and returns the one it replaces.
/// Safe to call from any thread.
AssertHandler set_assert_handler(AssertHandler handler);

/// Reports a failed SWEPT_ASSERT to the installed handler.
void assert_failed(const char* condition, const char* message, const char* file, int line);

}  // namespace swept

#if !defined(NDEBUG) || defined(SWEPT_SANITIZE)
#define SWEPT_ASSERTS_ENABLED 1
#define SWEPT_ASSERT(condition, message)                                    \
  do {                                                                      \
    if (!(condition)) ::swept::assert_failed(#condition, message, __FILE__, __LINE__); \
  } while (false)
#else
#define SWEPT_ASSERTS_ENABLED 0
#define SWEPT_ASSERT(condition, message) \
  do {                                   \
    (void)sizeof((condition) ? 1 : 0);   \
  } while (false)
#endif
