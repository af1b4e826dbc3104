#include "comm.h"

#include <chrono>

namespace relt::mpi {
namespace {
double g_collectiveSeconds = 0.0;

// Times one collective call, including the wait for the slowest rank.
template <class F>
void timed(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  g_collectiveSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

Session::Session(int* argc, char*** argv) {
  MPI_Init(argc, argv);
  // A failed rank must end the job with an error, never hang it.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() { MPI_Finalize(); }

void allreduceSum(std::vector<double>& data) {
  timed([&] {
    MPI_Allreduce(MPI_IN_PLACE, data.data(), static_cast<int>(data.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  });
}

void reduceSumToRoot(std::vector<double>& data, int root) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // MPI counts are int: reduce in chunks so large films (per-level layers) stay within range.
  const size_t chunk = size_t(1) << 28;
  timed([&] {
    for (size_t off = 0; off < data.size(); off += chunk) {
      const int n = static_cast<int>(std::min(chunk, data.size() - off));
      if (rank == root)
        MPI_Reduce(MPI_IN_PLACE, data.data() + off, n, MPI_DOUBLE, MPI_SUM, root, MPI_COMM_WORLD);
      else
        MPI_Reduce(data.data() + off, nullptr, n, MPI_DOUBLE, MPI_SUM, root, MPI_COMM_WORLD);
    }
  });
}

double allreduceMax(double value) {
  double out = value;
  timed([&] { MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD); });
  return out;
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
std::vector<std::vector<uint64_t>> transfer(const std::vector<Payload>& sends, const std::vector<int>& receiveFrom) {
  constexpr int kTag = 7;
  std::vector<std::vector<uint64_t>> received(receiveFrom.size());
  timed([&] {
    std::vector<MPI_Request> requests(sends.size());
    for (size_t i = 0; i < sends.size(); ++i)
      MPI_Isend(sends[i].data.data(), static_cast<int>(sends[i].data.size()), MPI_UINT64_T, sends[i].rank, kTag,
                MPI_COMM_WORLD, &requests[i]);
    for (size_t i = 0; i < receiveFrom.size(); ++i) {
      MPI_Status status;
      MPI_Probe(receiveFrom[i], kTag, MPI_COMM_WORLD, &status);
      int count = 0;
      MPI_Get_count(&status, MPI_UINT64_T, &count);
      received[i].resize(static_cast<size_t>(count));
      MPI_Recv(received[i].data(), count, MPI_UINT64_T, receiveFrom[i], kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  });
  return received;
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

std::vector<std::vector<double>> PendingAllgatherv::wait() {
  timed([&] { MPI_Wait(&request_, MPI_STATUS_IGNORE); });
  std::vector<std::vector<double>> out(counts_.size());
  for (size_t r = 0; r < counts_.size(); ++r)
    out[r].assign(all_.begin() + offsets_[r], all_.begin() + offsets_[r] + counts_[r]);
  return out;
}
}  // namespace relt::mpi
