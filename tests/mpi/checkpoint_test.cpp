// Checkpoints and resume: a render continued from its checkpoint gives the image of the render
// that never stopped, on the same rank count (identical) or another (1e-5 relative); whether it
// stopped at its budget, by SIGTERM, or because a rank was killed. A checkpoint of another scene,
// other settings or another integrator is refused, as is a damaged one. Output safety: a full
// disk is reported without partial files, a read-only output folder fails before rendering.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_support.h"

using namespace relt;
using namespace relt::test;

namespace {

const std::string kRelt =
    "--integrator relt --ladders 2 --family tempered --levels 4 --regularisation 0.05 --regularisation-decay 0.2 "
    "--exchange-interval 10 --width 40 --height 30 --seed 5";

// relt render of `scene` with `args`; the exit code is checked unless `expectFailure`.
CommandResult render(int ranks, const std::string& scene, const std::string& args, bool expectFailure = false) {
  const CommandResult r = runCommand((ranks > 0 ? mpirun(ranks) : std::string()) + reltBinary() + " render " +
                                     sourcePath("scenes/" + scene + ".gltf") + " " + args);
  if (!expectFailure) EXPECT_EQ(r.exitCode, 0) << r.output;
  return r;
}

// kRelt with one option's value replaced.
std::string reltWith(const std::string& option, const std::string& value) {
  std::string args = kRelt;
  const size_t at = args.find(option + " ");
  const size_t end = args.find(' ', at + option.size() + 1);
  return args.replace(at, end == std::string::npos ? std::string::npos : end - at, option + " " + value);
}

void expectIdentical(const Image& a, const Image& b) {
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_TRUE(a.rgb == b.rgb) << "not bitwise identical";
  EXPECT_GT(a.mean(), 0.0);
}

// Renders `args` (a resume) on `rankCounts`: bit-identical to `whole` on the 2 ranks that wrote
// the checkpoint, within 1e-5 relative on the others.
void expectResumedIs(const Image& whole, const std::string& dir, const std::string& scene, const std::string& args,
                     const std::vector<int>& rankCounts = {2, 1, 3}) {
  for (int ranks : rankCounts) {
    const std::string out = dir + "/resumed" + std::to_string(ranks) + ".exr";
    render(ranks, scene, "-o " + out + " " + args);
    if (ranks == 2)
      expectIdentical(readExr(out), whole);
    else
      expectSameImage(readExr(out), whole);
  }
}

// A resume of DIR/ck by a render of `args` (another integrator or seed) is refused with exit 2,
// naming the checkpoint, before any output.
void expectRefused(const std::string& dir, const std::string& args) {
  const CommandResult r = render(0, "cornell-box", "-o " + dir + "/refused.exr --resume " + dir + "/ck" + args, true);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/ck/checkpoint.relt"), std::string::npos) << r.output;
  EXPECT_FALSE(fileExists(dir + "/refused.exr"));
}

}  // namespace

// relt on ring (mirrors: the tempered levels differ; the regularisation moves the targets before
// and after the checkpoint): 4 then 8 mutations per pixel, stopped at the first budget with a
// checkpoint, resumed to the second. 8 chains x 10 steps a round: both budgets end on a round.
TEST(Checkpoint, ReltResumedIsTheRenderThatNeverStoppedOnAnyRankCount) {
  const std::string dir = makeTempDir("checkpoint-relt");
  render(2, "ring", "-o " + dir + "/whole.exr --mutations-per-pixel 8 " + kRelt);
  render(2, "ring", "-o " + dir + "/half.exr --mutations-per-pixel 4 --checkpoint " + dir + "/ck " + kRelt);
  ASSERT_TRUE(fileExists(dir + "/ck/checkpoint.relt"));
  expectResumedIs(readExr(dir + "/whole.exr"), dir, "ring", "--mutations-per-pixel 8 --resume " + dir + "/ck " + kRelt);
}

// pt and bdpt: the checkpoint is the film and the passes done.
TEST(Checkpoint, PtAndBdptResumedAreTheRendersThatNeverStopped) {
  for (const std::string integrator : {"pt", "bdpt"}) {
    const std::string dir = makeTempDir("checkpoint-" + integrator);
    const std::string common = " --integrator " + integrator + " --width 40 --height 30 --seed 3";
    render(2, "cornell-box", "-o " + dir + "/whole.exr --spp 6" + common);
    render(2, "cornell-box", "-o " + dir + "/half.exr --spp 2 --checkpoint " + dir + "/ck" + common);
    render(2, "cornell-box", "-o " + dir + "/same.exr --spp 6 --resume " + dir + "/ck" + common);
    render(1, "cornell-box", "-o " + dir + "/other.exr --spp 6 --resume " + dir + "/ck" + common);
    const Image whole = readExr(dir + "/whole.exr");
    expectIdentical(readExr(dir + "/same.exr"), whole);
    expectSameImage(readExr(dir + "/other.exr"), whole);
  }
}

