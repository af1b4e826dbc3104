#pragma once
// The job across MPI ranks: every call of parallel/job.h by comm.h's collectives (MPI_COMM_WORLD),
// requests by the signals of interrupt.h.
#include "comm.h"
#include "parallel/job.h"

namespace relt::mpi {

class MpiJob final : public Job {
 public:
  explicit MpiJob(const Session& session) : session_(session) {}

  int rank() const override { return session_.rank(); }
  int size() const override { return session_.size(); }

  void reduceSumToRoot(std::vector<double>& data) override { mpi::reduceSumToRoot(data); }
  void reduceSumToRoot(const std::vector<double>& send, double* sumsOnRoot) override {
    mpi::reduceSumToRoot(send, sumsOnRoot);
  }
  void allreduceSum(std::vector<double>& data) override { mpi::allreduceSum(data); }
  double allreduceSum(double value) override { return mpi::allreduceSum(value); }
  uint64_t allreduceSum(uint64_t value) override { return mpi::allreduceSum(value); }
  double allreduceMax(double value) override { return mpi::allreduceMax(value); }
  int allreduceMax(int value) override { return mpi::allreduceMax(value); }
  std::vector<double> allgather(double value) override { return mpi::allgather(value); }
  std::vector<std::string> processorNames() override { return mpi::processorNames(); }
  std::vector<std::vector<uint64_t>> gatherToRoot(const std::vector<uint64_t>& mine) override {
    return mpi::gatherToRoot(mine);
  }
  std::vector<std::vector<double>> gatherToRoot(const std::vector<double>& mine) override {
    return mpi::gatherToRoot(mine);
  }
  void broadcastFromRoot(std::vector<uint64_t>& words) override { mpi::broadcastFromRoot(words); }
  void broadcastFromRoot(std::vector<double>& values) override { mpi::broadcastFromRoot(values); }
  void broadcastFromRoot(std::string& text) override { mpi::broadcastFromRoot(text); }
  void shareRootProblem(std::string problem) override { mpi::shareRootProblem(std::move(problem)); }

  JobAgreement agree(double elapsed) override { return mpi::agree(elapsed); }
  bool stopRequested() const override;
  bool takeSaveRequest() override;
  bool stopAgreed() const override;
  void markStopAgreed() override;

  std::vector<std::vector<uint64_t>> transfer(const std::vector<Payload>& sends, const std::vector<int>& receiveFrom,
                                              const std::function<void()>& idle = {}) override {
    return mpi::transfer(sends, receiveFrom, idle);
  }
  std::unique_ptr<PendingGather> startAllgatherv(std::vector<double> mine,
                                                 const std::vector<size_t>& lengths) override {
    return std::make_unique<PendingAllgatherv>(std::move(mine), lengths);
  }
  std::unique_ptr<RequestChannel> openRequestChannel() override;
  double collectiveSeconds() const override { return mpi::collectiveSeconds(); }

 private:
  const Session& session_;
};

}  // namespace relt::mpi
