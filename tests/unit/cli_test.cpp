// The command line contract (DESIGN §6): bad options and bad input give one clear message on
// stderr, exit code 2, and no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_support.h"

using namespace relt::test;

namespace {

const std::string kScene = sourcePath("scenes/cornell-box.gltf");

struct BadInvocation {
  const char* name;
  std::string args;
  const char* mentions;
};

int lineCount(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

class CliRejects : public ::testing::TestWithParam<BadInvocation> {};

TEST_P(CliRejects, WithOneLineAndExitCode2AndNoOutput) {
  const std::string dir = makeTempDir("cli");
  const std::string out = dir + "/out.exr";
  std::string args = GetParam().args;
  for (size_t p; (p = args.find("OUT")) != std::string::npos;) args.replace(p, 3, out);
  const CommandResult r = runCommand(reltBinary() + " " + args);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find(GetParam().mentions), std::string::npos) << r.output;
  EXPECT_FALSE(fileExists(out));
}

INSTANTIATE_TEST_SUITE_P(
    BadOptions, CliRejects,
    ::testing::Values(BadInvocation{"NoSubcommand", "", "subcommand"},
                      BadInvocation{"UnknownSubcommand", "foo", "unknown command 'foo'"},
                      BadInvocation{"NegativeTime", "render " + kScene + " -o OUT --time -1", "--time: must be a number > 0, got -1 ("},
                      BadInvocation{"InfiniteTime", "render " + kScene + " -o OUT --time inf", "must be a number > 0"},
                      BadInvocation{"KelemenWeightsRemoved", "render " + kScene + " -o OUT --integrator pssmlt --kelemen-weights", "kelemen-weights"},
                      BadInvocation{"UnknownOption", "render " + kScene + " -o OUT --bogus 1", "bogus"},
                      BadInvocation{"MissingOutput", "render " + kScene, "output"},
                      BadInvocation{"UnknownOutputFormat", "render " + kScene + " -o OUT.tiff", "unknown image format"},
                      BadInvocation{"PngPreviewNotPng", "render " + kScene + " -o OUT --png OUT.jpg", "--png"},
                      BadInvocation{"LayersInAPng", "render " + kScene + " -o OUT.png --integrator relt --per-level", "EXR layers"},
                      BadInvocation{"SppWithPssmlt", "render " + kScene + " -o OUT --integrator pssmlt --spp 4", "mutations-per-pixel"},
                      BadInvocation{"MutationsWithBdpt", "render " + kScene + " -o OUT --mutations-per-pixel 4", "pssmlt"},
                      BadInvocation{"ZeroChains", "render " + kScene + " -o OUT --integrator pssmlt --chains 0", "chains"},
                      BadInvocation{"ZeroChainLength", "render " + kScene + " -o OUT --integrator erpt --chain-length 0", "chain-length"},
                      BadInvocation{"DirectEmissionWithMmlt", "render " + kScene + " -o OUT --integrator mmlt --direct-emission-spp 16", "--direct-emission-spp: only for --integrator pssmlt, relt, vcm and meb"},
                      BadInvocation{"NegativeDirectEmissionSpp", "render " + kScene + " -o OUT --integrator pssmlt --direct-emission-spp -1", "direct-emission-spp"},
                      BadInvocation{"WordForDirectEmissionSpp", "render " + kScene + " -o OUT --integrator relt --direct-emission-spp often", "direct-emission-spp"},
                      BadInvocation{"SmallStepsOutOfOrder", "render " + kScene + " -o OUT --integrator pssmlt --small-step-min 0.1 --small-step-max 0.01", "small-step"},
                      BadInvocation{"LargeStepProbabilityAboveOne", "render " + kScene + " -o OUT --integrator pssmlt --large-step-probability 1.5", "large-step-probability"},
                      BadInvocation{"ErptFilterWithBdpt", "render " + kScene + " -o OUT --erpt-proposal-filter", "--erpt-proposal-filter: only for --integrator erpt"},
                      BadInvocation{"ChainsWithPt", "render " + kScene + " -o OUT --integrator pt --chains 4", "--chains: only for --integrator pssmlt and mmlt"},
                      BadInvocation{"ChainLengthWithBdpt", "render " + kScene + " -o OUT --chain-length 50", "--chain-length: only for --integrator erpt"},
                      BadInvocation{"SmallStepWithPt", "render " + kScene + " -o OUT --integrator pt --small-step-min 0.01", "--small-step-min: only for"},
                      BadInvocation{"LargeStepWithErpt", "render " + kScene + " -o OUT --integrator erpt --large-step-probability 0.5", "--large-step-probability: only for"},
                      BadInvocation{"DirectEmissionOffWithBdpt", "render " + kScene + " -o OUT --direct-emission-spp 0", "--direct-emission-spp: only for"},
                      BadInvocation{"TraceWithPssmlt", "render " + kScene + " -o OUT --integrator pssmlt --trace OUT.json", "--trace: only for --integrator relt"},
                      BadInvocation{"NegativeSeed", "render " + kScene + " -o OUT --seed -1", "--seed: must be an integer"},
                      BadInvocation{"SeedBeyond64Bits", "render " + kScene + " -o OUT --seed 18446744073709551616", "--seed: must be an integer"},
                      BadInvocation{"NanExposure", "render " + kScene + " -o OUT --exposure nan", "--exposure: must be a number"},
                      BadInvocation{"HugeExposure", "render " + kScene + " -o OUT --exposure 1e30", "--exposure: must be a number"},
                      BadInvocation{"LaddersWithBdpt", "render " + kScene + " -o OUT --ladders 4", "only for --integrator relt"},
                      BadInvocation{"ChainsWithRelt", "render " + kScene + " -o OUT --integrator relt --chains 8", "--ladders"},
                      BadInvocation{"ZeroNormaliserLag", "render " + kScene + " -o OUT --integrator relt --normaliser-lag 0", "normaliser-lag"},
                      BadInvocation{"NormaliserLagWithPssmlt", "render " + kScene + " -o OUT --integrator pssmlt --normaliser-lag 2", "only for --integrator relt"},
                      BadInvocation{"NormaliserLagGrowthWithPssmlt", "render " + kScene + " -o OUT --integrator pssmlt --normaliser-lag-growth 2", "only for --integrator relt"},
                      BadInvocation{"TemperatureMaxWithKitaoka", "render " + kScene + " -o OUT --integrator relt --temperature-max 100", "only for --family tempered"},
                      BadInvocation{"RelaxedEpsWithTempered", "render " + kScene + " -o OUT --integrator relt --family tempered --relaxed-eps 0.1", "only for --family relaxed"},
                      BadInvocation{"LevelsWithKitaoka", "render " + kScene + " -o OUT --integrator relt --family kitaoka --levels 6", "kitaoka"},
                      BadInvocation{"UnknownFamily", "render " + kScene + " -o OUT --integrator relt --family warm", "warm"},
                      BadInvocation{"UnknownExchange", "render " + kScene + " -o OUT --integrator relt --exchange shuffle", "shuffle"},
                      BadInvocation{"PermutationBeyondTwelveLevels", "render " + kScene + " -o OUT --integrator relt --family relaxed --levels 13 --exchange permutation", "at most 12"},
                      BadInvocation{"UnknownInit", "render " + kScene + " -o OUT --integrator relt --init warm", "warm"},
                      BadInvocation{"OneLevel", "render " + kScene + " -o OUT --integrator relt --levels 1", "levels"},
                      BadInvocation{"MissingScene", "render /nonexistent.gltf -o OUT", "nonexistent"},
                      BadInvocation{"UnknownIntegrator", "render " + kScene + " -o OUT --integrator magic", "magic"},
                      BadInvocation{"NegativeSpp", "render " + kScene + " -o OUT --spp -3", "spp"},
                      BadInvocation{"SppAndTime", "render " + kScene + " -o OUT --spp 4 --time 2", "time"},
                      BadInvocation{"ZeroWidth", "render " + kScene + " -o OUT --width 0", "width"},
                      BadInvocation{"HugeWidth", "render " + kScene + " -o OUT --width 16385", "width"},
                      BadInvocation{"CheckpointEveryAlone", "render " + kScene + " -o OUT --checkpoint-every 5", "--checkpoint"},
                      BadInvocation{"HugeDepth", "render " + kScene + " -o OUT --max-depth 100000", "max-depth"},
                      BadInvocation{"UnknownCamera", "render " + kScene + " -o OUT --camera nope --spp 1", "nope"},
                      BadInvocation{"UnwritableOutput", "render " + kScene + " -o /nonexistent-dir/x.exr --spp 1",
                                    "nonexistent-dir"},
                      BadInvocation{"InvalidScene",
                                    "render " + sourcePath("tests/data/gltf/invalid/validator/json/invalid_syntax.gltf") +
                                        " -o OUT --spp 1",
                                    "invalid_syntax.gltf"},
                      BadInvocation{"AverageOfAMissingImage", "average /nonexistent-image.exr -o OUT", "nonexistent-image.exr"},
                      BadInvocation{"AverageIntoAPngName", "average " + kScene + " -o OUT.png", "name it .exr"},
                      BadInvocation{"ComparePngPreviewNotPng", "compare " + kScene + " " + kScene + " --png OUT.exr", "name it .png"},
                      BadInvocation{"CompareDiffNotExr", "compare " + kScene + " " + kScene + " --diff OUT.png", "--diff"},
                      BadInvocation{"AverageWithoutOutput", "average /nonexistent-image.exr", "output"},
                      BadInvocation{"DracoScene",
                                    "render " + sourcePath("tests/data/gltf/invalid/draco-box/Box.gltf") + " -o OUT",
                                    "KHR_draco_mesh_compression"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Cli, HelpListsTheSubcommandsAndExitsZero) {
  const CommandResult r = runCommand(reltBinary() + " --help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.output.find("render"), std::string::npos);
  EXPECT_NE(r.output.find("info"), std::string::npos);
}

TEST(Cli, InfoSummarisesAValidScene) {
  const CommandResult r = runCommand(reltBinary() + " info " + kScene);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("triangles"), std::string::npos) << r.output;
}

TEST(Cli, InfoRejectsAnInvalidSceneWithExitCode2) {
  const CommandResult r = runCommand(reltBinary() + " info " + sourcePath("tests/data/gltf/invalid/validator/asset/1_0_version.gltf"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
}

TEST(Cli, InfoSummarisesAValidButUnrenderableSceneThenFailsWithExitCode2) {
  // A valid glTF file without a camera or emitter: summary on stdout, one error line, exit 2.
  const CommandResult r =
      runCommand(reltBinary() + " info " + sourcePath("tests/data/gltf/valid/Khronos-SimpleMeshes/SimpleMeshes.gltf"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("triangles: 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("SimpleMeshes.gltf: scene: no camera"), std::string::npos) << r.output;
}

TEST(Cli, CompareReportsZeroErrorForAnImageAgainstItselfAndWritesTheDifference) {
  const std::string dir = makeTempDir("compare");
  ASSERT_EQ(runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/a.exr --spp 1 --width 16 --height 16").exitCode, 0);
  const CommandResult r = runCommand(reltBinary() + " compare " + dir + "/a.exr " + dir + "/a.exr --diff " + dir +
                                     "/d.exr --png " + dir + "/d.png");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("\"rmse\": 0,"), std::string::npos) << r.output;
  EXPECT_TRUE(fileExists(dir + "/d.exr"));
  EXPECT_TRUE(fileExists(dir + "/d.png"));
}

TEST(Cli, AverageWritesTheMeanOfRendersWeightedIfAskedAndRejectsADifferentSizeOrBadWeights) {
  const std::string dir = makeTempDir("average");
  const std::string render = reltBinary() + " render " + kScene + " --spp 1 --width 16 --height 16 -o " + dir;
  ASSERT_EQ(runCommand(render + "/a.exr --seed 1").exitCode, 0);
  ASSERT_EQ(runCommand(render + "/b.exr --seed 2").exitCode, 0);
  ASSERT_EQ(runCommand(reltBinary() + " render " + kScene + " --spp 1 --width 16 --height 8 -o " + dir + "/small.exr").exitCode, 0);
  CommandResult r = runCommand(reltBinary() + " average " + dir + "/a.exr " + dir + "/b.exr -o " + dir + "/m.exr --png " + dir + "/m.png");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const relt::Image a = relt::readExr(dir + "/a.exr"), b = relt::readExr(dir + "/b.exr"), m = relt::readExr(dir + "/m.exr");
  ASSERT_EQ(m.rgb.size(), a.rgb.size());
  for (size_t i = 0; i < m.rgb.size(); ++i) EXPECT_FLOAT_EQ(m.rgb[i], 0.5f * (a.rgb[i] + b.rgb[i])) << i;
  EXPECT_TRUE(fileExists(dir + "/m.png"));

  r = runCommand(reltBinary() + " average " + dir + "/a.exr " + dir + "/b.exr --weights 3,1 -o " + dir + "/w.exr");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const relt::Image w = relt::readExr(dir + "/w.exr");
  for (size_t i = 0; i < w.rgb.size(); ++i) EXPECT_FLOAT_EQ(w.rgb[i], 0.75f * a.rgb[i] + 0.25f * b.rgb[i]) << i;
  r = runCommand(reltBinary() + " average " + dir + "/a.exr " + dir + "/b.exr --weights 1 -o " + dir + "/bad.exr");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--weights"), std::string::npos) << r.output;
  EXPECT_FALSE(fileExists(dir + "/bad.exr"));

  r = runCommand(reltBinary() + " average " + dir + "/a.exr " + dir + "/small.exr -o " + dir + "/bad.exr");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("small.exr"), std::string::npos) << r.output;
  EXPECT_FALSE(fileExists(dir + "/bad.exr"));
}

TEST(Cli, ADirectEmissionPassThatTakesMostOfTheBudgetIsReportedAndTimed) {
  const std::string dir = makeTempDir("direct-budget");
  const CommandResult r = runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/p.exr --stats " + dir +
                                     "/p.json --integrator pssmlt --time 0.02 --direct-emission-spp 4096 --width 32 --height 32");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("warning: --direct-emission-spp 4096 took"), std::string::npos) << r.output;
  std::ifstream stats(dir + "/p.json");
  const nlohmann::json j = nlohmann::json::parse(stats);
  EXPECT_GT(j["direct_emission_seconds"].get<double>(), 0.01);
}

// By default pssmlt and relt estimate the directly seen emission apart, sized from the budget, and
// leave it to the chains when no emitter is in view; stats.json says what was taken.
TEST(Cli, TheDirectEmissionPassIsOnAutoByDefaultAndReported) {
  const std::string dir = makeTempDir("direct-auto");
  const std::string dark = sourcePath("scenes/door-ajar.gltf");
  for (const auto& [scene, name, spp] : {std::tuple{kScene, "lit", 16}, std::tuple{dark, "dark", 0}}) {
    const CommandResult r = runCommand(reltBinary() + " render " + scene + " -o " + dir + "/" + name + ".exr --stats " +
                                       dir + "/" + name + ".json --integrator relt --ladders 2 --mutations-per-pixel 2 "
                                       "--width 16 --height 16");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream stats(dir + "/" + name + ".json");
    const nlohmann::json j = nlohmann::json::parse(stats);
    EXPECT_EQ(j["settings"]["direct_emission_spp"], "auto") << name;
    EXPECT_EQ(j["direct_emission_spp"], spp) << name << ": 2 x 2 mutations per pixel, raised to the probe's 16";
  }
}

TEST(Cli, ReltWritesLadderDiagnosticsToStats) {
  const std::string dir = makeTempDir("cli-relt");
  const CommandResult r = runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/r.exr --stats " + dir +
                                     "/r.json --integrator relt --family relaxed --levels 4 --ladders 2 --mutations-per-pixel 2 "
                                     "--width 24 --height 16");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream stats(dir + "/r.json");
  const nlohmann::json j = nlohmann::json::parse(stats);
  ASSERT_EQ(j["relt"]["levels"].size(), 4u);
  EXPECT_GT(j["relt"]["rounds"].get<int>(), 0);
  EXPECT_TRUE(j["relt"]["levels"][0].contains("swap_acceptance_with_next"));
  EXPECT_FALSE(j["relt"]["levels"][3].contains("swap_acceptance_with_next"));
  EXPECT_EQ(j["settings"]["exchange"], "deo");
  EXPECT_EQ(j["mutations"].get<uint64_t>(), 8u * uint64_t(j["relt"]["steps_per_chain"].get<int>()));
}

TEST(Cli, RenderWritesExrPngAndStats) {
  const std::string dir = makeTempDir("cli-render");
  const CommandResult r = runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/a.exr --png " + dir +
                                     "/a.png --stats " + dir + "/a.json --spp 1 --width 32 --height 24");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fileExists(dir + "/a.exr"));
  EXPECT_TRUE(fileExists(dir + "/a.png"));
  EXPECT_TRUE(fileExists(dir + "/a.json"));
  // The closing line names every file written.
  EXPECT_NE(r.output.find("wrote " + dir + "/a.exr, " + dir + "/a.png and " + dir + "/a.json"), std::string::npos)
      << r.output;
  // The EXR says what made it.
  std::map<std::string, std::string> meta;
  for (const auto& [name, value] : relt::readExrAttributes(dir + "/a.exr")) meta[name] = value;
  EXPECT_EQ(meta["relt:integrator"], "bdpt");
  EXPECT_EQ(meta["relt:spp"], "1");
  EXPECT_EQ(nlohmann::json::parse(meta["relt:settings"])["width"], 32);
  EXPECT_GT(std::stod(meta["relt:render_seconds"]), 0.0);
  EXPECT_FALSE(meta["relt:commit"].empty());
}

// -o's extension picks the format: a .png output is a PNG (its signature), and no EXR is written.
TEST(Cli, AnOutputNamedPngIsWrittenAsAPng) {
  const std::string dir = makeTempDir("cli-png");
  const CommandResult r = runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/a.PNG --spp 1 --width 32 --height 24");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::ifstream png(dir + "/a.PNG", std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_FALSE(fileExists(dir + "/a.exr"));
}

// stats.json's settings say how the image was made: a timed render names no mutation count it did
// not have, and float settings read as given (0.3, not 0.30000001192092896).
TEST(Cli, StatsSettingsAreTheOnesGiven) {
  const std::string dir = makeTempDir("stats-settings");
  const CommandResult r = runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/t.exr --stats " + dir +
                                     "/t.json --integrator pssmlt --time 0.2 --width 16 --height 16 --chains 4");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream stats(dir + "/t.json");
  const nlohmann::json s = nlohmann::json::parse(stats)["settings"];
  EXPECT_FALSE(s.contains("mutations_per_pixel")) << s.dump();
  EXPECT_EQ(s["large_step_probability"].dump(), "0.3");
  EXPECT_EQ(s["small_step"].dump(), "[0.0009765625,0.015625]");
}

// The stepping trace (one number per rank and group round) goes to its own file, on request; it
// made stats.json grow with the render.
TEST(Cli, ReltWritesTheSteppingTraceApartOnRequest) {
  const std::string dir = makeTempDir("cli-trace");
  const std::string base = reltBinary() + " render " + kScene + " -o " + dir + "/r.exr --integrator relt --ladders 2 "
                           "--mutations-per-pixel 2 --width 24 --height 16 --stats " + dir;
  ASSERT_EQ(runCommand(base + "/plain.json").exitCode, 0);
  const CommandResult r = runCommand(base + "/traced.json --trace " + dir + "/trace.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* name : {"/plain.json", "/traced.json"}) {
    std::ifstream stats(dir + name);
    EXPECT_FALSE(nlohmann::json::parse(stats)["relt"].contains("group_round_step_seconds_trace_per_rank")) << name;
  }
  std::ifstream traceFile(dir + "/trace.json");
  const nlohmann::json trace = nlohmann::json::parse(traceFile)["group_round_step_seconds_per_rank"];
  ASSERT_EQ(trace.size(), 1u) << "one rank";
  EXPECT_GT(trace[0].size(), 0u);
  EXPECT_NE(runCommand(reltBinary() + " render " + kScene + " -o " + dir + "/p.exr --trace " + dir + "/t.json").exitCode, 0)
      << "relt only";
}
