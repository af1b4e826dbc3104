#pragma once
// RAII MPI session and the few typed collectives relt needs. Only this layer includes mpi.h.
#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "parallel/job.h"

namespace relt::mpi {

class Session {
 public:
  Session(int* argc, char*** argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }

 private:
  int rank_ = 0, size_ = 1;
};

// How many ranks of the job run on this rank's node (collective).
int ranksOnThisNode();

// From now on a rank that waits longer than this in one collective ends the job with a message
// and status 1 (0: never). Rendering work between collectives does not count.
void startStallWatchdog(double timeoutSeconds);

// Sum of a double buffer onto the root (in place on the root).
void reduceSumToRoot(std::vector<double>& data, int root = 0);
// The same into `sumsOnRoot` (room for send.size() doubles on the root, ignored elsewhere): no
// copy of `send` is made.
void reduceSumToRoot(const std::vector<double>& send, double* sumsOnRoot, int root = 0);
// Element-wise sum over all ranks, result on every rank.
void allreduceSum(std::vector<double>& data);
double allreduceMax(double value);
double allreduceSum(double value);
uint64_t allreduceSum(uint64_t value);
int allreduceMax(int value);
// The ranks' agreement after a pass or round (Job::agree); a stop agreed makes stopAgreed() in
// interrupt.h hold from here on.
JobAgreement agree(double elapsed);
// Wall-clock seconds spent inside collectives by this rank, accumulated by the functions above.
double collectiveSeconds();

}  // namespace relt::mpi

namespace relt::mpi {
// Every rank's value, in rank order, on every rank.
std::vector<double> allgather(double value);
// Every rank's processor (host) name, in rank order, on every rank.
std::vector<std::string> processorNames();
}  // namespace relt::mpi

namespace relt::mpi {
// Point-to-point payloads of any length: `sends` go out (rank, data), and one payload arrives from
// each rank of `receiveFrom`, returned in that order. Between two ranks payloads keep their order.
// Counted as collective time (every rank of a plan takes part).
// While waiting, `idle` (if any) runs between tests (the request channel's poll).
std::vector<std::vector<uint64_t>> transfer(const std::vector<Payload>& sends, const std::vector<int>& receiveFrom,
                                            const std::function<void()>& idle = {});
// Completes `request`, counted as collective time (and watched for stalls) like the collectives
// here; `idle` (if any) runs between tests while waiting.
void waitTimed(MPI_Request& request, const std::function<void()>& idle = {});
}  // namespace relt::mpi

namespace relt::mpi {
// Every rank's buffer, in rank order, on every rank, by a nonblocking MPI_Iallgatherv: started by
// the constructor, completed by wait() (the time in wait counts as collective time); lengths[r] is
// rank r's buffer length, known to all in advance. Not movable: MPI holds the buffers until then.
class PendingAllgatherv final : public PendingGather {
 public:
  PendingAllgatherv(std::vector<double> mine, const std::vector<size_t>& lengths);
  PendingAllgatherv(const PendingAllgatherv&) = delete;
  PendingAllgatherv& operator=(const PendingAllgatherv&) = delete;
  ~PendingAllgatherv();
  // Every rank's buffer, in rank order; `idle` (if any) runs between tests while waiting.
  std::vector<std::vector<double>> wait(const std::function<void()>& idle = {}) override;
  // Lets MPI advance the collective (Open MPI moves a nonblocking collective only inside MPI calls).
  void test() override;
  // Completes it, counted as collective time (wait() then returns at once); `idle` as for wait().
  void complete(const std::function<void()>& idle = {}) override;

 private:
  std::vector<double> mine_, all_;
  std::vector<int> counts_, offsets_;
  MPI_Request request_ = MPI_REQUEST_NULL;
};
}  // namespace relt::mpi

namespace relt::mpi {
// Every rank's words on the root, in rank order (empty elsewhere).
std::vector<std::vector<uint64_t>> gatherToRoot(const std::vector<uint64_t>& mine);
std::vector<std::vector<double>> gatherToRoot(const std::vector<double>& mine);
// The root's words (or text) on every rank.
void broadcastFromRoot(std::vector<uint64_t>& words);
void broadcastFromRoot(std::vector<double>& values);
void broadcastFromRoot(std::string& text);
// A problem the root found (empty: none) becomes the same InputError on every rank.
void shareRootProblem(std::string problem);
}  // namespace relt::mpi
