#include "render/direct_pass.h"

#include <algorithm>
#include <chrono>

#include "render/schedule.h"

namespace relt {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Extends the pass over rays [done, end) of every pixel, when a rank may be asked to stop in
// chunks, agreeing on a stop request after each. A chunk's size follows the slowest rank's time for
// the last one; the film does not depend on it (rays in two ranges sum to the film of one).
struct ChunkedPass {
  Renderer& renderer;
  int firstRow, rowStride;
  Film& film;
  const RankReduce& reduce;
  uint32_t done = 0, chunk = uint32_t(kDirectProbeSpp);
  bool stopped = false;

  bool extendTo(uint32_t end) {
    while (done < end && !stopped) {
      const uint32_t next = reduce.stop ? std::min(end, done + chunk) : end;
      const auto t0 = std::chrono::steady_clock::now();
      renderer.renderDirect(firstRow, rowStride, film, done, next);
      const uint32_t taken = next - done;
      done = next;
      if (!reduce.stop) break;
      chunk = nextDirectChunk(taken, reduce.max(secondsSince(t0)));
      stopped = reduce.max(reduce.stop() ? 1.0 : 0.0) > 0.0;
    }
    return !stopped;
  }
};

// Whether any rank's probe rays saw emission (a NaN sum was dropped by the film).
bool probeSeesEmission(Renderer& renderer, int firstRow, int rowStride, const RankReduce& reduce) {
  const RenderSettings& s = renderer.settings();
  Film probe(s.width, s.height);
  renderer.renderDirect(firstRow, rowStride, probe, 0, uint32_t(kDirectProbeSpp), true);
  double seen = 0.0;
  for (double v : probe.data()) seen += v;
  return reduce.sum(seen) > 0.0;
}

}  // namespace

DirectPass renderDirectPass(Renderer& renderer, int firstRow, int rowStride, Film& film, const RankReduce& reduce) {
  const RenderSettings& s = renderer.settings();
  DirectPass out;
  if (!directEmissionApart(s)) return out;
  const auto start = std::chrono::steady_clock::now();
  const bool automatic = s.directSpp == kDirectSppAuto;
  const int fixed = !automatic ? s.directSpp : s.seconds ? 0 : autoDirectSpp(s.mutationsPerPixel.value_or(16.0));
  if (automatic && !probeSeesEmission(renderer, firstRow, rowStride, reduce)) {  // no emitter in view
    renderer.keepDirectEmissionInChains();
    out.seconds = reduce.max(secondsSince(start));
    return out;
  }
  ChunkedPass pass{renderer, firstRow, rowStride, film, reduce};
  if (fixed > 0) {
    pass.extendTo(uint32_t(fixed));
  } else if (pass.extendTo(uint32_t(kDirectMinSpp))) {
    // A timed auto pass: doublings decided on the slowest rank's time.
    while (pass.done < uint32_t(kDirectMaxSpp) && doubleDirectPass(reduce.max(secondsSince(start)), *s.seconds) &&
           pass.extendTo(2 * pass.done)) {
    }
  }
  out.spp = int(pass.done);
  out.stopped = pass.stopped;
  out.seconds = reduce.max(secondsSince(start));
  return out;
}

}  // namespace relt
