// --snapshot-every: while a render runs (Markov chains or the per-pixel pass loop), the output file
// already holds a valid image of the render so far (written atomically), close to the final one.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_support.h"

using namespace relt;
using namespace relt::test;

class Snapshot : public ::testing::TestWithParam<std::string> {};

TEST_P(Snapshot, MidRenderImageIsAValidExrCloseToTheFinalOne) {
  const std::string dir = makeTempDir("snapshot-" + GetParam());
  const std::string out = dir + "/out.exr", early = dir + "/early.exr";
  // Start a 4 s render on 2 ranks, copy the first snapshot as soon as the output appears, then
  // wait for the end.
  const std::string render = mpirun(2) + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") + " -o " +
                             out + " --integrator " + GetParam() + " --time 4 --snapshot-every 0.5 --width 64 --height 64" +
                             " --stats " + dir + "/stats.json";
  const CommandResult r = runCommand("(" + render + ") & pid=$!; while [ ! -f " + out +
                                     " ] && kill -0 $pid 2>/dev/null; do sleep 0.05; done; cp " + out + " " + early +
                                     "; wait $pid");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_TRUE(fileExists(early));
  std::ifstream stats(dir + "/stats.json");
  const nlohmann::json j = nlohmann::json::parse(stats);
  EXPECT_GE(j["snapshots"].get<int>(), 1);  // the copy came from a snapshot, not the final write
  const Image snapshot = readExr(early), final = readExr(out);
  ASSERT_EQ(snapshot.width, 64);
  EXPECT_GT(snapshot.mean(), 0.0);
  EXPECT_NEAR(snapshot.mean(), final.mean(), 0.1 * final.mean());
}

INSTANTIATE_TEST_SUITE_P(Integrators, Snapshot, ::testing::Values("pssmlt", "relt", "pt", "bdpt", "erpt", "vcm", "meb"),
                         [](const auto& info) { return info.param; });
