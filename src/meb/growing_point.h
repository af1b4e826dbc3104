#pragma once
// A point of primary sample space for meb's light subpaths: the coordinates read so far, in the
// order they are read; reading past the end draws fresh uniform ones. A coordinate never read is
// uniform whatever the chain did, so drawing it on first use is exact for every proposal.
#include <vector>

#include "core/rng.h"
#include "core/sample_source.h"

namespace relt {

class GrowingPoint final : public SampleSource {
 public:
  GrowingPoint(std::vector<float>& coordinates, Rng& fresh) : coordinates_(coordinates), fresh_(fresh) {}
  // Every stream reads the one sequence: one evaluator reads them, always in the same order.
  float next(SampleStream) override {
    if (cursor_ == coordinates_.size()) coordinates_.push_back(fresh_.uniform());
    return coordinates_[cursor_++];
  }

 private:
  std::vector<float>& coordinates_;
  Rng& fresh_;
  size_t cursor_ = 0;
};

}  // namespace relt
