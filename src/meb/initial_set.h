#pragma once
// meb's start-up (thesis digest §2.5 and §5.3): independent uniform light subpaths, from which
// every chain pair of the iteration resamples its start states (the visibility chain's in
// proportion to 1[C > 0], the contribution chain's to lum(C)), and whose targets start the
// normalisers' estimate. Sample j's coordinates come from the stream keyed (key, j).
#include <cstdint>
#include <vector>

#include "core/sampling.h"
#include "meb/chain_pair.h"

namespace relt {

template <class Contribution>
class MebInitialSet {
 public:
  using State = typename MebChainPair<Contribution>::State;

  // Calls evaluate(SampleSource&, j) for j in [first, end) and keeps the samples with C > 0.
  template <class Evaluate>
  void evaluate(uint64_t key, uint32_t first, uint32_t end, Evaluate&& evaluate) {
    for (uint32_t j = first; j < end; ++j) {
      Rng fresh(key, j);
      State s;
      GrowingPoint point(s.u, fresh);
      s.c = evaluate(static_cast<SampleSource&>(point), j);
      const double lum = s.c.luminance();
      sums_.add(lum);
      if (lum > 0.0) visible_.push_back(std::move(s));
    }
  }
  // Appends another part's samples (parts evaluated apart, joined in the order of their j).
  void append(MebInitialSet&& part) {
    sums_.add(part.sums_);
    for (State& s : part.visible_) visible_.push_back(std::move(s));
  }
  // Evaluates kept samples first .. end - 1 again from their coordinates (the same subpaths, other
  // weights: meb's light subpath factor). Parts may run at once; then call rescored().
  template <class Evaluate>
  void rescore(size_t first, size_t end, Evaluate&& evaluate) {
    for (size_t i = first; i < end; ++i) {
      Rng unused(0);  // the subpath reads the coordinates it read before
      GrowingPoint point(visible_[i].u, unused);
      visible_[i].c = evaluate(static_cast<SampleSource&>(point));
    }
  }
  // The sums from the rescored samples, in their order (a sample whose value is no longer finite
  // drops out).
  void rescored() {
    NormaliserSums sums;
    std::vector<State> kept;
    for (State& s : visible_) {
      const double lum = s.c.luminance();
      sums.add(lum);
      if (lum > 0.0) kept.push_back(std::move(s));
    }
    sums_.visibility = sums.visibility;
    sums_.contribution = sums.contribution;
    visible_ = std::move(kept);
  }
  size_t visibleCount() const { return visible_.size(); }
  // Ready to pick from: false if no sample saw any light (the chains then have nothing to do).
  bool prepare() {
    std::vector<double> lum;
    for (const State& s : visible_) lum.push_back(s.c.luminance());
    if (lum.empty()) return false;
    byContribution_ = Distribution1D(lum);
    return true;
  }
  // A start state for the visibility chain (uniform over the visible samples) and for the
  // contribution chain (in proportion to lum(C)).
  const State& visibilityStart(Rng& rng) const { return visible_[rng.below(uint32_t(visible_.size()))]; }
  const State& contributionStart(Rng& rng) const { return visible_[byContribution_.sample(rng.uniform())]; }

  const NormaliserSums& sums() const { return sums_; }

 private:
  std::vector<State> visible_;
  NormaliserSums sums_;
  Distribution1D byContribution_;
};

}  // namespace relt
