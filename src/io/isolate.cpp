// Third-party readers in a child process (see isolate.h).
#include "isolate.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace swept::io_detail {
namespace {

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// This process's address space and resident memory, in bytes (/proc/self/statm); 0, 0 when
// unreadable.
std::pair<std::size_t, std::size_t> own_memory() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return {0, 0};
  unsigned long size = 0, resident = 0;
  const int got = std::fscanf(f, "%lu %lu", &size, &resident);
  std::fclose(f);
  if (got != 2) return {0, 0};
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  return {size * page, resident * page};
}

// The largest address space this process has had, in bytes (VmPeak of /proc/self/status); 0 when
// unreadable.
std::size_t peak_address_space() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (f == nullptr) return 0;
  char line[256];
  unsigned long kb = 0;
  while (std::fgets(line, sizeof line, f) != nullptr)
    if (std::sscanf(line, "VmPeak: %lu kB", &kb) == 1) break;
  std::fclose(f);
  return static_cast<std::size_t>(kb) * 1024;
}

// "2.1 GB", or "150 MB" below a gigabyte.
std::string gigabytes(double bytes) {
  char buf[32];
  const double mb = bytes / (1024.0 * 1024.0);
  if (mb < 1024.0)
    std::snprintf(buf, sizeof buf, "%.0f MB", mb);
  else
    std::snprintf(buf, sizeof buf, "%.1f GB", mb / 1024.0);
  return buf;
}

std::string out_of_memory(const std::string& display, const std::string& reader, double used, const ChildLimits& limits) {
  return display + ": the " + reader + " reader ran out of memory on this file: it used " + gigabytes(used) + " of its " +
         gigabytes(static_cast<double>(limits.memory_bytes)) + " limit (SWEPT_READER_MEMORY=GB raises it)" + limits.advice;
}

}  // namespace

bool child_memory_limit_applies() {
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

Result<std::size_t> reader_memory_bytes(std::size_t option) {
  if (option > 0) return option;
  if (const char* env = std::getenv("SWEPT_READER_MEMORY"); env != nullptr) {
    char* end = nullptr;
    const double gb = std::strtod(env, &end);
    if (end == env || *end != '\0' || !(gb > 0.0) || !(gb < 1e9))
      return Error{std::string("SWEPT_READER_MEMORY='") + env + "': not a positive number of gigabytes"};
    return static_cast<std::size_t>(gb * 1024.0 * 1024.0 * 1024.0);
  }
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::size_t{0};
  return static_cast<std::size_t>(pages) / 4 * 3 * static_cast<std::size_t>(page);
}

Result<std::string> run_isolated(const std::string& display, const std::string& reader, const ChildLimits& limits,
                                 const std::function<Result<std::string>()>& work) {
  const double timeout_s = limits.timeout_s;
  // What the child starts with (its pages are the parent's until written): its growth past this
  // is what the reader took.
  const auto [start_size, start_resident] = own_memory();
  const bool limit_memory = limits.memory_bytes > 0 && start_size > 0 && child_memory_limit_applies();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return Error{display + ": cannot create a pipe for the " + reader + " reader: " + std::strerror(errno)};
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return Error{display + ": cannot start the " + reader + " reader: " + std::strerror(errno)};
  }
  if (pid == 0) {
    // The child: one status byte ('1' bytes / '0' message), then the payload. _exit: no atexit
    // handlers, no leak report for what the reader left behind.
    ::close(fds[0]);
    if (limit_memory) {
      // Past the limit, allocations fail: std::bad_alloc, OCCT's Standard_OutOfMemory, a reader
      // that catches them and goes on without, or a crash of code that does not check.
      const rlimit lim{start_size + limits.memory_bytes, start_size + limits.memory_bytes};
      ::setrlimit(RLIMIT_AS, &lim);
    }
    std::string out;
    try {
      Result<std::string> r = work();
      out.push_back(r ? '1' : '0');
      out.append(r ? *r : r.error().message);
    } catch (const std::exception& e) {
      out = "0";
      out.append(display).append(": the ").append(reader).append(" reader failed: ").append(e.what());
    } catch (...) {
      out = "0";
      out.append(display).append(": the ").append(reader).append(" reader failed with an unknown exception");
    }
    // Within a tenth of the limit, allocations may have failed where the reader caught them
    // (BRepMesh then leaves the face out, a quieter loss): whatever came of the read, the limit
    // is the answer. (A child that crashed writes nothing: the parent judges by its memory.)
    const std::size_t peak = limit_memory ? peak_address_space() : 0;
    if (peak > start_size && static_cast<double>(peak - start_size) > 0.9 * static_cast<double>(limits.memory_bytes))
      out = "0" + out_of_memory(display, reader, static_cast<double>(peak - start_size), limits);
    const bool ok = write_all(fds[1], out.data(), out.size());
    ::_exit(ok ? 0 : 3);
  }
  ::close(fds[1]);
  std::string bytes;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  char buf[1 << 16];
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min(left * 1000.0 + 1.0, 60000.0)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of the child's output
    bytes.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    return Error{display + ": the " + reader + " reader did not finish within " + std::to_string(static_cast<long>(timeout_s)) +
                 " s on this file (stopped); it is probably malformed" + limits.advice};
  }
  // Ended without a word (a crash, or killed) after growing near its memory limit: the limit is
  // the reason, whatever the end looked like.
  const double used = 1024.0 * static_cast<double>(usage.ru_maxrss) - static_cast<double>(start_resident);
  if (limit_memory && bytes.empty() && used > 0.75 * static_cast<double>(limits.memory_bytes))
    return Error{out_of_memory(display, reader, used, limits)};
  if (WIFSIGNALED(status)) {
    return Error{display + ": the " + reader + " reader crashed (signal " + std::to_string(WTERMSIG(status)) +
                 ") on this file, which is probably malformed"};
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty()) {
    return Error{display + ": the " + reader + " reader stopped abnormally (exit status " +
                 std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ") on this file, which is probably malformed"};
  }
  const bool ok = bytes[0] == '1';
  bytes.erase(0, 1);
  if (!ok) return Error{std::move(bytes)};
  return bytes;
}

}  // namespace swept::io_detail
