// write_file_atomically(): temporary file in the target's folder, fsync, close, rename.
#include "swept/io/file_write.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace swept {

namespace {

namespace fs = std::filesystem;

std::string reason(int err) { return std::generic_category().message(err); }

Error failure(const fs::path& file, const std::string& what, int err) {
  return Error{file.string() + ": " + what + ": " + reason(err)};
}

// Writes all of `bytes` to `fd`, retrying short writes and interrupted calls; 0 or the errno.
int write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

// Devices and pipes: no rename is possible, so the bytes go straight in, every step checked.
Result<bool> write_in_place(const fs::path& file, std::string_view bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return failure(file, "cannot open for writing", errno);
  if (const int err = write_all(fd, bytes); err != 0) {
    ::close(fd);
    return failure(file, "write failed", err);
  }
  if (::close(fd) != 0) return failure(file, "write failed on close", errno);
  return true;
}

}  // namespace

Result<bool> write_file_atomically(const fs::path& file, std::string_view bytes) {
  if (file.empty()) return Error{"cannot write a file with an empty name"};
  std::error_code ec;
  fs::path target = file;
  const fs::file_status status = fs::status(file, ec);  // follows symbolic links
  if (fs::exists(status)) {
    if (fs::is_directory(status)) return Error{file.string() + ": is a directory, not a file"};
    if (!fs::is_regular_file(status)) return write_in_place(file, bytes);
    if (fs::is_symlink(fs::symlink_status(file, ec))) {
      target = fs::canonical(file, ec);  // replace the link's target, keep the link
      if (ec) return Error{file.string() + ": cannot resolve the symbolic link: " + ec.message()};
    }
  }
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");

  // A fresh name in the target's folder (the rename must not cross file systems).
  static std::atomic<unsigned> counter{0};
  fs::path temp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = folder / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                     std::to_string(counter.fetch_add(1)));
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);  // the umask applies
    if (fd < 0 && errno != EEXIST) return failure(file, "cannot create a temporary file in '" + folder.string() + "'", errno);
  }
  if (fd < 0) return failure(file, "cannot create a temporary file in '" + folder.string() + "'", EEXIST);

  auto give_up = [&](const std::string& what, int err) {
    if (fd >= 0) ::close(fd);
    ::unlink(temp.c_str());
    return failure(file, what, err);
  };
  struct stat existing {};
  if (fs::is_regular_file(status) && ::stat(target.c_str(), &existing) == 0 &&
      ::fchmod(fd, existing.st_mode & 07777) != 0)
    return give_up("cannot keep the file's permissions", errno);
  if (const int err = write_all(fd, bytes); err != 0) return give_up("write failed", err);
  if (::fsync(fd) != 0) return give_up("write failed on flush", errno);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) return give_up("write failed on close", errno);
  if (::rename(temp.c_str(), target.c_str()) != 0) return give_up("cannot rename the temporary file into place", errno);
  return true;
}

}  // namespace swept
