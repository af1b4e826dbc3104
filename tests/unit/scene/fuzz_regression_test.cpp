// Every fuzz regression input (tests/data/fuzz) loads, or fails with the one-line InputError the
// command line prints with exit code 2, naming the file: never a crash, a hang or another
// exception. A scene that loads is also checked for renderability the same way.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "scene/gltf_loader.h"
#include "scene/scene_summary.h"
#include "test_support.h"

using namespace relt;

namespace {

std::vector<std::string> fuzzInputs() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(test::sourcePath("tests/data/fuzz")))
    if (e.path().extension() == ".gltf" || e.path().extension() == ".glb") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST(FuzzRegression, EveryInputLoadsOrFailsWithOneClearLine) {
  const std::vector<std::string> files = fuzzInputs();
  ASSERT_GE(files.size(), 100u);
  for (const std::string& file : files) {
    try {
      checkRenderable(loadGltf(file));
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file);
      EXPECT_FALSE(e.reason().empty()) << file;
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << file << ": " << e.what();
    }
  }
}
