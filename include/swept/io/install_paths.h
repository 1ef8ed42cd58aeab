#pragma once
// Where a swept program finds its companion files (the CAD reader module, swept-tools): whether
// a folder lies in a given tree, such as the build tree a binary was built in.
#include <filesystem>
#include <string>

namespace swept {

/// True when `dir` is `root` or lies below it, compared folder by folder (`root` made canonical
/// first; both in normal form, without a trailing separator; `dir`'s symbolic links are not
/// resolved, so pass a canonical path). False when either is empty or `root` cannot be resolved.
bool path_inside(const std::filesystem::path& dir, const std::string& root);

}  // namespace swept
