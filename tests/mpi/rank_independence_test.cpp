// The image depends on the seed and the sample count (and for Markov chains the chain count), not on
// the number of ranks (up to the order of floating-point sums): -np 1 and -np 2 agree to 1e-5.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_support.h"

using namespace relt;
using namespace relt::test;

namespace {

Image renderWithRanks(int ranks, const std::string& integrator, const std::string& dir,
                      const std::string& amount = "--spp 3", const std::string& scene = "cornell-box") {
  const std::string out = dir + "/np" + std::to_string(ranks) + "-" + integrator + ".exr";
  const CommandResult r = runCommand(mpirun(ranks) + reltBinary() + " render " + sourcePath("scenes/" + scene + ".gltf") +
                                     " -o " + out + " --integrator " + integrator + " " + amount +
                                     " --width 40 --height 30 --seed 5");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return readExr(out);
}

}  // namespace

TEST(RankIndependence, BdptImageIsTheSameOnOneAndTwoRanks) {
  const std::string dir = makeTempDir("mpi-bdpt");
  expectSameImage(renderWithRanks(1, "bdpt", dir), renderWithRanks(2, "bdpt", dir));
}

TEST(RankIndependence, PtImageIsTheSameOnOneAndTwoRanks) {
  const std::string dir = makeTempDir("mpi-pt");
  expectSameImage(renderWithRanks(1, "pt", dir), renderWithRanks(2, "pt", dir));
}

TEST(RankIndependence, PssmltImageIsTheSameOnOneAndTwoRanks) {
  // Chains are keyed by (seed, chain), so only the chain count matters; 7 chains split unevenly.
  const std::string dir = makeTempDir("mpi-pssmlt");
  const std::string amount = "--mutations-per-pixel 4 --chains 7";
  expectSameImage(renderWithRanks(1, "pssmlt", dir, amount), renderWithRanks(2, "pssmlt", dir, amount));
}

TEST(RankIndependence, MmltImageIsTheSameOnOneAndTwoRanks) {
  const std::string dir = makeTempDir("mpi-mmlt");
  const std::string amount = "--mutations-per-pixel 8 --chains 9";
  expectSameImage(renderWithRanks(1, "mmlt", dir, amount), renderWithRanks(2, "mmlt", dir, amount));
}

TEST(RankIndependence, ErptImageIsTheSameOnOneAndTwoRanks) {
  const std::string dir = makeTempDir("mpi-erpt");
  expectSameImage(renderWithRanks(1, "erpt", dir, "--spp 1 --chain-length 10"),
                  renderWithRanks(2, "erpt", dir, "--spp 1 --chain-length 10"));
}

TEST(RankIndependence, TimedRenderStopsEveryRankAtTheSamePass) {
  const std::string dir = makeTempDir("mpi-time");
  const CommandResult r = runCommand(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") +
                                     " -o " + dir + "/t.exr --stats " + dir + "/t.json --time 1 --width 32 --height 32");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fileExists(dir + "/t.exr"));
}

TEST(RankIndependence, ReltImageIsTheSameOnOneTwoAndFourRanksWithBothPlacements) {
  // 3 ladders of 5 levels: 15 chains split unevenly; exchanges are permutations, so every level's
  // label moves between ranks under spread placement.
  const std::string amount =
      "--mutations-per-pixel 4 --ladders 3 --family relaxed --levels 5 --exchange permutation --exchange-interval 4";
  const std::string spread = makeTempDir("mpi-relt-spread"), packed = makeTempDir("mpi-relt-packed");
  const Image reference = renderWithRanks(1, "relt", spread, amount);
  expectSameImage(reference, renderWithRanks(2, "relt", spread, amount));
  expectSameImage(reference, renderWithRanks(4, "relt", spread, amount));
  expectSameImage(reference, renderWithRanks(2, "relt", packed, amount + " --placement packed"));
  expectSameImage(reference, renderWithRanks(4, "relt", packed, amount + " --placement packed"));
}

TEST(RankIndependence, ReltMovesChainsToTheFasterRankWithoutChangingTheImage) {
  // Rank 1 shares its core with two busy loops, so it steps at about a third of its speed: load
  // balancing moves chains mid-render (single chains with spread placement, whole ladders with
  // packed; states travel between the processes), and the image stays the one-rank image. (Which
  // way they go depends on what else the machine runs meanwhile; the direction is checked in the
  // unit tests of the pool.)
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "needs two cores";
  for (const std::string placement : {"spread", "packed"}) {
    const std::string dir = makeTempDir("mpi-relt-balance-" + placement);
    const std::string amount = "--mutations-per-pixel 256 --ladders 8 --family relaxed --levels 5 --exchange permutation "
                               "--exchange-interval 4 --balance-window 0.05 --placement " + placement;
    const Image reference = renderWithRanks(1, "relt", dir, amount);
    const std::string args = " render " + sourcePath("scenes/cornell-box.gltf") + " -o " + dir + "/uneven.exr --stats " +
                             dir + "/uneven.json --integrator relt " + amount + " --width 40 --height 30 --seed 5";
    const std::string slowRank =
        "sh -c 'timeout 120 taskset -c 1 yes >/dev/null & a=$!; timeout 120 taskset -c 1 yes >/dev/null & b=$!; "
        "taskset -c 1 " + reltBinary() + args + "; status=$?; kill $a $b; exit $status'";
    const std::string launcher = mpirun(1);  // "... -np 1 ": rank 0 alone on core 0, then rank 1 (MPMD)
    const CommandResult r =
        runCommand(launcher.substr(0, launcher.find("-np")) + "--bind-to none -np 1 taskset -c 0 " + reltBinary() +
                   args + " : -np 1 " + slowRank);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream stats(dir + "/uneven.json");
    const nlohmann::json j = nlohmann::json::parse(stats)["relt"];
    EXPECT_EQ(j["placement"], placement);
    EXPECT_GT(j["chain_moves"].get<int>(), 0) << placement;
    expectSameImage(reference, readExr(dir + "/uneven.exr"));
  }
}

