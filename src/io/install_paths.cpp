#include "swept/io/install_paths.h"

#include <algorithm>
#include <system_error>

namespace swept {
namespace {

namespace fs = std::filesystem;

/// `p` in normal form without a trailing separator ("/a/b/" and "/a/c/../b" give "/a/b").
fs::path tidy(const fs::path& p) {
  fs::path n = p.lexically_normal();
  if (n.has_relative_path() && n.filename().empty()) n = n.parent_path();
  return n;
}

}  // namespace

bool path_inside(const fs::path& dir, const std::string& root) {
  if (root.empty() || dir.empty()) return false;
  std::error_code ec;
  const fs::path r = tidy(fs::weakly_canonical(fs::path(root), ec));
  if (ec) return false;
  const fs::path d = tidy(dir);
  // Element by element: "/a/bc" is not inside "/a/b".
  return std::mismatch(r.begin(), r.end(), d.begin(), d.end()).first == r.end();
}

}  // namespace swept
