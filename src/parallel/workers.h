#pragma once
// Threads inside a rank: one call run by N workers at once, each knowing its index, and counters
// each worker adds to without sharing a cache line with the others.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace relt {

// Most workers a rank runs (--threads); counters keep a slot for each.
constexpr int kMaxWorkers = 256;

// The cores this process may run on: its CPU affinity (1 under mpirun --bind-to core, every core
// for a plain run), at least 1 and at most kMaxWorkers.
int coresAvailable();

// The cores of the machine (online), at least 1.
int coresOnline();

// --threads on auto: the cores this rank may use. A launcher that bound the rank (its affinity is
// narrower than the machine, e.g. mpirun --bind-to core) gave it `affinity` cores; an unbound rank
// shares the machine with the other `ranksOnNode` ranks there, so takes its share of it.
int defaultThreads(int affinity, int online, int ranksOnNode);

// The index of the worker the calling thread is: 0 outside runOnWorkers.
int currentWorker();

// Runs work(w) for w = 0 .. workers - 1 at once (w = 0 on the calling thread) and returns when all
// have ended; an exception thrown by a worker is rethrown then (the lowest worker's if several).
void runOnWorkers(int workers, const std::function<void(int worker)>& work);

// Runs item(k, worker) for k = 0 .. n - 1 on `workers` threads, each taking the next k as soon as
// it is free (none waits for another's dearer items), and after(k) on the calling thread (worker
// 0) for every k in order, as soon as k and every item before it are done: results kept per item
// are combined in one order whatever the workers did. Returns when every after(k) has run.
void runInOrder(int workers, size_t n, const std::function<void(size_t k, int worker)>& item,
                const std::function<void(size_t k)>& after);

// A rank's share of a sequence of samples (first, first + stride, ...) split over its workers:
// worker w computes part(w, first + w * stride, workers * stride), a vector with its samples'
// entries and zeros elsewhere; the parts are summed. Every entry comes from one worker, so the sum
// is exact: the result does not depend on the number of workers (bootstraps).
std::vector<double> sumOfWorkerShares(int workers, int first, int stride,
                                      const std::function<std::vector<double>(int worker, int first, int stride)>& part);

// A count every worker adds to at full speed (a slot per worker), read as the total.
class PerWorkerCount {
 public:
  void add(uint64_t n) { slots_[currentWorker()].n += n; }
  uint64_t total() const {
    uint64_t sum = 0;
    for (const Slot& s : slots_) sum += s.n;
    return sum;
  }

 private:
  struct alignas(64) Slot {
    uint64_t n = 0;
  };
  std::array<Slot, kMaxWorkers> slots_{};
};

}  // namespace relt
