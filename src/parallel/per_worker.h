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
  T& operator[](int worker) { return items_[size_t(worker)].item; }
  const T& operator[](int worker) const { return items_[size_t(worker)].item; }
  int size() const { return int(items_.size()); }

 private:
  // Each on cache lines of its own: workers write their objects' members all the time, and two
  // objects sharing a line would pass it back and forth between the cores.
  struct alignas(64) Slot {
    template <class... Args>
    explicit Slot(const Args&... args) : item(args...) {}
    T item;
  };
  std::deque<Slot> items_;  // a deque: T need not be movable
};

}  // namespace relt
