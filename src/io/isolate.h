#pragma once
// Internal to swept_io: running a third-party reader (assimp, OpenCASCADE) in a child process,
// so that what it does on a malformed file — a crash (OpenCASCADE dereferences null on some
// broken STEP, IGES and BREP entities), a failed assert, a hang (assimp on some broken COLLADA),
// a leak — ends the child, not the caller, and becomes an Error naming the file.
#include "swept/geometry/result.h"

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>

namespace swept::io_detail {

/// Limits of a reader's child process.
struct ChildLimits {
  double timeout_s = 600.0;       ///< killed after this long
  std::size_t memory_bytes = 0;   ///< address space past what it inherits (RLIMIT_AS); 0: none
  /// Appended to the messages of a child stopped by either limit (what the user can change).
  std::string advice;
};

/// Runs `work` in a forked child and returns the bytes it produced, or its Error. Errors name
/// `display` and `reader`: "the assimp reader crashed (signal 11) on this file, which is probably
/// malformed", "... did not finish within 600 s", "... ran out of memory: it used 2.1 GB of its
/// 2 GB limit". The child must not use oneTBB (its scheduler does not survive fork): readers run
/// single-threaded there. Not reentrant across threads that fork at the same time.
Result<std::string> run_isolated(const std::string& display, const std::string& reader, const ChildLimits& limits,
                                 const std::function<Result<std::string>()>& work);

/// `ImportOptions::reader_memory` resolved: itself; when 0, SWEPT_READER_MEMORY (gigabytes) if
/// set, else three quarters of the physical memory. An Error for a SWEPT_READER_MEMORY that is
/// not a positive number.
Result<std::size_t> reader_memory_bytes(std::size_t option);

/// Whether the child's memory limit is applied in this build (not under AddressSanitizer, whose
/// shadow memory is address space).
bool child_memory_limit_applies();

/// Little helpers to pack what a reader returns into bytes and back.
class ByteWriter {
 public:
  void u64(std::uint64_t v) { put(&v, sizeof v); }
  void f64(double v) { put(&v, sizeof v); }
  void str(const std::string& s) {
    u64(s.size());
    bytes_.append(s);
  }
  void put(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  bool u64(std::uint64_t& v) { return get(&v, sizeof v); }
  bool f64(double& v) { return get(&v, sizeof v); }
  bool str(std::string& s) {
    std::uint64_t n = 0;
    if (!u64(n) || n > bytes_.size() - at_) return false;
    s.assign(bytes_, at_, n);
    at_ += n;
    return true;
  }
  bool get(void* p, std::size_t n) {
    if (n > bytes_.size() - at_) return false;
    std::memcpy(p, bytes_.data() + at_, n);
    at_ += n;
    return true;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace swept::io_detail
