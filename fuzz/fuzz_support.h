#pragma once
/// What every fuzz target shares: the readers take paths, so each input is written to a file
/// with the extension that selects the reader, in a scratch folder of this process.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace swept::fuzz {

/// This process's scratch folder (mkdtemp under $TMPDIR or /tmp), created on first use and
/// removed at normal exit. A crash leaves it behind, with the input that crashed in it.
const std::filesystem::path& scratch_dir();

/// Copies the small meshes of fuzz/data/ (tet.stl, tet.obj, ...) into scratch_dir(), so that
/// problem files written there can name them ("tet.stl") as their seed corpora do.
void copy_seed_meshes();

/// One input as a file: `bytes` written to a fresh, uniquely named file in scratch_dir() ending
/// in `extension` (".stl", ".toml", ...); removed again when this goes out of scope.
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, std::string_view extension);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace swept::fuzz
