// A failed rank ends the job with an error within seconds, never a hang: a rank killed with -9
// (Open MPI notices and ends the job), and a rank that stops responding (the other ranks' stall
// watchdog ends the job after --stall-timeout).
#include <gtest/gtest.h>

#include "test_support.h"

using namespace relt;
using namespace relt::test;

namespace {

// Starts a long render on 2 ranks, waits for its first progress line, sends `signal` to rank 1's
// process and waits for mpirun (at most 60 s, so a hang fails the test instead of blocking it).
SignalledRun renderAndHurtARank(const std::string& integrator, const std::string& signal, const std::string& extra) {
  const std::string dir = makeTempDir("rank-failure-" + integrator + "-" + signal);
  const std::string render = "timeout -s KILL 60 " + mpirun(2) + reltBinary() + " render " +
                             sourcePath("scenes/cornell-box.gltf") + " -o " + dir + "/out.exr --integrator " +
                             integrator + " --time 120 --width 64 --height 64 " + extra;
  const SignalledRun out = runAndSignal(render, dir + "/log.txt", signal, "^" + reltBinary() + " render .*" + dir);
  EXPECT_FALSE(fileExists(dir + "/out.exr")) << "no image from a failed job";
  return out;
}

}  // namespace

class RankFailure : public ::testing::TestWithParam<std::string> {};

TEST_P(RankFailure, KilledRankEndsTheJobWithAnErrorWithinTenSeconds) {
  const SignalledRun f = renderAndHurtARank(GetParam(), "KILL", "");
  EXPECT_NE(f.result.exitCode, 0) << f.result.output;
  EXPECT_GT(f.secondsAfterSignal, 0.0) << f.result.output;
  EXPECT_LT(f.secondsAfterSignal, 10.0) << f.result.output;
  EXPECT_NE(f.result.output.find("exited on signal 9"), std::string::npos) << f.result.output;
}

TEST_P(RankFailure, StalledRankEndsTheJobAfterTheStallTimeout) {
  const SignalledRun f = renderAndHurtARank(GetParam(), "STOP", "--stall-timeout 3");
  EXPECT_NE(f.result.exitCode, 0) << f.result.output;
  EXPECT_GT(f.secondsAfterSignal, 2.5) << f.result.output;
  EXPECT_LT(f.secondsAfterSignal, 10.0) << f.result.output;
  EXPECT_NE(f.result.output.find("waited 3 s for the other ranks"), std::string::npos) << f.result.output;
}

INSTANTIATE_TEST_SUITE_P(Integrators, RankFailure, ::testing::Values("relt", "pt"),
                         [](const auto& info) { return info.param; });
