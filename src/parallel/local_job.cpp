#include "parallel/local_job.h"

#include <algorithm>
#include <stdexcept>

#include "core/error.h"

namespace relt {

namespace {
// A gather over one rank: complete from the start.
class LocalGather final : public PendingGather {
 public:
  explicit LocalGather(std::vector<double> mine) : mine_(std::move(mine)) {}
  std::vector<std::vector<double>> wait(const std::function<void()>&) override { return {mine_}; }
  void complete(const std::function<void()>&) override {}

 private:
  std::vector<double> mine_;
};
}  // namespace

void LocalJob::reduceSumToRoot(const std::vector<double>& send, double* sumsOnRoot) {
  std::copy(send.begin(), send.end(), sumsOnRoot);
}

void LocalJob::shareRootProblem(std::string problem) {
  if (!problem.empty()) throw InputError("", "", problem);
}

JobAgreement LocalJob::agree(double elapsed) {
  const JobAgreement agreed{elapsed, stopRequested_, takeSaveRequest()};
  stopAgreed_ |= agreed.stop;
  return agreed;
}

bool LocalJob::takeSaveRequest() {
  const bool asked = saveRequested_;
  saveRequested_ = false;
  return asked;
}

std::vector<std::vector<uint64_t>> LocalJob::transfer(const std::vector<Payload>& sends,
                                                      const std::vector<int>& receiveFrom,
                                                      const std::function<void()>&) {
  if (sends.size() != receiveFrom.size()) throw std::logic_error("LocalJob::transfer: a payload has no receiver");
  std::vector<std::vector<uint64_t>> received;
  for (const Payload& p : sends) {
    if (p.rank != 0) throw std::logic_error("LocalJob::transfer: a payload to a rank that does not exist");
    received.push_back(p.data);
  }
  return received;
}

std::unique_ptr<PendingGather> LocalJob::startAllgatherv(std::vector<double> mine,
                                                         const std::vector<size_t>& lengths) {
  if (lengths.size() != 1 || lengths[0] != mine.size())
    throw std::logic_error("LocalJob::startAllgatherv: lengths do not describe one rank's buffer");
  return std::make_unique<LocalGather>(std::move(mine));
}

}  // namespace relt