// pssmlt and mmlt: the chains (by global id, so any rank takes the ones it owns now), the bootstrap
// targets (not run again), the film and mmlt's per-depth films. 48 chains on 40 x 30: 25 steps a
// round, 4 and 8 mutations per pixel end on whole rounds.
TEST(Checkpoint, MarkovChainRendersResumedAreTheRendersThatNeverStopped) {
  for (const std::string integrator : {"pssmlt", "mmlt"}) {
    const std::string dir = makeTempDir("checkpoint-" + integrator);
    const std::string common = " --integrator " + integrator + " --chains 48 --width 40 --height 30 --seed 3";
    render(2, "cornell-box", "-o " + dir + "/whole.exr --mutations-per-pixel 8" + common);
    render(2, "cornell-box", "-o " + dir + "/half.exr --mutations-per-pixel 4 --checkpoint " + dir + "/ck" + common);
    expectResumedIs(readExr(dir + "/whole.exr"), dir, "cornell-box", "--mutations-per-pixel 8 --resume " + dir + "/ck" + common);
    const std::string other = integrator == "pssmlt" ? "mmlt" : "pssmlt";
    expectRefused(dir, " --mutations-per-pixel 8 --integrator " + other + " --chains 48 --width 40 --height 30 --seed 3");
    expectRefused(dir, " --mutations-per-pixel 8 --integrator " + integrator + " --chains 48 --width 40 --height 30 --seed 4");
  }
}

namespace {

// cornell-box with `common` for `total` passes on 2 ranks, and for `part` with a checkpoint that
// is then resumed to `total` on 2, 1 and 3 ranks (expectResumedIs); returns the checkpoint's folder.
std::string expectPassesResumed(const std::string& name, const std::string& common, int part, int total) {
  const std::string dir = makeTempDir("checkpoint-" + name), spp = " --spp " + std::to_string(total);
  render(2, "cornell-box", "-o " + dir + "/whole.exr" + spp + common);
  render(2, "cornell-box", "-o " + dir + "/part.exr --spp " + std::to_string(part) + " --checkpoint " + dir + "/ck" + common);
  expectResumedIs(readExr(dir + "/whole.exr"), dir, "cornell-box", spp + " --resume " + dir + "/ck" + common);
  return dir;
}

}  // namespace

// erpt: the film, the passes done, the counters, the proposal tally and the normaliser (the
// bootstrap is not run again).
TEST(Checkpoint, ErptResumedIsTheRenderThatNeverStopped) {
  const std::string dir =
      expectPassesResumed("erpt", " --integrator erpt --erpt-proposal-filter --width 40 --height 30 --seed 3", 2, 6);
  expectRefused(dir, " --spp 6 --integrator pt --width 40 --height 30 --seed 3");
  expectRefused(dir, " --spp 6 --integrator erpt --erpt-proposal-filter --width 40 --height 30 --seed 4");
}

// vcm's checkpoint holds the film and the iterations done: resumed on any rank count it goes on
// with the next iteration.
TEST(Checkpoint, VcmResumedIsTheRenderThatNeverStopped) {
  const std::string dir = expectPassesResumed("vcm", " --integrator vcm --width 40 --height 30 --seed 3", 3, 7);
  expectRefused(dir, " --spp 7 --integrator vcm --vcm-mode bpt --width 40 --height 30 --seed 3");
}

// meb's the same way (its loop is vcm's), with its chains restarted every iteration.
TEST(Checkpoint, MebResumedIsTheRenderThatNeverStopped) {
  const std::string dir = expectPassesResumed("meb", " --integrator meb --width 40 --height 30 --seed 3", 3, 7);
  expectRefused(dir, " --spp 7 --integrator meb --meb-pairs 3 --width 40 --height 30 --seed 3");
}