TEST(RankIndependence, ReltWithPopulationAnnealingIsTheSameOnOneAndTwoRanks) {
  // Every rank anneals all particles with the same keys, then takes its chains' starts from them.
  const std::string dir = makeTempDir("mpi-relt-annealing");
  const std::string amount = "--mutations-per-pixel 2 --ladders 2 --family relaxed --levels 4 --init annealing";
  expectSameImage(renderWithRanks(1, "relt", dir, amount), renderWithRanks(2, "relt", dir, amount));
}

TEST(RankIndependence, ReltTemperedWithRegularisationIsTheSameOnOneAndTwoRanks) {
  // ring's mirrors make the tempered levels differ; the fast regularisation decay moves the targets
  // during the render, so every rank re-evaluates its states and restarts the normalisers together.
  const std::string dir = makeTempDir("mpi-relt-tempered");
  const std::string amount =
      "--mutations-per-pixel 4 --ladders 2 --family tempered --levels 4 --regularisation 0.05 --regularisation-decay 0.2";
  expectSameImage(renderWithRanks(1, "relt", dir, amount, "ring"), renderWithRanks(2, "relt", dir, amount, "ring"));
}

TEST(RankIndependence, ReltPerLevelLayersSumToTheImage) {
  const std::string dir = makeTempDir("mpi-relt-layers");
  const Image image =
      renderWithRanks(2, "relt", dir, "--mutations-per-pixel 4 --ladders 2 --family kitaoka --per-level --direct-emission-spp 0");
  const std::string path = dir + "/np2-relt.exr";
  Image sum(image.width, image.height);
  for (int k = 0; k < 3; ++k) {
    const Image layer = readExr(path, "level" + std::to_string(k));
    for (size_t i = 0; i < sum.rgb.size(); ++i) sum.rgb[i] += layer.rgb[i];
  }
  expectSameImage(image, sum);
  EXPECT_THROW(readExr(path, "level3"), std::exception)
      << "kitaoka's four levels less the specific one: cornell-box has no implicit path after a specular bounce";
}

// With the emission seen directly or in specular surfaces estimated apart (rows split over ranks),
// pssmlt, relt, vcm and meb still give the same image on one and two ranks (mirror-balls for vcm
// and meb: emission in the mirrors), and relt's layers (levels plus "direct") sum to it.
TEST(RankIndependence, DirectEmissionApartIsTheSameOnOneAndTwoRanks) {
  const std::string dir = makeTempDir("mpi-direct");
  const std::string pss = "--mutations-per-pixel 4 --chains 7 --direct-emission-spp 9";
  expectSameImage(renderWithRanks(1, "pssmlt", dir, pss), renderWithRanks(2, "pssmlt", dir, pss));
  for (const std::string integrator : {"vcm", "meb"}) {
    const std::string args = "--spp 3 --direct-emission-spp 9";
    expectSameImage(renderWithRanks(1, integrator, dir, args, "mirror-balls"), renderWithRanks(2, integrator, dir, args, "mirror-balls"));
  }
  const std::string relt = "--mutations-per-pixel 4 --ladders 2 --family kitaoka --per-level --direct-emission-spp 9";
  const Image one = renderWithRanks(1, "relt", dir, relt);
  const Image two = renderWithRanks(2, "relt", dir, relt);
  expectSameImage(one, two);
  const std::string path = dir + "/np2-relt.exr";
  Image sum(two.width, two.height);
  for (const std::string layer : {"level0", "level1", "level2", "direct"}) {  // the specific level left out
    const Image l = readExr(path, layer);
    for (size_t i = 0; i < sum.rgb.size(); ++i) sum.rgb[i] += l.rgb[i];
  }
  expectSameImage(two, sum);
}

