// The checkpoint file (format, checksum, atomic replacement), what identifies a render, when a
// checkpoint is due, and the schedule of a resumed render.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "checkpoint/checkpoint.h"
#include "core/error.h"
#include "core/words.h"
#include "integrators/registry.h"
#include "integrators/relt/relt_settings.h"
#include "replica/replica_schedule.h"
#include "test_support.h"

using namespace relt;

namespace {

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CheckpointFile, WrittenAndReadBackExactlyAndReplacedWhole) {
  const std::string dir = test::makeTempDir("checkpoint-file");
  Checkpoint c;
  c.header = {{"format", 1}, {"progress", {{"rounds", 7}}}};
  WordWriter w;
  w.f64(-0.0);
  w.f64(1e-300);
  w.block({1, 2, 3});
  c.words = w.words();
  writeCheckpoint(dir, c);
  const Checkpoint back = readCheckpoint(dir);
  EXPECT_EQ(back.header, c.header);
  EXPECT_EQ(back.words, c.words);
  WordReader in(back.words);
  EXPECT_TRUE(std::signbit(in.f64()));
  EXPECT_EQ(in.f64(), 1e-300);
  EXPECT_EQ(in.block(), (std::vector<uint64_t>{1, 2, 3}));
  EXPECT_TRUE(in.done());
  EXPECT_THROW(in.u64(), std::runtime_error) << "reading past the end";

  c.header["progress"]["rounds"] = 8;
  writeCheckpoint(dir, c);
  EXPECT_EQ(readCheckpoint(dir).header["progress"]["rounds"], 8);
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "the temporary file is renamed over the old one";
}

TEST(CheckpointFile, ADamagedOrForeignFileIsRefusedNamingIt) {
  const std::string dir = test::makeTempDir("checkpoint-damaged");
  const std::string file = checkpointFile(dir);
  EXPECT_NE(errorOf([&] { readCheckpoint(dir); }).find(file + ": cannot read the checkpoint"), std::string::npos);
  std::ofstream(file) << "glTF";
  EXPECT_NE(errorOf([&] { readCheckpoint(dir); }).find("not a relt checkpoint"), std::string::npos);
  Checkpoint c;
  c.header = {{"format", 1}};
  c.words = {1, 2, 3, 4};
  writeCheckpoint(dir, c);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (size_t cut : {bytes.size() - 1, bytes.size() - 9, size_t(20)}) {
    std::ofstream(file, std::ios::binary) << bytes.substr(0, cut);
    EXPECT_NE(errorOf([&] { readCheckpoint(dir); }).find("checkpoint is damaged"), std::string::npos) << cut;
  }
  bytes[bytes.size() - 12] ^= 1;  // a flipped bit in the words
  std::ofstream(file, std::ios::binary) << bytes;
  EXPECT_NE(errorOf([&] { readCheckpoint(dir); }).find("checksum mismatch"), std::string::npos);
  c.header["format"] = 99;
  writeCheckpoint(dir, c);
  EXPECT_NE(errorOf([&] { readCheckpoint(dir); }).find("format 99"), std::string::npos);
}

// Checkpoints written before the words were hashed a word at a time (FNV-1a by bytes over the
// whole file) still read; a flipped bit in any word of the new hash is caught.
TEST(CheckpointFile, AByteHashedCheckpointStillReadsAndEveryWordIsChecked) {
  const std::string dir = test::makeTempDir("checkpoint-legacy");
  const std::string file = checkpointFile(dir);
  Checkpoint c;
  c.header = {{"format", 1}};
  c.words = {5, 6, 7};
  writeCheckpoint(dir, c);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const size_t body = bytes.size() - sizeof(uint64_t);
  const uint64_t legacy = fnv1a(bytes.data(), body);
  std::string old = bytes.substr(0, body);
  old.append(reinterpret_cast<const char*>(&legacy), sizeof legacy);
  std::ofstream(file, std::ios::binary) << old;
  EXPECT_EQ(readCheckpoint(dir).words, c.words);
  for (size_t word = 0; word < c.words.size(); ++word)
    for (int bit : {0, 63}) {
      std::string flipped = bytes;
      flipped[body - (c.words.size() - word) * sizeof(uint64_t) + bit / 8] ^= char(1 << (bit % 8));
      std::ofstream(file, std::ios::binary) << flipped;
      EXPECT_NE(errorOf([&] { readCheckpoint(dir); }).find("checksum mismatch"), std::string::npos) << word << " " << bit;
    }
}

