#include "mcmc/pss_evaluator.h"

namespace relt {

float PssEvaluator::operator()(SampleSource& u, PathSample& out) {
  out.clear();
  const float x = u.next(SampleStream::Camera), y = u.next(SampleStream::Camera);
  bdpt_.trace(Vec2(x * width_, y * height_), u, out);
  return out.target();
}

float PssEvaluator::operator()(SampleSource& u, PathSample& out, ConnectionHook* hook) {
  bdpt_.setConnectionHook(hook);
  const float target = (*this)(u, out);
  bdpt_.setConnectionHook(nullptr);
  return target;
}

}  // namespace relt
