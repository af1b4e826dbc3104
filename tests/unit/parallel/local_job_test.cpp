// A job of one process: its collectives are what MPI's are on one rank, and requests a test makes
// are agreed as a signal's would be.
#include <gtest/gtest.h>

#include "core/error.h"
#include "parallel/local_job.h"

namespace relt {
namespace {

TEST(LocalJob, IsOneRankWhoseCollectivesReturnItsOwnValues) {
  LocalJob job;
  EXPECT_EQ(job.rank(), 0);
  EXPECT_EQ(job.size(), 1);
  EXPECT_TRUE(job.isRoot());
  EXPECT_EQ(job.allreduceSum(2.5), 2.5);
  EXPECT_EQ(job.allreduceMax(7), 7);
  EXPECT_EQ(job.allgather(3.0), std::vector<double>{3.0});
  std::vector<double> sums(2, 0.0);
  job.reduceSumToRoot({1.0, 2.0}, sums.data());
  EXPECT_EQ(sums, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(job.gatherToRoot(std::vector<uint64_t>{4, 5}), (std::vector<std::vector<uint64_t>>{{4, 5}}));
}

TEST(LocalJob, GathersARoundMessageAndRefusesLengthsOfOtherRanks) {
  LocalJob job;
  const std::unique_ptr<PendingGather> gather = job.startAllgatherv({1.0, 2.0, 3.0}, {3});
  EXPECT_EQ(gather->wait(), (std::vector<std::vector<double>>{{1.0, 2.0, 3.0}}));
  EXPECT_THROW(job.startAllgatherv({1.0}, {1, 1}), std::logic_error);
  EXPECT_THROW(job.transfer({{1, {9}}}, {1}), std::logic_error);
}

TEST(LocalJob, AgreesOnAStopOnceAskedAndOnASaveOncePerRequest) {
  LocalJob job;
  EXPECT_FALSE(job.agree(1.0).stop);
  job.requestSave();
  const JobAgreement saved = job.agree(2.0);
  EXPECT_TRUE(saved.save);
  EXPECT_EQ(saved.elapsed, 2.0);
  EXPECT_FALSE(job.agree(3.0).save);
  EXPECT_FALSE(job.stopAgreed());
  job.requestStop();
  EXPECT_TRUE(job.stopRequested());
  EXPECT_TRUE(job.agree(4.0).stop);
  EXPECT_TRUE(job.stopAgreed());
}

TEST(LocalJob, MakesARootProblemAnInputError) {
  LocalJob job;
  EXPECT_NO_THROW(job.shareRootProblem(""));
  EXPECT_THROW(job.shareRootProblem("scene.gltf: no such file"), InputError);
}

}  // namespace
}  // namespace relt
