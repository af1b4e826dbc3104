// A stop signal mid-render: every rank stops after the same round or pass, the image so far is
// written (normalised by the work actually done) with stats saying so, and the ranks exit 0.
// Open MPI's mpirun forwards SIGUSR1 and then returns the ranks' status; on SIGINT/SIGTERM it
// forwards the signal and ends with status 1 itself, so there only the outputs are checked.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_support.h"

using namespace relt;
using namespace relt::test;

namespace {

struct Interrupted : SignalledRun {
  std::string dir;
};

// Starts `render` (a command line writing `dir`/out.exr and stats.json), waits until its first
// progress line, sends `signal` to it and waits for the end.
Interrupted renderAndSignal(const std::string& render, const std::string& dir, const std::string& signal) {
  return {runAndSignal(render, dir + "/log.txt", signal), dir};
}

std::string renderCommand(const std::string& launcher, const std::string& integrator, const std::string& dir) {
  return launcher + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") + " -o " + dir +
         "/out.exr --integrator " + integrator + " --time 60 --width 64 --height 64 --stats " + dir + "/stats.json";
}

// The mean of cornell-box at 64x64 from an uninterrupted bdpt render.
double referenceMean() {
  static const double mean = [] {
    const std::string dir = makeTempDir("interrupt-reference");
    const CommandResult r = runCommand(reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") + " -o " +
                                       dir + "/ref.exr --integrator bdpt --spp 64 --width 64 --height 64 2>&1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return readExr(dir + "/ref.exr").mean();
  }();
  return mean;
}

// The outputs of an interrupted render: complete, finite, normalised by the work done.
void expectPartialImage(const Interrupted& run) {
  EXPECT_NE(run.result.output.find("stopped early by a signal"), std::string::npos) << run.result.output;
  EXPECT_LT(run.secondsAfterSignal, 10.0) << run.result.output;
  ASSERT_TRUE(fileExists(run.dir + "/out.exr")) << run.result.output;
  std::ifstream stats(run.dir + "/stats.json");
  const nlohmann::json j = nlohmann::json::parse(stats);
  EXPECT_TRUE(j["interrupted"].get<bool>());
  EXPECT_LT(j["render_seconds"].get<double>(), 30.0);
  const Image image = readExr(run.dir + "/out.exr");
  for (float v : image.rgb) ASSERT_TRUE(std::isfinite(v));
  EXPECT_NEAR(image.mean(), referenceMean(), 0.1 * referenceMean());
}

}  // namespace

class Interruption : public ::testing::TestWithParam<std::string> {};

TEST_P(Interruption, Sigusr1ToMpirunStopsEveryRankWritesTheImageSoFarAndExitsZero) {
  const std::string dir = makeTempDir("interrupt-usr1-" + GetParam());
  const Interrupted run = renderAndSignal(renderCommand(mpirun(2), GetParam(), dir), dir, "USR1");
  EXPECT_EQ(run.result.exitCode, 0) << run.result.output;
  expectPartialImage(run);
}

TEST_P(Interruption, SigtermToMpirunStillWritesTheImageSoFar) {
  const std::string dir = makeTempDir("interrupt-term-" + GetParam());
  const Interrupted run = renderAndSignal(renderCommand(mpirun(2), GetParam(), dir), dir, "TERM");
  expectPartialImage(run);  // mpirun's own status is 1 here (Open MPI), the ranks returned 0
}

TEST_P(Interruption, SigintToASingleProcessExitsZero) {
  const std::string dir = makeTempDir("interrupt-int-" + GetParam());
  const Interrupted run = renderAndSignal(renderCommand("", GetParam(), dir), dir, "INT");
  EXPECT_EQ(run.result.exitCode, 0) << run.result.output;
  expectPartialImage(run);
}

INSTANTIATE_TEST_SUITE_P(Integrators, Interruption, ::testing::Values("relt", "pt", "pssmlt"),
                         [](const auto& info) { return info.param; });
