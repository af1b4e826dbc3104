#include "parallel/workers.h"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace relt {
namespace {

thread_local int tWorker = 0;

}  // namespace

int coresAvailable() {
  cpu_set_t set;
  CPU_ZERO(&set);
  int cores = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : 0;
  if (cores <= 0) cores = int(std::thread::hardware_concurrency());
  return std::clamp(cores, 1, kMaxWorkers);
}

int coresOnline() { return std::clamp(int(sysconf(_SC_NPROCESSORS_ONLN)), 1, kMaxWorkers); }

int defaultThreads(int affinity, int online, int ranksOnNode) {
  if (affinity < online) return std::max(affinity, 1);
  return std::clamp(online / std::max(ranksOnNode, 1), 1, kMaxWorkers);
}

int currentWorker() { return tWorker; }

void runOnWorkers(int workers, const std::function<void(int worker)>& work) {
  if (workers <= 1) {
    work(0);
    return;
  }
  std::vector<std::exception_ptr> failed(static_cast<size_t>(workers));
  auto run = [&](int w) {
    tWorker = w;
    try {
      work(w);
    } catch (...) {
      failed[size_t(w)] = std::current_exception();
    }
    tWorker = 0;
  };
  std::vector<std::thread> threads;
  threads.reserve(size_t(workers - 1));
  for (int w = 1; w < workers; ++w) threads.emplace_back(run, w);
  run(0);
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

void runInOrder(int workers, size_t n, const std::function<void(size_t k, int worker)>& item,
                const std::function<void(size_t k)>& after) {
  std::vector<std::atomic<bool>> done(n);
  std::atomic<size_t> next{0};
  size_t finished = 0;  // after() has run for 0 .. finished - 1
  auto catchUp = [&] {
    for (; finished < n && done[finished].load(std::memory_order_acquire); ++finished) after(finished);
  };
  runOnWorkers(workers, [&](int w) {
    for (size_t k = next++; k < n; k = next++) {
      item(k, w);
      done[k].store(true, std::memory_order_release);
      if (w == 0) catchUp();
    }
  });
  catchUp();
}

std::vector<double> sumOfWorkerShares(int workers, int first, int stride,
                                      const std::function<std::vector<double>(int worker, int first, int stride)>& part) {
  workers = std::max(workers, 1);
  std::vector<std::vector<double>> parts(static_cast<size_t>(workers));
  runOnWorkers(workers, [&](int w) { parts[size_t(w)] = part(w, first + w * stride, workers * stride); });
  std::vector<double> sum = std::move(parts[0]);
  for (size_t w = 1; w < parts.size(); ++w)
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += parts[w][i];
  return sum;
}

}  // namespace relt
