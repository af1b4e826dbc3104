#pragma once
// A job of one process: every collective is the identity (a sum over one rank is its value). For
// tests, which render through the integrators' own code without MPI, and for requests a test makes
// (a test may also script collectives by overriding them: tests/support/scripted_job.h).
#include "parallel/job.h"

namespace relt {

class LocalJob : public Job {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }

  void reduceSumToRoot(std::vector<double>&) override {}
  void reduceSumToRoot(const std::vector<double>& send, double* sumsOnRoot) override;
  void allreduceSum(std::vector<double>&) override {}
  double allreduceSum(double value) override { return value; }
  uint64_t allreduceSum(uint64_t value) override { return value; }
  double allreduceMax(double value) override { return value; }
  int allreduceMax(int value) override { return value; }
  std::vector<double> allgather(double value) override { return {value}; }
  std::vector<std::string> processorNames() override { return {"local"}; }
  std::vector<std::vector<uint64_t>> gatherToRoot(const std::vector<uint64_t>& mine) override { return {mine}; }
  std::vector<std::vector<double>> gatherToRoot(const std::vector<double>& mine) override { return {mine}; }
  void broadcastFromRoot(std::vector<uint64_t>&) override {}
  void broadcastFromRoot(std::vector<double>&) override {}
  void broadcastFromRoot(std::string&) override {}
  void shareRootProblem(std::string problem) override;

  JobAgreement agree(double elapsed) override;
  bool stopRequested() const override { return stopRequested_; }
  bool takeSaveRequest() override;
  bool stopAgreed() const override { return stopAgreed_; }
  void markStopAgreed() override { stopAgreed_ = true; }
  // What a signal would ask of a rank (not collective).
  void requestStop() { stopRequested_ = true; }
  void requestSave() { saveRequested_ = true; }

  // Only payloads to this rank itself can go anywhere: each is received in the order sent.
  std::vector<std::vector<uint64_t>> transfer(const std::vector<Payload>& sends, const std::vector<int>& receiveFrom,
                                              const std::function<void()>& idle = {}) override;
  std::unique_ptr<PendingGather> startAllgatherv(std::vector<double> mine,
                                                 const std::vector<size_t>& lengths) override;
  std::unique_ptr<RequestChannel> openRequestChannel() override { return nullptr; }
  double collectiveSeconds() const override { return 0.0; }

 private:
  bool stopRequested_ = false, saveRequested_ = false, stopAgreed_ = false;
};

}  // namespace relt
