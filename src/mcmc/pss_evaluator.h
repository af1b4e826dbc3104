#pragma once
// The path builder as a function of a point u of primary sample space: S(u) -> splats, and the
// scalar target I(u) = luminance of their sum (DESIGN §3). The film position comes from the first
// two numbers of the camera stream, uniform over the whole film.
#include <array>
#include <vector>

#include "core/sample_source.h"
#include "path/bdpt.h"

namespace relt {

class PssEvaluator {
 public:
  PssEvaluator(const PathContext& ctx, int width, int height) : bdpt_(ctx), width_(width), height_(height) {}

  // Fills `out` and returns I(u); 0 when the sample is not finite (it is then never splatted).
  float operator()(SampleSource& u, PathSample& out);

  // The same with a hook shown every connection (Bdpt::setConnectionHook; null: none).
  float operator()(SampleSource& u, PathSample& out, ConnectionHook* hook);

  // Splats carry this factor so that a uniform sample estimates every pixel (film area / pixel).
  double filmArea() const { return double(width_) * height_; }

 private:
  Bdpt bdpt_;
  int width_, height_;
};

// The coordinates of a point of primary sample space, one list per stream.
using StreamValues = std::array<std::vector<float>, kSampleStreamCount>;

// Independent numbers that also keeps what each stream handed out, so that a point of primary
// sample space found by independent sampling can become a chain's state. With a prefix, each
// stream first hands out the prefix's values (erpt: the film position of a per-pixel seed; a
// population-annealing particle: its whole state), then independent numbers.
class RecordingSource final : public SampleSource {
 public:
  explicit RecordingSource(uint64_t key) : source_(key) {}
  RecordingSource(uint64_t key, StreamValues prefix) : source_(key), prefix_(std::move(prefix)) {}
  float next(SampleStream stream) override {
    const int s = static_cast<int>(stream);
    std::vector<float>& values = values_[size_t(s)];
    const std::vector<float>& prefix = prefix_[size_t(s)];
    const float v = values.size() < prefix.size() ? prefix[values.size()] : source_.next(stream);
    values.push_back(v);
    return v;
  }
  const std::vector<float>& values(SampleStream stream) const { return values_[static_cast<size_t>(stream)]; }

 private:
  IndependentSource source_;
  StreamValues prefix_;
  StreamValues values_;
};

}  // namespace relt
