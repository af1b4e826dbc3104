#include "mcmc/pss_evaluator.h"

namespace relt {

float PssEvaluator::operator()(SampleSource& u, PathSample& out) {
  out.clear();
  const float x = u.next(SampleStream::Camera), y = u.next(SampleStream::Camera);
  bdpt_.trace(Vec2(x * width_, y * height_), u, out);
  const float target = out.luminanceSum();
  return std::isfinite(target) && out.finite() ? target : 0.0f;
}

}  // namespace relt
