#include "comm.h"

#include "core/error.h"
#include "interrupt.h"

#include <algorithm>
#include <bit>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <thread>

namespace relt::mpi {
namespace {
double g_collectiveSeconds = 0.0;
// When this rank entered the collective it is waiting in (steady-clock nanoseconds), 0 outside.
std::atomic<int64_t> g_waitingSince{0};

int64_t nowNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Times one collective call, including the wait for the slowest rank.
template <class F>
void timed(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  g_waitingSince = nowNanoseconds();
  f();
  g_waitingSince = 0;
  g_collectiveSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Completes `requests`: blocking, or with `idle` run between tests (it must not block).
void waitPolling(MPI_Request* requests, int count, const std::function<void()>& idle) {
  if (!idle) {
    MPI_Waitall(count, requests, MPI_STATUSES_IGNORE);
    return;
  }
  for (int done = 0; !done;) {
    MPI_Testall(count, requests, &done, MPI_STATUSES_IGNORE);
    if (!done) idle();
  }
}

// Ends this process when it has waited longer than `timeout` seconds in one collective: mpirun
// then ends the whole job with an error. Open MPI itself ends the job when a rank dies, but not
// when a rank stalls or a host disappears without its daemon noticing.
class StallWatchdog {
 public:
  StallWatchdog(double timeout, int rank) : timeout_(timeout), rank_(rank), thread_([this] { watch(); }) {}
  ~StallWatchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }

 private:
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return done_; })) {
      const int64_t since = g_waitingSince.load();
      if (since == 0 || (nowNanoseconds() - since) * 1e-9 < timeout_) continue;
      std::fprintf(stderr,
                   "relt: error: rank %d waited %.0f s for the other ranks: a rank or its host failed or stalled; "
                   "ending the job (--stall-timeout)\n",
                   rank_, timeout_);
      std::fflush(stderr);
      std::_Exit(1);
    }
  }
  double timeout_;
  int rank_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};
std::unique_ptr<StallWatchdog> g_watchdog;

}  // namespace

void startStallWatchdog(double timeoutSeconds) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  g_watchdog.reset();
  if (timeoutSeconds > 0.0) g_watchdog = std::make_unique<StallWatchdog>(timeoutSeconds, rank);
}

Session::Session(int* argc, char*** argv) {
  // Worker threads (--threads) never call MPI; the main thread, worker 0, makes every call.
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  // A failed rank must end the job with an error, never hang it.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() {
  g_watchdog.reset();
  MPI_Finalize();
}

void allreduceSum(std::vector<double>& data) {
  timed([&] {
    MPI_Allreduce(MPI_IN_PLACE, data.data(), static_cast<int>(data.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  });
}

namespace {

// MPI_Reduce of `size` doubles from `send` (MPI_IN_PLACE allowed on the root) into `recv`, in
// chunks: MPI counts are int, and large films (per-level layers) exceed them.
void reduceChunks(const double* send, double* recv, size_t size, int root) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const size_t chunk = size_t(1) << 28;
  timed([&] {
    for (size_t off = 0; off < size; off += chunk) {
      const int n = static_cast<int>(std::min(chunk, size - off));
      const void* from = send == MPI_IN_PLACE ? MPI_IN_PLACE : send + off;
      MPI_Reduce(from, rank == root ? recv + off : nullptr, n, MPI_DOUBLE, MPI_SUM, root, MPI_COMM_WORLD);
    }
  });
}

}  // namespace

void reduceSumToRoot(std::vector<double>& data, int root) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  reduceChunks(rank == root ? static_cast<const double*>(MPI_IN_PLACE) : data.data(), data.data(), data.size(), root);
}

void reduceSumToRoot(const std::vector<double>& send, double* sumsOnRoot, int root) {
  reduceChunks(send.data(), sumsOnRoot, send.size(), root);
}

double allreduceMax(double value) {
  double out = value;
  timed([&] { MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD); });
  return out;
}

