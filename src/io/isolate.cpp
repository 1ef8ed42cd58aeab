// Third-party readers in a child process (see isolate.h).
#include "isolate.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
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

}  // namespace

Result<std::string> run_isolated(const std::string& display, const std::string& reader, double timeout_s,
                                 const std::function<Result<std::string>()>& work) {
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
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    return Error{display + ": the " + reader + " reader did not finish within " + std::to_string(static_cast<long>(timeout_s)) +
                 " s on this file (stopped); it is probably malformed"};
  }
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