// SIGTERM mid-render (to mpirun, which forwards it): every rank stops at the next round, writes
// the image so far and a checkpoint; resuming it finishes the uninterrupted image. A rank killed
// with -9 leaves the last periodic checkpoint, which resumes just as well.
TEST(Checkpoint, ACheckpointLeftBySigtermOrAKilledRankResumesToTheUninterruptedImage) {
  const std::string dir = makeTempDir("checkpoint-stopped");
  const std::string args = " --integrator relt --ladders 2 --exchange-interval 16 --width 64 --height 64 --seed 9 "
                           "--mutations-per-pixel 400 ";
  render(2, "cornell-box", "-o " + dir + "/whole.exr" + args);
  const Image whole = readExr(dir + "/whole.exr");
  for (const std::string signal : {"TERM", "KILL"}) {
    const std::string ck = dir + "/ck-" + signal, out = dir + "/stopped-" + signal + ".exr";
    const std::string victim = signal == "KILL" ? "^" + reltBinary() + " render .*" + out : "";
    const SignalledRun run = runAndSignal(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") +
                                              " -o " + out + args + "--checkpoint " + ck + " --checkpoint-every 0.2",
                                          dir + "/log-" + signal + ".txt", signal, victim);
    EXPECT_LT(run.secondsAfterSignal, 10.0) << run.result.output;
    if (signal == "TERM") {
      EXPECT_NE(run.result.output.find("stopped early by a signal"), std::string::npos) << run.result.output;
      EXPECT_TRUE(fileExists(out));
    } else {
      EXPECT_NE(run.result.exitCode, 0);
      EXPECT_FALSE(fileExists(out));
    }
    ASSERT_TRUE(fileExists(ck + "/checkpoint.relt")) << run.result.output;
    for (const auto& e : std::filesystem::directory_iterator(ck))
      EXPECT_EQ(e.path().filename(), "checkpoint.relt") << "no temporary file left behind";
    const std::string resumed = dir + "/resumed-" + signal + ".exr";
    render(2, "cornell-box", "-o " + resumed + args + "--resume " + ck);
    expectIdentical(readExr(resumed), whole);
  }
}

// Packed placement (local decisions) with its messages read back 64 rounds late: the stop and the
// save that precedes it (mpirun's SIGCONT) are agreed apart from the messages, at a round every
// rank reaches; the checkpoint of that round resumes to the uninterrupted image.
TEST(Checkpoint, APackedReltCheckpointLeftBySigtermResumesToTheUninterruptedImage) {
  const std::string dir = makeTempDir("checkpoint-packed-stopped");
  const std::string args = " --integrator relt --ladders 4 --placement packed --normaliser-lag 64 "
                           "--normaliser-lag-growth 0 --exchange-interval 16 --width 64 --height 64 --seed 9 "
                           "--mutations-per-pixel 400 ";
  render(2, "cornell-box", "-o " + dir + "/whole.exr" + args);
  const std::string ck = dir + "/ck", out = dir + "/stopped.exr";
  const SignalledRun run = runAndSignal(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") +
                                            " -o " + out + args + "--checkpoint " + ck, dir + "/log.txt", "TERM");
  EXPECT_LT(run.secondsAfterSignal, 10.0) << run.result.output;
  EXPECT_NE(run.result.output.find("stopped early by a signal"), std::string::npos) << run.result.output;
  EXPECT_TRUE(fileExists(out));
  ASSERT_TRUE(fileExists(ck + "/checkpoint.relt")) << run.result.output;
  expectResumedIs(readExr(dir + "/whole.exr"), dir, "cornell-box", args + "--resume " + ck, {2, 1});
}

// pssmlt stopped by SIGTERM to mpirun: the checkpoint of the round it stopped after resumes to the
// uninterrupted image. The signal goes after the first progress line (1 s in), so the render must
// last longer than that on an idle machine too (about 2.5 s here).
TEST(Checkpoint, APssmltCheckpointLeftBySigtermResumesToTheUninterruptedImage) {
  const std::string dir = makeTempDir("checkpoint-pssmlt-stopped");
  const std::string args = " --integrator pssmlt --chains 64 --width 64 --height 64 --seed 9 --mutations-per-pixel 400 ";
  render(2, "cornell-box", "-o " + dir + "/whole.exr" + args);
  const std::string ck = dir + "/ck", out = dir + "/stopped.exr";
  const SignalledRun run = runAndSignal(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") +
                                            " -o " + out + args + "--checkpoint " + ck + " --checkpoint-every 0.2",
                                        dir + "/log.txt", "TERM");
  EXPECT_LT(run.secondsAfterSignal, 10.0) << run.result.output;
  EXPECT_NE(run.result.output.find("stopped early by a signal"), std::string::npos) << run.result.output;
  EXPECT_TRUE(fileExists(out));
  ASSERT_TRUE(fileExists(ck + "/checkpoint.relt")) << run.result.output;
  render(2, "cornell-box", "-o " + dir + "/resumed.exr" + args + "--resume " + ck);
  expectIdentical(readExr(dir + "/resumed.exr"), readExr(dir + "/whole.exr"));
}

