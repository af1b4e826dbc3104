#pragma once
// C(x^L), the contribution of one light subpath (thesis digest §5.2, Eq. 6.1): light tracing, the
// connections of its vertices to one camera subpath (the first coordinate picks it, uniformly, so
// a small step keeps it), and merging with every stored camera vertex within the radius. A list of
// splats; PT and next-event estimation are not in it (they do not depend on the light subpath).
#include <vector>

#include "meb/meb_cameras.h"
#include "path/splat.h"

namespace relt {

struct MebContribution {
  PathSample sample;
  // lum(C): the contribution chain's target; 0 for a list with a number that is not finite.
  double luminance() const { return sample.target(); }
};

class MebLightPath {
 public:
  MebLightPath(const PathContext& ctx, const VcmTracer& tracer, const MebCameras& cameras)
      : ctx_(ctx), tracer_(tracer), cameras_(cameras) {}

  MebContribution operator()(SampleSource& u);
  // Contributions with a value that is not finite (dropped: their target is 0).
  uint64_t nonFinite() const { return nonFinite_; }
  uint64_t merges() const { return merges_; }

 private:
  void connect(const LightVertex& y, uint32_t pixel, PathSample& out) const;
  void merge(const LightVertex& y, PathSample& out);

  const PathContext& ctx_;
  const VcmTracer& tracer_;
  const MebCameras& cameras_;
  std::vector<LightVertex> vertices_;  // scratch: the subpath's stored vertices
  uint64_t nonFinite_ = 0, merges_ = 0;
};

}  // namespace relt