TEST(CheckpointFile, TheIdentityIgnoresBudgetsAndOutputsButNotWhatShapesTheImage) {
  RenderSettings a;
  selectIntegrator(a, "relt");
  a.width = 40;
  a.height = 30;
  a.output = "a.exr";
  a.mutationsPerPixel = 4;
  RenderSettings b = a;
  b.output = "b.exr";
  b.mutationsPerPixel = 64;
  b.snapshotEvery = 10;
  replicaSettings(b).placement = Placement::Packed;
  b.threads = 2;
  EXPECT_EQ(imageIdentity(a, "d1"), imageIdentity(b, "d1"));
  EXPECT_NO_THROW(checkSameRender(imageIdentity(a, "d1"), imageIdentity(b, "d1"), "f"));
  b.seed = 2;
  EXPECT_NE(errorOf([&] { checkSameRender(imageIdentity(a, "d1"), imageIdentity(b, "d1"), "f"); })
                .find("f: the checkpoint was rendered with seed 1, this render has 2"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { checkSameRender(imageIdentity(a, "d1"), imageIdentity(a, "d2"), "f"); }).find("another scene"),
            std::string::npos);
  b = a;
  replicaSettings(b).family.kind = FamilyKind::Tempered;
  EXPECT_NE(errorOf([&] { checkSameRender(imageIdentity(a, "d1"), imageIdentity(b, "d1"), "f"); }).find("family"),
            std::string::npos);
}

TEST(CheckpointFile, DueAtTheEndAndEveryPeriod) {
  EXPECT_TRUE(checkpointDue(0.0, 5.0, 0.0, false)) << "the end, finished or stopped";
  EXPECT_FALSE(checkpointDue(0.0, 5.0, 0.0, true)) << "no period: only the end";
  EXPECT_FALSE(checkpointDue(10.0, 9.9, 0.0, true));
  EXPECT_TRUE(checkpointDue(10.0, 10.0, 0.0, true));
  EXPECT_FALSE(checkpointDue(10.0, 15.0, 10.0, true));
}

TEST(ReplicaScheduleResume, ContinuesTheStepsOfTheRenderItResumes) {
  // 1200 pixels, 8 chains, 10 steps a round: 4 mpp = 600 steps = 60 rounds, 8 mpp = 120.
  ReplicaSchedule whole(1200.0, 8, 10, std::nullopt, 8.0);
  ReplicaSchedule resumed(1200.0, 8, 10, std::nullopt, 8.0);
  resumed.resumeAt(60, 600);
  for (uint64_t r = 60; r < 125; ++r) {
    EXPECT_EQ(resumed.stepsAfter(r), whole.stepsAfter(r)) << r;
    EXPECT_EQ(resumed.stepsInRound(r), whole.stepsInRound(r)) << r;
    EXPECT_EQ(resumed.anotherRound(r, 0.0, 0.0), whole.anotherRound(r, 0.0, 0.0)) << r;
  }
  // A render that ended on a short round (5 mpp, 16 steps a round: 750 steps in 47 rounds)
  // continues with whole rounds from its actual steps.
  ReplicaSchedule afterShort(1200.0, 8, 16, std::nullopt, 8.0);
  afterShort.resumeAt(47, 750);  // 46 rounds of 16 and one of 14
  EXPECT_EQ(afterShort.stepsInRound(47), 16u);
  EXPECT_EQ(afterShort.stepsAfter(48), 766u);
  EXPECT_EQ(afterShort.stepsAfter(200), 1200u);
  EXPECT_FALSE(afterShort.anotherRound(200, 0.0, 0.0));
  // Resuming with the budget already spent runs nothing.
  ReplicaSchedule spent(1200.0, 8, 10, std::nullopt, 4.0);
  spent.resumeAt(60, 600);
  EXPECT_FALSE(spent.anotherRound(60, 0.0, 0.0));
}
