// Every fuzz regression input (tests/data/fuzz) loads, or fails with the one-line InputError the
// command line prints with exit code 2, naming the file: never a crash, a hang or another
// exception. As in the fuzz harness, a scene that loads is rendered (one row, bdpt, 8 x 8) and
// its film must stay finite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "scene/gltf_loader.h"
#include "render/renderer.h"
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
      RenderSettings settings;
      settings.width = settings.height = 8;
      settings.maxDepth = 4;
      Renderer renderer(loadGltf(file), settings);
      Film film(8, 8);
      renderer.renderRow(RowEstimator::Bidirectional, 0, 3, film);
      for (double v : film.data()) ASSERT_TRUE(std::isfinite(v)) << file;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file);
      EXPECT_FALSE(e.reason().empty()) << file;
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << file << ": " << e.what();
    }
  }
}
