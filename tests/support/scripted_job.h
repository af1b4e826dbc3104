#pragma once
// A job of one process whose collectives a test scripts, to play the other ranks: the largest of
// every rank's value (the slowest rank's time), what the others add to a sum, and a stop or save
// request agreed at the n-th agreement.
#include <deque>
#include <functional>

#include "parallel/local_job.h"

namespace relt::test {

class ScriptedJob final : public LocalJob {
 public:
  // The maxima over ranks, in turn (empty: this rank's own value).
  std::deque<double> maxima;
  // What the other ranks add to every sum of one number.
  double othersAdd = 0.0;
  // At this agreement (1 is the first; 0: never) the ranks agree to stop, or to save.
  int stopAt = 0, saveAt = 0;

  double allreduceMax(double value) override {
    if (maxima.empty()) return value;
    const double slowest = maxima.front();
    maxima.pop_front();
    return slowest;
  }
  double allreduceSum(double value) override { return value + othersAdd; }
  JobAgreement agree(double elapsed) override {
    ++agreements_;
    if (agreements_ == stopAt) requestStop();
    if (agreements_ == saveAt) requestSave();
    return LocalJob::agree(elapsed);
  }

 private:
  int agreements_ = 0;
};

}  // namespace relt::test
