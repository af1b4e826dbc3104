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

std::string renderCommand(const std::string& launcher, const std::string& integrator, const std::string& dir,
                          const std::string& size = "--width 64 --height 64") {
  return launcher + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") + " -o " + dir +
         "/out.exr --integrator " + integrator + " --time 60 " + size + " --stats " + dir + "/stats.json";
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

namespace {

// Seconds from SIGTERM to mpirun until the image (and with `checkpoint` the checkpoint) exist.
// mpirun sends the ranks SIGCONT at once, SIGTERM a second later and SIGKILL a second after that.
// The signal goes after the first progress line of `progress` (the render's own, or the
// direct-emission pass's, which comes first in relt and pssmlt).
double secondsUntilWritten(const std::string& integrator, bool checkpoint, const std::string& more = "",
                           const std::string& size = "--width 64 --height 64",
                           const std::string& progress = kRenderProgress) {
  const std::string dir = makeTempDir("interrupt-latency-" + integrator);
  std::string render = renderCommand(mpirun(2), integrator, dir, size) + more;
  if (checkpoint) render += " --checkpoint " + dir + "/ck";
  const std::string wanted = "[ -e " + dir + "/out.exr ]" + (checkpoint ? " && [ -e " + dir + "/ck/checkpoint.relt ]" : "");
  const std::string script = "(" + render + ") > " + dir + "/log.txt 2>&1 & pid=$!; " +
                             "for i in $(seq 300); do grep -qE '" + progress + "' " + dir + "/log.txt && break; sleep 0.05; done; " +
                             "t0=$(date +%s.%N); kill -TERM $pid; " +
                             "for i in $(seq 1000); do " + wanted + " && break; sleep 0.005; done; " +
                             "echo \"seconds $(echo \"$(date +%s.%N) - $t0\" | bc)\"; wait $pid; cat " + dir + "/log.txt";
  const CommandResult r = runCommand(script);
  const size_t at = r.output.find("seconds ");
  EXPECT_NE(at, std::string::npos) << r.output;
  return at == std::string::npos ? 1e9 : std::stod(r.output.substr(at + 8));
}

}  // namespace

// A batch system's or mpirun's stop leaves a rank one second between SIGTERM and SIGKILL, but
// mpirun sends SIGCONT a second before SIGTERM: on it the ranks write the image so far and a
// checkpoint after the next round or chunk of a pass, well within 0.8 s of the signal to mpirun;
// also inside a long pass (bdpt at 768 x 768: about 0.9 s a pass on 2 ranks), with packed
// placement, and in pssmlt's and relt's direct-emission pass (here 2^20 rays per pixel: minutes),
// before any chain.
TEST(InterruptionLatency, AfterSigtermToMpirunTheImageAndCheckpointAreWrittenWithin08Seconds) {
  for (const char* integrator : {"relt", "pt", "bdpt", "pssmlt", "mmlt", "erpt", "vcm", "meb"})
    EXPECT_LT(secondsUntilWritten(integrator, true), 0.8) << integrator;
  EXPECT_LT(secondsUntilWritten("bdpt", true, "", "--width 768 --height 768"), 0.8) << "bdpt inside a long pass";
  // Packed placement reads its messages back 256 rounds late here (a long render's lag; 2 s at
  // these rounds of 256 steps a chain): the request travels apart from them.
  EXPECT_LT(secondsUntilWritten("relt", true,
                                " --placement packed --ladders 4 --normaliser-lag 256 --normaliser-lag-growth 0 "
                                "--exchange-interval 256"),
            0.8)
      << "relt, packed";
  for (const char* integrator : {"relt", "pssmlt"})
    EXPECT_LT(secondsUntilWritten(integrator, true, " --direct-emission-spp 1048576", "--width 64 --height 64",
                                  kDirectPassProgress),
              0.8)
        << integrator << " in the pass";
}
