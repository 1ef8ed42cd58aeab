// A model's external references (glTF buffer and image uris, an OBJ's mtllib) are read only from
// the model's own folder and below: an absolute path elsewhere, a "../" climbing out of the folder
// or a URL is an error naming the reference (glTF), or, for materials we do not need (OBJ), never
// opened while the geometry loads.
#include "import_test_util.h"

#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

// One triangle (0,0,0), (1,0,0), (0,1,0) as 9 little-endian floats.
std::string triangle_bytes() {
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string out(sizeof v, '\0');
  std::memcpy(out.data(), v, sizeof v);
  return out;
}

std::string gltf_json(const std::string& uri) {
  return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":")" + uri +
         R"("}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,)"
         R"("count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
         R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
}

std::string glb(const std::string& json) {
  std::string chunk = json;
  while (chunk.size() % 4) chunk.push_back(' ');
  auto u32 = [](std::uint32_t v) {
    std::string s(4, '\0');
    for (int i = 0; i < 4; ++i) s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
    return s;
  };
  return "glTF" + u32(2) + u32(static_cast<std::uint32_t>(20 + chunk.size())) + u32(static_cast<std::uint32_t>(chunk.size())) +
         "JSON" + chunk;
}

TEST(ExternalReferences, GltfUrisOutsideTheModelFolderAreErrorsNamingThem) {
  const fs::path root = scratch_dir();
  fs::create_directories(root / "model");
  write_file(root / "secret.bin", triangle_bytes());
  const struct {
    std::string uri, says;
  } cases[] = {
      {"../secret.bin", "outside the model's folder"},
      {"%2E%2E/secret.bin", "outside the model's folder"},  // percent-encoded "..", as assimp decodes it
      {"sub/../../secret.bin", "outside the model's folder"},
      {"/etc/passwd", "outside the model's folder"},
      {"file:///etc/passwd", "is a URL"},
      {"http://example.com/x.bin", "is a URL"},
  };
  for (const auto& c : cases) {
    const fs::path file = write_file(root / "model" / "m.gltf", gltf_json(c.uri));
    expect_error(import_mesh(file), {file.string() + ": buffers[0].uri '" + c.uri + "' ", c.says});
    const fs::path binary = write_file(root / "model" / "m.glb", glb(gltf_json(c.uri)));
    expect_error(import_mesh(binary), {binary.string() + ": buffers[0].uri '" + c.uri + "' ", c.says});
  }
}

TEST(ExternalReferences, GltfWithABufferInItsFolderStillLoads) {
  const fs::path root = scratch_dir();
  fs::create_directories(root / "model" / "sub");
  write_file(root / "model" / "m.bin", triangle_bytes());
  write_file(root / "model" / "sub" / "geo.bin", triangle_bytes());
  for (const std::string uri : {"m.bin", "sub/geo.bin", "./sub/../m.bin"}) {
    const auto model = import_mesh(write_file(root / "model" / "m.gltf", gltf_json(uri)));
    ASSERT_TRUE(model) << uri << ": " << model.error().message;
    EXPECT_EQ(model->triangle_count(), 1u) << uri;
  }
}

// The OBJ's mtllib names a FIFO outside the model's folder: opening it for reading would block
// until a writer comes, so a watchdog tries to open it for writing without blocking, which
// succeeds only while a reader is waiting. It must never succeed; the geometry loads.
TEST(ExternalReferences, ObjMaterialLibraryOutsideTheFolderIsNeverOpened) {
  const fs::path root = scratch_dir();
  fs::create_directories(root / "model");
  const fs::path trap = root / "trap.mtl";
  ASSERT_EQ(::mkfifo(trap.c_str(), 0600), 0);
  const fs::path obj = write_file(root / "model" / "m.obj", "mtllib " + trap.string() + "\nmtllib ../trap.mtl\n"
                                                            "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
  std::atomic<bool> done{false}, opened{false};
  std::thread watchdog([&] {
    while (!done) {
      const int fd = ::open(trap.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) {
        opened = true;
        ::close(fd);  // the reader sees end of file and goes on
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  // In this process: forking while the watchdog thread runs can deadlock the child under
  // AddressSanitizer; the file system the reader is given is the same either way.
  ImportOptions here;
  here.isolate_readers = false;
  const auto model = import_mesh(obj, here);
  done = true;
  watchdog.join();
  EXPECT_FALSE(opened) << "the material library outside the model's folder was opened";
  ASSERT_TRUE(model) << model.error().message;
  EXPECT_EQ(model->triangle_count(), 1u);
}

}  // namespace
}  // namespace swept::test
