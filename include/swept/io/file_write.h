#pragma once
/// Writing output files whole or not at all.
#include "swept/geometry/result.h"

#include <filesystem>
#include <string_view>

namespace swept {

/// Writes `bytes` to `file` so that no reader ever sees a partial file and a failed write leaves
/// nothing behind: the bytes go to a new temporary file in the same folder (".NAME.tmp-PID-K",
/// created with the usual permissions, or the existing file's), which is flushed to disk, closed,
/// and only then renamed over `file` (a symbolic link is followed and its target replaced).
/// A target that exists but is not a regular file (a device such as /dev/stdout or /dev/full, a
/// pipe) cannot be replaced by a rename, so it is written in place and every write is checked.
/// Error (naming the file and the system's reason) for an empty path, a directory, a folder that
/// does not exist or cannot be written, or any failed write, flush, close or rename; the temporary
/// file is removed then.
Result<bool> write_file_atomically(const std::filesystem::path& file, std::string_view bytes);

}  // namespace swept
