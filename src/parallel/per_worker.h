#pragma once
// One object per worker thread of a rank, all made from the same arguments: evaluators, whose
// scratch must not be shared between threads. Zero workers make none (a kind of evaluator a
// render does not use).
#include <deque>

namespace relt {

template <class T>
class PerWorker {
 public:
  template <class... Args>
  explicit PerWorker(int workers, const Args&... args) {
    for (int w = 0; w < workers; ++w) items_.emplace_back(args...);
  }
  T& operator[](int worker) { return items_[size_t(worker)]; }
  const T& operator[](int worker) const { return items_[size_t(worker)]; }
  int size() const { return int(items_.size()); }

 private:
  std::deque<T> items_;  // a deque: T need not be movable
};

}  // namespace relt