JobAgreement agree(double elapsed) {
  double mine[3] = {elapsed, stopSignalled() ? 1.0 : 0.0, takeSaveRequest() ? 1.0 : 0.0}, all[3];
  timed([&] { MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD); });
  if (all[1] > 0.0) markStopAgreed();
  return {all[0], all[1] > 0.0, all[2] > 0.0};
}

double allreduceSum(double value) {
  double out = value;
  timed([&] { MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD); });
  return out;
}

uint64_t allreduceSum(uint64_t value) {
  uint64_t out = value;
  timed([&] { MPI_Allreduce(&value, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD); });
  return out;
}

int allreduceMax(int value) {
  int out = value;
  timed([&] { MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD); });
  return out;
}

double collectiveSeconds() { return g_collectiveSeconds; }

}  // namespace relt::mpi

namespace relt::mpi {
std::vector<double> allgather(double value) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::vector<double> out(static_cast<size_t>(size));
  MPI_Allgather(&value, 1, MPI_DOUBLE, out.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
  return out;
}

std::vector<std::string> processorNames() {
  int size = 1, length = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::vector<char> mine(MPI_MAX_PROCESSOR_NAME, '\0'), all(size_t(size) * MPI_MAX_PROCESSOR_NAME);
  MPI_Get_processor_name(mine.data(), &length);
  MPI_Allgather(mine.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, all.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR,
                MPI_COMM_WORLD);
  std::vector<std::string> out;
  for (int r = 0; r < size; ++r) out.emplace_back(all.data() + size_t(r) * MPI_MAX_PROCESSOR_NAME);
  return out;
}

}  // namespace relt::mpi