// A render of the pass-loop integrators stopped inside a pass, and the image it wrote.
struct StoppedInAPass {
  Image image;
  int passes = 0, rows = 0, imageRows = 0;
};

// Renders `scene` with `args` (4 passes) and a checkpoint in DIR/ck and stops it by SIGTERM at
// its first progress line past 25 % (a pass done, so the image is not black); a stop can fall
// between passes (one chunk in several ends one), so it is tried up to five times until one
// falls inside a pass (a pass of about a second is some ten chunks of kPassChunkSeconds).
StoppedInAPass stopInsideAPass(const std::string& dir, const std::string& scene, const std::string& args) {
  const std::string ck = dir + "/ck", out = dir + "/stopped.exr", stats = dir + "/stopped.json";
  StoppedInAPass s;
  for (int attempt = 0; attempt < 5 && s.rows == 0; ++attempt) {
    std::filesystem::remove_all(ck);
    const SignalledRun run = runAndSignal(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/" + scene + ".gltf") +
                                              " -o " + out + args + "--checkpoint " + ck + " --stats " + stats,
                                          dir + "/log.txt", "TERM", "", "^ *(2[5-9]|[3-9][0-9])\\.[0-9]%");
    EXPECT_TRUE(fileExists(stats)) << run.result.output;
    if (!fileExists(stats)) return s;
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
    EXPECT_TRUE(j["interrupted"].get<bool>()) << run.result.output;
    s.passes = j["spp"].get<int>();
    s.rows = j.value("rows_of_the_stopped_pass", 0);
    s.imageRows = j.value("image_rows_of_the_stopped_pass", 0);
  }
  s.image = readExr(out);
  return s;
}

// The image of a render of `scene` with `args` and --spp `passes` (2 ranks); black for none.
Image renderPasses(const std::string& dir, const std::string& scene, const std::string& args, int passes, int width,
                   int height) {
  if (passes == 0) return Image(width, height);
  const std::string out = dir + "/spp" + std::to_string(passes) + ".exr";
  render(2, scene, "-o " + out + args + "--spp " + std::to_string(passes));
  return readExr(out);
}

// Bitwise equality of rows [first, end) of two images of the same size.
void expectSameRows(const Image& a, const Image& b, int first, int end) {
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  const size_t row = size_t(3) * a.width;
  EXPECT_TRUE(std::equal(a.rgb.begin() + row * first, a.rgb.begin() + row * end, b.rgb.begin() + row * first))
      << "rows " << first << " to " << end - 1 << " differ";
}

// A stop inside a pass writes an image and a checkpoint there; the resume finishes that pass and
// the rest: the image of the render that never stopped. The image is exact, since pass k's
// samples depend on k only: pt's rows done are those of a render of one more pass, the others
// those of a render of the passes done; bdpt's light paths and erpt's chains splat outside their
// row, so their image is exactly that of a render of the passes done (render/pass_film.h). A pass
// lasts about a second on 2 ranks (pt in the furnace, whose paths are long; a larger film would
// take longer to write than mpirun waits), erpt's 1.7 s, with its proposal filter (a tally per
// pixel; at 96x72 its render could end in 1.6 s, before a stop sent at the first progress line took
// effect, about a second later; at 144x108 a pass of 0.75 s was few enough chunks that three stops
// in a row fell between passes).
TEST(Checkpoint, AStopInsideAPassResumesToTheUninterruptedImage) {
  struct Case {
    std::string integrator, scene;
    int width, height;
    std::string extra;
    std::vector<int> resumeRanks;
  };
  for (const Case& c : {Case{"bdpt", "cornell-box", 1024, 768, "", {2, 1}},
                        Case{"pt", "furnace", 1024, 768, "--max-depth 256 ", {2}},
                        Case{"erpt", "cornell-box", 216, 162, "--erpt-proposal-filter ", {2, 1}}}) {
    SCOPED_TRACE(c.integrator);
    const std::string dir = makeTempDir("checkpoint-inside-a-pass-" + c.integrator);
    const std::string common = " --integrator " + c.integrator + " --width " + std::to_string(c.width) + " --height " +
                               std::to_string(c.height) + " --seed 6 " + c.extra;
    const std::string args = common + "--spp 4 ";
    render(2, c.scene, "-o " + dir + "/whole.exr" + args);
    const Image whole = readExr(dir + "/whole.exr");
    const StoppedInAPass s = stopInsideAPass(dir, c.scene, args);
    ASSERT_GT(s.rows, 0) << "every stop fell between two passes";
    ASSERT_GT(s.passes, 0);
    for (float v : s.image.rgb) ASSERT_TRUE(std::isfinite(v));
    const Image passesDone = renderPasses(dir, c.scene, common, s.passes, c.width, c.height);
    if (c.integrator == "pt") {
      EXPECT_EQ(s.imageRows, s.rows);
      expectSameRows(s.image, renderPasses(dir, c.scene, common, s.passes + 1, c.width, c.height), 0, s.rows);
      expectSameRows(s.image, passesDone, s.rows, c.height);
    } else {
      EXPECT_EQ(s.imageRows, 0);
      EXPECT_TRUE(s.image.rgb == passesDone.rgb) << "not the image of " << s.passes << " passes";
    }
    expectResumedIs(whole, dir, c.scene, args + "--resume " + dir + "/ck", c.resumeRanks);
  }
}