// furnace (every pixel Le (1 - a^D) / (1 - a), scenes/README.md) with the directly seen emission
// apart: the chains' longer paths and the separate estimate add up to the analytic value.
TEST(DirectEmission, FurnaceMatchesTheAnalyticValueWithinOnePercent) {
  const std::string dir = makeTempDir("direct-furnace");
  const double expected = 1.0 * (1.0 - std::pow(0.5, 8)) / (1.0 - 0.5);
  for (const std::string integrator : {"pssmlt", "relt"}) {
    const std::string out = dir + "/" + integrator + ".exr";
    const CommandResult r = runCommand(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/furnace.gltf") + " -o " +
                                       out + " --integrator " + integrator +
                                       " --mutations-per-pixel 16 --width 32 --height 32 --seed 7 --direct-emission-spp 4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NEAR(readExr(out).mean(), expected, 0.01 * expected) << integrator;
  }
}

// Nor on the worker threads of a rank: -np 1 --threads 2 (and 3, which deals rows and chains
// unevenly) and -np 2 --threads 1 give the image of -np 1 --threads 1 for every integrator; the
// stats say how many ran.
TEST(ThreadIndependence, EveryIntegratorsImageIsTheSameOnAnySplitOfRanksAndThreads) {
  struct Case {
    std::string integrator, amount;
  };
  const std::string relt =
      "--mutations-per-pixel 4 --ladders 3 --family relaxed --levels 5 --exchange permutation --exchange-interval 4";
  for (const Case& c : {Case{"pt", "--spp 3"}, Case{"bdpt", "--spp 3"}, Case{"erpt", "--spp 1 --chain-length 10"},
                        Case{"pssmlt", "--mutations-per-pixel 4 --chains 7"},
                        Case{"mmlt", "--mutations-per-pixel 8 --chains 9"}, Case{"relt", relt},
                        Case{"vcm", "--spp 3"}, Case{"meb", "--spp 3 --meb-pairs 5"}}) {
    SCOPED_TRACE(c.integrator);
    const std::string dir = makeTempDir("threads-" + c.integrator);
    const Image one = renderWithRanks(1, c.integrator, dir, c.amount + " --threads 1");
    expectSameImage(one, renderWithRanks(2, c.integrator, dir, c.amount + " --threads 1"));
    for (int threads : {2, 3}) {
      const std::string stats = dir + "/t" + std::to_string(threads) + ".json";
      expectSameImage(one, renderWithRanks(1, c.integrator, dir,
                                           c.amount + " --threads " + std::to_string(threads) + " --stats " + stats));
      EXPECT_EQ(nlohmann::json::parse(std::ifstream(stats))["settings"]["threads"].get<int>(), threads);
    }
  }
}

// The chain integrators' workers take chains as they come free but add each chain's splats in
// chain order, so on one rank the thread count changes no bit of the image.
TEST(ThreadIndependence, AChainIntegratorsImageIsBitForBitTheSameOnAnyNumberOfThreads) {
  struct Case {
    std::string integrator, amount;
  };
  for (const Case& c : {Case{"pssmlt", "--mutations-per-pixel 4 --chains 7"},
                        Case{"mmlt", "--mutations-per-pixel 8 --chains 9"},
                        Case{"relt", "--mutations-per-pixel 4 --ladders 3 --family tempered --levels 3"}}) {
    SCOPED_TRACE(c.integrator);
    const std::string dir = makeTempDir("threads-exact-" + c.integrator);
    const Image one = renderWithRanks(1, c.integrator, dir, c.amount + " --threads 1");
    EXPECT_GT(one.mean(), 0.0);
    for (int threads : {2, 3})
      EXPECT_TRUE(one.rgb == renderWithRanks(1, c.integrator, dir, c.amount + " --threads " + std::to_string(threads)).rgb)
          << threads << " threads";
  }
}

// A checkpoint of a render on two threads holds every worker's sums: resumed for more work, it
// gives the image of the render that never stopped (bdpt: passes; mmlt: per-depth films; relt:
// chains whose splats were in the second worker's films at the checkpoint).
TEST(ThreadIndependence, ACheckpointOfTwoThreadsResumesToTheUninterruptedImage) {
  struct Case {
    std::string integrator, whole, half;
  };
  const std::string relt = " --ladders 3 --family relaxed --levels 5 --exchange-interval 4 ";
  for (const Case& c : {Case{"bdpt", "--spp 4", "--spp 2"},
                        Case{"mmlt", "--chains 48 --mutations-per-pixel 8", "--chains 48 --mutations-per-pixel 4"},
                        Case{"relt", relt + "--mutations-per-pixel 8", relt + "--mutations-per-pixel 4"}}) {
    SCOPED_TRACE(c.integrator);
    const std::string dir = makeTempDir("threads-checkpoint-" + c.integrator);
    const std::string scene = sourcePath("scenes/cornell-box.gltf"),
                      common = " --integrator " + c.integrator + " --width 40 --height 30 --seed 5 --threads 2 ";
    auto render = [&](const std::string& args) {
      const CommandResult r = runCommand(mpirun(1) + reltBinary() + " render " + scene + common + args);
      EXPECT_EQ(r.exitCode, 0) << r.output;
    };
    render("-o " + dir + "/whole.exr " + c.whole);
    render("-o " + dir + "/half.exr " + c.half + " --checkpoint " + dir + "/ck");
    render("-o " + dir + "/resumed.exr " + c.whole + " --resume " + dir + "/ck");
    expectSameImage(readExr(dir + "/whole.exr"), readExr(dir + "/resumed.exr"));
  }
}
