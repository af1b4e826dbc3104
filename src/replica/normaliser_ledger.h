#pragma once
// The sums relt's level normalisers b_k rest on (DESIGN §3.3): every level's targets summed over the
// bootstrap and over every large step read back, b_k = (bootstrap sum + large-step sum) / samples.
// When the regularisation moves the targets (a new epoch) both start again from nothing: sums
// under the old targets would bias the normalisers. The same on every rank (same read-backs).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace relt {

class NormaliserLedger {
 public:
  explicit NormaliserLedger(int levels);

  // The bootstrap: one sample's targets of every level, then the sample count once all are in.
  void addBootstrapSample(const double* targets);
  void bootstrapDone(double samples);
  // A round's large steps read back: their targets' sums per level and how many they were.
  void addLargeSteps(std::span<const double> sums, double count);
  // The regularisation moved the targets: the sums start again.
  void targetsMoved();

  // b_k from everything summed so far; nothing before the first sample of the current targets.
  std::optional<std::vector<double>> normalisers() const;
  double bootstrapSum(int level) const { return bootstrapSum_[size_t(level)]; }
  double samples() const { return bootstrapCount_ + largeCount_; }
  uint64_t epoch() const { return epoch_; }
  // The targets moved and have fewer large steps than the bootstrap had samples.
  bool fewSamplesSinceMove() const { return epoch_ > 0 && largeCount_ < bootstrapSamples_; }

  // What a checkpoint keeps of it.
  struct State {
    double bootstrapSamples = 0.0;  // the bootstrap's size, also after the targets moved
    uint64_t epoch = 0;             // moves of the targets so far
    std::vector<double> bootstrapSum;
    double bootstrapCount = 0.0;
    std::vector<double> largeSum;
    double largeCount = 0.0;
  };
  State state() const { return {bootstrapSamples_, epoch_, bootstrapSum_, bootstrapCount_, largeSum_, largeCount_}; }
  void restore(State state);

 private:
  double bootstrapSamples_ = 0.0;
  uint64_t epoch_ = 0;
  std::vector<double> bootstrapSum_;
  double bootstrapCount_ = 0.0;
  std::vector<double> largeSum_;  // all ranks' large-step sums so far
  double largeCount_ = 0.0;
};

}  // namespace relt