// A stop during pssmlt's, relt's or vcm's direct-emission pass (here a long one: 2^17 rays per pixel,
// about 8 s on 2 ranks) writes the image of the pass so far and a checkpoint of it, before any
// chain or iteration starts; the resume goes on with the pass from there and then runs the chains: the image
// of the render that never stopped (relt also on 3 ranks), and its checkpoints keep the pass (a
// resume of the last one renders no ray of it again).
TEST(Checkpoint, AStopInTheDirectEmissionPassResumesToTheUninterruptedImage) {
  for (const std::string integrator : {"relt", "pssmlt", "vcm"}) {
    const std::string dir = makeTempDir("checkpoint-direct-" + integrator);
    const std::string budget = integrator == "vcm" ? "--spp 4 " : "--mutations-per-pixel 4 ";
    const std::string args = " --integrator " + integrator + " --width 40 --height 30 --seed 4 " + budget +
                             "--direct-emission-spp 131072 ";
    render(2, "cornell-box", "-o " + dir + "/whole.exr" + args);
    const Image whole = readExr(dir + "/whole.exr");
    const std::string ck = dir + "/ck", out = dir + "/stopped.exr";
    const SignalledRun run = runAndSignal(mpirun(2) + reltBinary() + " render " + sourcePath("scenes/cornell-box.gltf") +
                                              " -o " + out + args + "--checkpoint " + ck + " --stats " + dir + "/stopped.json",
                                          dir + "/log.txt", "TERM", "", kDirectPassProgress);
    ASSERT_NE(run.result.output.find("stopped in the direct-emission pass"), std::string::npos) << run.result.output;
    ASSERT_TRUE(fileExists(out));
    const int spp = nlohmann::json::parse(std::ifstream(dir + "/stopped.json"))["direct_emission_spp"].get<int>();
    EXPECT_GT(spp, 0);
    EXPECT_LT(spp, 131072);
    expectResumedIs(whole, dir, "cornell-box", args + "--resume " + ck + " --checkpoint " + dir + "/again",
                    integrator == "relt" ? std::vector<int>{2, 3} : std::vector<int>{2});
    const std::string stats = dir + "/again.json";
    render(1, "cornell-box", "-o " + dir + "/again.exr --stats " + stats + args + "--resume " + dir + "/again");
    expectSameImage(readExr(dir + "/again.exr"), whole);
    EXPECT_LT(nlohmann::json::parse(std::ifstream(stats))["render_seconds"].get<double>(), 2.0) << "the pass rendered again";
  }
}

