// path_inside: the build-tree test by which swept and its companions (the CAD reader module,
// swept-tools) prefer their own build tree's files. The trailing-slash and ".." cases failed
// with the prefix comparison it replaced.
#include "swept/io/install_paths.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace swept {
namespace {

namespace fs = std::filesystem;

TEST(InstallPaths, AFolderIsInsideItsTreeAndNotInsideASiblingWithTheSamePrefix) {
  const fs::path tmp = fs::weakly_canonical(fs::temp_directory_path());
  const fs::path root = tmp / "swept_paths_root";
  EXPECT_TRUE(path_inside(root, root.string()));
  EXPECT_TRUE(path_inside(root / "apps" / "swept", root.string()));
  EXPECT_TRUE(path_inside(root / "apps", root.string() + "/"));  // a trailing slash in the root
  EXPECT_FALSE(path_inside(tmp / "swept_paths_root2" / "apps", root.string()));  // same prefix, another folder
  EXPECT_FALSE(path_inside(tmp, root.string()));
  EXPECT_FALSE(path_inside(root, ""));
  EXPECT_FALSE(path_inside(fs::path(), root.string()));
  // The root is made canonical: a root given through ".." still contains its folders.
  EXPECT_TRUE(path_inside(root / "bench", (root / "apps" / "..").string()));
  EXPECT_FALSE(path_inside(root / "..", root.string()));  // the folder is tidied too
  EXPECT_TRUE(path_inside(root / "apps" / "", root.string()));
  EXPECT_TRUE(path_inside(tmp, "/"));  // everything is inside the file system's root
}

}  // namespace
}  // namespace swept
