#pragma once
// Where the path builder gets its random numbers. Independent samplers wrap an Rng; the Markov
// chains (later) feed primary-sample vectors with one stream per purpose.
#include "core/math.h"
#include "core/rng.h"

namespace relt {

enum class SampleStream : uint8_t { Camera = 0, Light = 1, Connection = 2 };
inline constexpr int kSampleStreamCount = 3;

class SampleSource {
 public:
  virtual ~SampleSource() = default;
  // Next number in [0, 1) from the given stream.
  virtual float next(SampleStream stream) = 0;
  Vec2 next2(SampleStream stream) {
    const float a = next(stream);
    return Vec2(a, next(stream));
  }
};

// Independent uniform numbers: one Rng per stream so that, e.g., the light subpath of a sample
// does not shift when the camera subpath consumes more numbers.
class IndependentSource final : public SampleSource {
 public:
  IndependentSource() : IndependentSource(0) {}
  explicit IndependentSource(uint64_t key) { reset(key); }
  void reset(uint64_t key) {
    for (int i = 0; i < kSampleStreamCount; ++i) rng_[i].seed(key, static_cast<uint64_t>(i));
  }
  float next(SampleStream stream) override { return rng_[static_cast<int>(stream)].uniform(); }

 private:
  Rng rng_[kSampleStreamCount];
};

}  // namespace relt
