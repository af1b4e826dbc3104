#include "pss/primary_sample_vector.h"

#include <bit>
#include <cmath>
#include <stdexcept>

#include "core/math.h"

namespace relt {

PrimarySampleVector::PrimarySampleVector(uint64_t key, KelemenSizes sizes)
    : rng_(key, 0x9551u), sizes_(sizes), step_(sizes) {}

void PrimarySampleVector::startIteration(bool largeStep) {
  ++iteration_;
  largeStep_ = largeStep;
  if (largeStep) {
    previousLargeStep_ = lastLargeStep_;
    lastLargeStep_ = iteration_;
  }
  for (Stream& s : streams_) s.cursor = 0;
  backup_.clear();
}

void PrimarySampleVector::accept() { backup_.clear(); }

void PrimarySampleVector::reject() {
  for (auto it = backup_.rbegin(); it != backup_.rend(); ++it) {
    std::vector<Coordinate>& coords = streams_[it->stream].coords;
    if (it->old.modified == kNeverSet) {
      coords.resize(it->index);  // created by the rejected proposal
    } else {
      coords[it->index] = it->old;
    }
  }
  backup_.clear();
  if (largeStep_) lastLargeStep_ = previousLargeStep_;
  --iteration_;
}

void PrimarySampleVector::materialise(Coordinate& c) {
  // Untouched since before the last large step: that step would have drawn it afresh.
  if (c.modified < lastLargeStep_) {
    c.value = rng_.uniform();
    c.modified = lastLargeStep_;
  }
  // Catch up on the small steps it missed, then take this iteration's. Beyond kExactSteps the sum of
  // the steps is drawn at once from its normal limit (zero mean, n sigma^2): still symmetric, and a
  // coordinate skipped for hundreds of iterations no longer costs hundreds of steps.
  const uint64_t n = iteration_ - c.modified;
  if (n > kExactSteps) {
    const float u1 = 1.0f - rng_.uniform(), u2 = rng_.uniform();
    const float gauss = std::sqrt(-2.0f * std::log(u1)) * std::cos(2.0f * kPi * u2);
    c.value = wrapUnit(c.value, gauss * step_.sigma() * std::sqrt(static_cast<float>(n)));
    c.modified = iteration_;
    return;
  }
  for (; c.modified < iteration_; ++c.modified) c.value = step_(c.value, rng_.uniform());
}

float PrimarySampleVector::next(SampleStream stream) {
  const int si = static_cast<int>(stream);
  Stream& s = streams_[si];
  const size_t i = s.cursor++;
  if (i == s.coords.size()) {
    // A coordinate no earlier state used: uniform (small steps would leave it uniform anyway).
    backup_.push_back({static_cast<uint8_t>(si), static_cast<uint32_t>(i), Coordinate{0.0f, kNeverSet}});
    s.coords.push_back(Coordinate{rng_.uniform(), iteration_});
    return s.coords.back().value;
  }
  if (s.coords[i].modified == iteration_) {
    return s.coords[i].value;  // already materialised in this iteration
  }
  backup_.push_back({static_cast<uint8_t>(si), static_cast<uint32_t>(i), s.coords[i]});
  materialise(s.coords[i]);
  return s.coords[i].value;
}

void PrimarySampleVector::setState(SampleStream stream, const std::vector<float>& values) {
  std::vector<Coordinate>& coords = streams_[static_cast<int>(stream)].coords;
  coords.clear();
  for (float v : values) coords.push_back(Coordinate{v, iteration_});
  lastLargeStep_ = iteration_;
}

std::vector<uint64_t> PrimarySampleVector::serialize() const {
  std::vector<uint64_t> out = {rng_.state(), rng_.increment(), std::bit_cast<uint32_t>(sizes_.s1),
                               std::bit_cast<uint32_t>(sizes_.s2), iteration_, lastLargeStep_, previousLargeStep_,
                               largeStep_ ? 1u : 0u};
  for (const Stream& s : streams_) {
    out.push_back(s.coords.size());
    for (const Coordinate& c : s.coords) {
      out.push_back(std::bit_cast<uint32_t>(c.value));
      out.push_back(c.modified);
    }
  }
  return out;
}

PrimarySampleVector PrimarySampleVector::deserialize(const std::vector<uint64_t>& data) {
  size_t k = 0;
  auto take = [&] {
    if (k >= data.size()) throw std::runtime_error("truncated primary-sample state");
    return data[k++];
  };
  PrimarySampleVector v(0);
  const uint64_t state = take(), inc = take();
  v.rng_.restore(state, inc);
  v.sizes_.s1 = std::bit_cast<float>(static_cast<uint32_t>(take()));
  v.sizes_.s2 = std::bit_cast<float>(static_cast<uint32_t>(take()));
  v.step_ = KelemenStep(v.sizes_);
  v.iteration_ = take();
  v.lastLargeStep_ = take();
  v.previousLargeStep_ = take();
  v.largeStep_ = take() != 0;
  for (Stream& s : v.streams_) {
    const uint64_t n = take();
    for (uint64_t i = 0; i < n; ++i) {
      const float value = std::bit_cast<float>(static_cast<uint32_t>(take()));
      s.coords.push_back(Coordinate{value, take()});
    }
  }
  if (k != data.size()) throw std::runtime_error("trailing data after primary-sample state");
  return v;
}

}  // namespace relt
