// Threads inside a rank (parallel/workers.h): every worker runs once with its own index, failures
// come back to the caller, counters add up across workers, and --threads on auto takes the cores
// the rank may use.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel/workers.h"

using namespace relt;

TEST(Workers, EveryWorkerRunsOnceOnAThreadOfItsOwn) {
  std::mutex m;
  std::vector<int> seen;
  std::set<std::thread::id> threads;
  runOnWorkers(4, [&](int w) {
    std::lock_guard lock(m);
    seen.push_back(w);
    EXPECT_EQ(currentWorker(), w);
    threads.insert(std::this_thread::get_id());
  });
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(threads.size(), 4u);
  EXPECT_EQ(currentWorker(), 0) << "the caller is worker 0 again";
}

TEST(Workers, OneWorkerRunsOnTheCallingThread) {
  const std::thread::id caller = std::this_thread::get_id();
  int runs = 0;
  runOnWorkers(1, [&](int w) {
    EXPECT_EQ(w, 0);
    EXPECT_EQ(std::this_thread::get_id(), caller);
    ++runs;
  });
  EXPECT_EQ(runs, 1);
}

TEST(Workers, AWorkersFailureReachesTheCallerAfterAllEnded) {
  std::atomic<int> ended{0};
  EXPECT_THROW(runOnWorkers(3,
                            [&](int w) {
                              ++ended;
                              if (w == 2) throw std::runtime_error("worker 2");
                            }),
               std::runtime_error);
  EXPECT_EQ(ended.load(), 3);
}

TEST(Workers, ACountAddsUpOverWorkers) {
  PerWorkerCount count;
  runOnWorkers(3, [&](int w) {
    for (int k = 0; k < 100000; ++k) count.add(uint64_t(w + 1));
  });
  EXPECT_EQ(count.total(), 600000u);
}

TEST(Workers, AutoThreadsTakeTheRanksShareOfItsCores) {
  EXPECT_EQ(defaultThreads(1, 2, 2), 1) << "mpirun --bind-to core: one core each";
  EXPECT_EQ(defaultThreads(4, 64, 1), 4) << "bound to four cores";
  EXPECT_EQ(defaultThreads(2, 2, 1), 2) << "a plain run takes every core";
  EXPECT_EQ(defaultThreads(64, 64, 4), 16) << "unbound ranks share the node";
  EXPECT_EQ(defaultThreads(2, 2, 3), 1) << "oversubscribed: never fewer than one";
  EXPECT_GE(coresAvailable(), 1);
  EXPECT_LE(coresAvailable(), coresOnline());
}

// A rank's share of a bootstrap (samples 1, 4, 7, ... of 3 ranks) split over 1, 2 or 5 workers:
// every sample computed once, by the worker the rule names, and the same sums bit for bit.
TEST(Workers, ASplitOfARanksSamplesIsTheSameOnAnyWorkerCount) {
  const int count = 23;
  auto value = [](int i) { return 1.0 / (3.0 + i); };  // not exact in binary: order would show
  std::vector<double> one;
  for (int workers : {1, 2, 5}) {
    std::vector<int> computedBy(count, -1);
    const std::vector<double> sum = sumOfWorkerShares(workers, 1, 3, [&](int w, int first, int stride) {
      std::vector<double> part(count, 0.0);
      for (int i = first; i < count; i += stride) {
        part[size_t(i)] = value(i);
        computedBy[size_t(i)] = w;
      }
      return part;
    });
    for (int i = 0; i < count; ++i) {
      EXPECT_EQ(computedBy[size_t(i)], i % 3 == 1 ? (i / 3) % workers : -1) << i;
      EXPECT_EQ(sum[size_t(i)], i % 3 == 1 ? value(i) : 0.0) << i;
    }
    if (one.empty()) one = sum;
    EXPECT_EQ(sum, one);
  }
}