// What cannot be continued is refused before any work, with one line naming the checkpoint.
TEST(Checkpoint, AForeignOrDamagedCheckpointIsRefused) {
  const std::string dir = makeTempDir("checkpoint-refused");
  const std::string ck = dir + "/ck";
  render(0, "ring", "-o " + dir + "/a.exr --mutations-per-pixel 1 --checkpoint " + ck + " " + kRelt);
  struct Case {
    std::string scene, args, mentions;
  };
  const std::vector<Case> cases = {
      {"ring", reltWith("--seed", "6"), "rendered with seed 5, this render has 6"},
      {"ring", reltWith("--levels", "5"), "rendered with levels 4, this render has 5"},
      {"cornell-box", kRelt, "another scene"},
      {"ring", "--integrator bdpt --width 40 --height 30 --seed 5", "is of a relt render, this one is bdpt"},
      {"ring", reltWith("--width", "41"), "rendered with width 40"},
  };
  for (const Case& c : cases) {
    // Two ranks once (every rank must give up together), otherwise one process (mpirun is slow).
    const int ranks = &c == &cases.front() ? 2 : 0;
    const CommandResult r = render(ranks, c.scene, "-o " + dir + "/b.exr --resume " + ck + " " + c.args, true);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(c.mentions), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(ck + "/checkpoint.relt"), std::string::npos) << r.output;
    EXPECT_FALSE(fileExists(dir + "/b.exr"));
  }
  // Cut short, or one byte changed: the checksum says so.
  const std::string file = ck + "/checkpoint.relt";
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (const std::string& damaged : {bytes.substr(0, bytes.size() / 2), bytes.substr(0, 100) + "x" + bytes.substr(101)}) {
    std::ofstream(file, std::ios::binary) << damaged;
    const CommandResult r = render(0, "ring", "-o " + dir + "/c.exr --resume " + ck + " " + kRelt, true);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("checkpoint is damaged"), std::string::npos) << r.output;
    EXPECT_FALSE(fileExists(dir + "/c.exr"));
  }
  const CommandResult missing = render(0, "ring", "-o " + dir + "/d.exr --resume " + dir + "/none " + kRelt, true);
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("no checkpoint to resume"), std::string::npos) << missing.output;
}

// A full disk (a 16 KiB tmpfs in a private mount namespace): the image or the checkpoint that does
// not fit is reported with exit 2 and leaves no partial file.
TEST(Checkpoint, AFullDiskIsReportedAndLeavesNoPartialFile) {
  const std::string dir = makeTempDir("checkpoint-full");
  const std::string full = dir + "/full";
  std::filesystem::create_directories(full);
  if (runCommand("unshare -m true").exitCode != 0) GTEST_SKIP() << "no mount namespaces here";
  auto inFullDisk = [&](const std::string& args) {
    return runCommand("unshare -m sh -c 'mount -t tmpfs -o size=16k tmpfs " + full + " && " + reltBinary() +
                      " render " + sourcePath("scenes/ring.gltf") + " " + args + "; rc=$?; echo left:; ls -A " + full +
                      "; exit $rc'");
  };
  const CommandResult image = inFullDisk("-o " + full + "/out.exr --spp 1 --width 128 --height 128");
  EXPECT_EQ(image.exitCode, 2) << image.output;
  EXPECT_NE(image.output.find("No space left on device"), std::string::npos) << image.output;
  EXPECT_EQ(image.output.find(".tmp", image.output.find("left:")), std::string::npos) << "a leftover: " << image.output;
  const CommandResult checkpoint =
      inFullDisk("-o " + dir + "/out.exr --mutations-per-pixel 4 --checkpoint " + full + " " + kRelt);
  EXPECT_EQ(checkpoint.exitCode, 2) << checkpoint.output;
  EXPECT_NE(checkpoint.output.find("checkpoint.relt: write failed"), std::string::npos) << checkpoint.output;
  EXPECT_FALSE(fileExists(dir + "/out.exr"));
}

// A read-only folder (a read-only tmpfs: root ignores permission bits, not a read-only mount) for
// the image or the checkpoint is refused before rendering: a render that would take minutes fails
// at once.
TEST(Checkpoint, AReadOnlyOutputFolderFailsBeforeRendering) {
  const std::string dir = makeTempDir("checkpoint-readonly");
  const std::string ro = dir + "/ro";
  std::filesystem::create_directories(ro);
  if (runCommand("unshare -m true").exitCode != 0) GTEST_SKIP() << "no mount namespaces here";
  for (const std::string& outputs : {"-o " + ro + "/out.exr", "-o " + dir + "/out.exr --checkpoint " + ro}) {
    const auto t0 = std::chrono::steady_clock::now();
    const CommandResult r = runCommand("unshare -m sh -c 'mount -t tmpfs -o ro tmpfs " + ro + " && " + reltBinary() +
                                       " render " + sourcePath("scenes/cornell-box.gltf") + " " + outputs +
                                       " --spp 100000 --width 256 --height 256'");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("not writable"), std::string::npos) << r.output;
    EXPECT_LT(seconds, 10.0) << "refused before rendering";
    EXPECT_FALSE(fileExists(dir + "/out.exr"));
  }
}
