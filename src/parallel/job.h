#pragma once
// What an integrator needs from the job it runs in: its rank among the job's processes, the
// collectives it decides with, and the round exchange's nonblocking gather. The MPI layer
// (mpi/mpi_job.h) implements it across ranks; LocalJob (parallel/local_job.h) is a job of one
// process, for tests and for renders without mpirun. Every call is collective unless it says not:
// every rank makes the same calls in the same order, from its main thread only.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace relt {

// What the ranks decide together after a pass or round: the largest elapsed time, whether any
// rank was asked to stop (then stopAgreed() holds from here on), and whether any was asked to
// save (write the image so far and a checkpoint now).
struct JobAgreement {
  double elapsed = 0.0;
  bool stop = false;
  bool save = false;
};

// Words sent to one rank (Job::transfer).
struct Payload {
  int rank;
  std::vector<uint64_t> data;
};

// A stop or save request the ranks agreed on apart from the round messages: the round loop acts on
// it after round `round` - 1 (when group 0 has finished it), on every rank.
struct RequestAgreement {
  uint64_t round = 0;
  bool stop = false, save = false;
};

// Stop and save requests agreed apart from the round messages, for relt's local decisions, whose
// messages come back many rounds late (mpi/request_channel.h says how the ranks agree).
class RequestChannel {
 public:
  virtual ~RequestChannel() = default;
  // After group 0's round: `rounds` rounds done, this rank's requests since the last call. Returns
  // what the ranks agreed to do at this point, if anything.
  virtual std::optional<RequestAgreement> at(uint64_t rounds, bool stop, bool save) = 0;
  // Between chains and while waiting for other ranks: joins an agreement another rank started.
  virtual void poll() = 0;
  // Collective, at the loop's end on every rank: completes an agreement under way, drops it.
  virtual void close() = 0;
  // Waits for every rank to get here, polling: before the collectives of snapshots and checkpoints.
  virtual void barrier() = 0;
};

// A gather of every rank's buffer under way (Job::startAllgatherv).
class PendingGather {
 public:
  virtual ~PendingGather() = default;
  // Every rank's buffer, in rank order; `idle` (if any) runs between tests while waiting.
  virtual std::vector<std::vector<double>> wait(const std::function<void()>& idle = {}) = 0;
  // Lets the gather advance (MPI moves a nonblocking collective only inside its calls). Not collective.
  virtual void test() {}
  // Completes it (wait() then returns at once); `idle` as for wait().
  virtual void complete(const std::function<void()>& idle = {}) = 0;
};

class Job {
 public:
  virtual ~Job() = default;
  // Not collective.
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool isRoot() const { return rank() == 0; }

  // Element-wise sums onto the root: in place (other ranks' buffers unchanged), or into
  // `sumsOnRoot` (room for send.size() doubles on the root, ignored elsewhere).
  virtual void reduceSumToRoot(std::vector<double>& data) = 0;
  virtual void reduceSumToRoot(const std::vector<double>& send, double* sumsOnRoot) = 0;
  // Sums and maxima over all ranks, the result on every rank.
  virtual void allreduceSum(std::vector<double>& data) = 0;
  virtual double allreduceSum(double value) = 0;
  virtual uint64_t allreduceSum(uint64_t value) = 0;
  virtual double allreduceMax(double value) = 0;
  virtual int allreduceMax(int value) = 0;
  // Every rank's value (or host name), in rank order, on every rank.
  virtual std::vector<double> allgather(double value) = 0;
  virtual std::vector<std::string> processorNames() = 0;
  // Every rank's words on the root, in rank order (empty elsewhere).
  virtual std::vector<std::vector<uint64_t>> gatherToRoot(const std::vector<uint64_t>& mine) = 0;
  virtual std::vector<std::vector<double>> gatherToRoot(const std::vector<double>& mine) = 0;
  // The root's words (or text) on every rank.
  virtual void broadcastFromRoot(std::vector<uint64_t>& words) = 0;
  virtual void broadcastFromRoot(std::vector<double>& values) = 0;
  virtual void broadcastFromRoot(std::string& text) = 0;
  // A problem the root found (empty: none) becomes the same InputError on every rank.
  virtual void shareRootProblem(std::string problem) = 0;

  // The agreement after a pass or round, from every rank's elapsed time and requests.
  virtual JobAgreement agree(double elapsed) = 0;
  // Not collective: a rank was asked to stop, or to save since it last asked (true once per request).
  virtual bool stopRequested() const = 0;
  virtual bool takeSaveRequest() = 0;
  // Not collective: the ranks agreed to stop (by agree()); the render writes what it has.
  virtual bool stopAgreed() const = 0;
  // Not collective: the ranks agreed to stop by other means (relt's round messages), on every rank.
  virtual void markStopAgreed() = 0;

  // Point-to-point payloads of any length: `sends` go out, and one payload arrives from each rank
  // of `receiveFrom`, returned in that order; between two ranks payloads keep their order. Every
  // rank of a plan takes part; `idle` (if any) runs between tests while waiting.
  virtual std::vector<std::vector<uint64_t>> transfer(const std::vector<Payload>& sends,
                                                      const std::vector<int>& receiveFrom,
                                                      const std::function<void()>& idle = {}) = 0;
  // Starts a gather of every rank's buffer, rank r's `lengths[r]` long (known to all in advance).
  virtual std::unique_ptr<PendingGather> startAllgatherv(std::vector<double> mine,
                                                         const std::vector<size_t>& lengths) = 0;
  // A channel for requests apart from the round messages, or none when requests need no channel
  // (one process acts on its own requests at once).
  virtual std::unique_ptr<RequestChannel> openRequestChannel() = 0;
  // Not collective: wall-clock seconds this rank has spent inside the calls above.
  virtual double collectiveSeconds() const = 0;
};

}  // namespace relt
