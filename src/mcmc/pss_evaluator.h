#pragma once
// The path builder as a function of a point u of primary sample space: S(u) -> splats, and the
// scalar target I(u) = luminance of their sum (DESIGN §3). The film position comes from the first
// two numbers of the camera stream, uniform over the whole film.
#include <vector>

#include "core/sample_source.h"
#include "path/bdpt.h"

namespace relt {

class PssEvaluator {
 public:
  PssEvaluator(const PathContext& ctx, int width, int height) : bdpt_(ctx), width_(width), height_(height) {}

  // Fills `out` and returns I(u); 0 when the sample is not finite (it is then never splatted).
  float operator()(SampleSource& u, PathSample& out);

  // Splats carry this factor so that a uniform sample estimates every pixel (film area / pixel).
  double filmArea() const { return double(width_) * height_; }

 private:
  Bdpt bdpt_;
  int width_, height_;
};

// Independent numbers that also keeps what each stream handed out, so that a point of primary
// sample space found by independent sampling can become a chain's state. With `film`, the first
// two camera numbers are that film position instead (erpt's per-pixel seeds).
class RecordingSource final : public SampleSource {
 public:
  explicit RecordingSource(uint64_t key) : source_(key) {}
  RecordingSource(uint64_t key, const Vec2& film) : source_(key), film_(film), fixedFilm_(true) {}
  float next(SampleStream stream) override {
    std::vector<float>& values = values_[static_cast<int>(stream)];
    const bool film = fixedFilm_ && stream == SampleStream::Camera && values.size() < 2;
    const float v = film ? film_[static_cast<int>(values.size())] : source_.next(stream);
    values.push_back(v);
    return v;
  }
  const std::vector<float>& values(SampleStream stream) const { return values_[static_cast<int>(stream)]; }

 private:
  IndependentSource source_;
  Vec2 film_{0.0f};
  bool fixedFilm_ = false;
  std::vector<float> values_[kSampleStreamCount];
};

}  // namespace relt