namespace relt::mpi {
std::vector<std::vector<uint64_t>> transfer(const std::vector<Payload>& sends, const std::vector<int>& receiveFrom,
                                            const std::function<void()>& idle) {
  constexpr int kTag = 7;
  std::vector<std::vector<uint64_t>> received(receiveFrom.size());
  timed([&] {
    std::vector<MPI_Request> requests(sends.size());
    for (size_t i = 0; i < sends.size(); ++i)
      MPI_Isend(sends[i].data.data(), static_cast<int>(sends[i].data.size()), MPI_UINT64_T, sends[i].rank, kTag,
                MPI_COMM_WORLD, &requests[i]);
    for (size_t i = 0; i < receiveFrom.size(); ++i) {
      MPI_Status status;
      if (!idle) MPI_Probe(receiveFrom[i], kTag, MPI_COMM_WORLD, &status);
      for (int found = 0; idle && !found;) {
        MPI_Iprobe(receiveFrom[i], kTag, MPI_COMM_WORLD, &found, &status);
        if (!found) idle();
      }
      int count = 0;
      MPI_Get_count(&status, MPI_UINT64_T, &count);
      received[i].resize(static_cast<size_t>(count));
      MPI_Recv(received[i].data(), count, MPI_UINT64_T, receiveFrom[i], kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    waitPolling(requests.data(), static_cast<int>(requests.size()), idle);
  });
  return received;
}

void waitTimed(MPI_Request& request, const std::function<void()>& idle) {
  timed([&] { waitPolling(&request, 1, idle); });
}
}  // namespace relt::mpi

namespace relt::mpi {
PendingAllgatherv::PendingAllgatherv(std::vector<double> mine, const std::vector<size_t>& lengths)
    : mine_(std::move(mine)), counts_(lengths.size()), offsets_(lengths.size()) {
  int total = 0;
  for (size_t r = 0; r < lengths.size(); ++r) {
    counts_[r] = static_cast<int>(lengths[r]);
    offsets_[r] = total;
    total += counts_[r];
  }
  all_.resize(static_cast<size_t>(total));
  timed([&] {
    MPI_Iallgatherv(mine_.data(), static_cast<int>(mine_.size()), MPI_DOUBLE, all_.data(), counts_.data(),
                    offsets_.data(), MPI_DOUBLE, MPI_COMM_WORLD, &request_);
  });
}

PendingAllgatherv::~PendingAllgatherv() {
  if (request_ != MPI_REQUEST_NULL) MPI_Wait(&request_, MPI_STATUS_IGNORE);
}

void PendingAllgatherv::test() {
  int done = 0;
  if (request_ != MPI_REQUEST_NULL) MPI_Test(&request_, &done, MPI_STATUS_IGNORE);
}

void PendingAllgatherv::complete(const std::function<void()>& idle) {
  if (request_ != MPI_REQUEST_NULL) waitTimed(request_, idle);
}

std::vector<std::vector<double>> PendingAllgatherv::wait(const std::function<void()>& idle) {
  complete(idle);
  std::vector<std::vector<double>> out(counts_.size());
  for (size_t r = 0; r < counts_.size(); ++r)
    out[r].assign(all_.begin() + offsets_[r], all_.begin() + offsets_[r] + counts_[r]);
  return out;
}
}  // namespace relt::mpi

namespace relt::mpi {
std::vector<std::vector<uint64_t>> gatherToRoot(const std::vector<uint64_t>& mine) {
  int size = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<std::vector<uint64_t>> out;
  timed([&] {
    const int count = static_cast<int>(mine.size());
    std::vector<int> counts(static_cast<size_t>(size)), offsets(static_cast<size_t>(size));
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<uint64_t> all;
    if (rank == 0) {
      size_t total = 0;
      for (int r = 0; r < size; ++r) {
        offsets[size_t(r)] = static_cast<int>(total);
        total += size_t(counts[size_t(r)]);
      }
      all.resize(total);
    }
    MPI_Gatherv(mine.data(), count, MPI_UINT64_T, all.data(), counts.data(), offsets.data(), MPI_UINT64_T, 0,
                MPI_COMM_WORLD);
    if (rank == 0)
      for (int r = 0; r < size; ++r)
        out.emplace_back(all.begin() + offsets[size_t(r)], all.begin() + offsets[size_t(r)] + counts[size_t(r)]);
  });
  return out;
}

std::vector<std::vector<double>> gatherToRoot(const std::vector<double>& mine) {
  std::vector<uint64_t> words(mine.size());
  std::transform(mine.begin(), mine.end(), words.begin(), [](double v) { return std::bit_cast<uint64_t>(v); });
  std::vector<std::vector<double>> out;
  for (const std::vector<uint64_t>& rank : gatherToRoot(words)) {
    out.emplace_back(rank.size());
    std::transform(rank.begin(), rank.end(), out.back().begin(), [](uint64_t w) { return std::bit_cast<double>(w); });
  }
  return out;
}

void broadcastFromRoot(std::vector<uint64_t>& words) {
  timed([&] {
    uint64_t n = words.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    words.resize(n);
    constexpr uint64_t kChunk = uint64_t(1) << 26;  // MPI counts are int
    for (uint64_t at = 0; at < n; at += kChunk)
      MPI_Bcast(words.data() + at, static_cast<int>(std::min(kChunk, n - at)), MPI_UINT64_T, 0, MPI_COMM_WORLD);
  });
}

void broadcastFromRoot(std::vector<double>& values) {
  std::vector<uint64_t> words(values.size());
  std::memcpy(words.data(), values.data(), values.size() * sizeof(double));
  broadcastFromRoot(words);
  values.resize(words.size());
  std::memcpy(values.data(), words.data(), words.size() * sizeof(double));
}

void broadcastFromRoot(std::string& text) {
  std::vector<uint64_t> words((text.size() + 7) / 8 + 1, 0);
  words[0] = text.size();
  std::memcpy(words.data() + 1, text.data(), text.size());
  broadcastFromRoot(words);
  text.assign(reinterpret_cast<const char*>(words.data() + 1), size_t(words[0]));
}

void shareRootProblem(std::string problem) {
  broadcastFromRoot(problem);
  if (!problem.empty()) throw InputError("", "", problem);
}
int ranksOnThisNode() {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks = 1;
  MPI_Comm_size(node, &ranks);
  MPI_Comm_free(&node);
  return ranks;
}

}  // namespace relt::mpi
