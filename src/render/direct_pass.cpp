#include "render/direct_pass.h"

#include <algorithm>
#include <bit>
#include <chrono>

#include "core/clock.h"
#include "schedule/schedule.h"

namespace relt {
namespace {

// Extends the pass over rays [done, end) of every pixel in chunks, the ranks agreeing on stop and
// save requests after each. A chunk's size follows the slowest rank's time for the last one; the
// film does not depend on it (rays in two ranges sum to the film of one).
struct ChunkedPass {
  Renderer& renderer;
  Job& job;
  Film& film;
  const DirectChunkDone& chunkDone;
  double earlier;  // seconds of the render this one continues
  Clock::time_point start;
  uint32_t done = 0, chunk = uint32_t(kDirectProbeSpp);
  double agreed = earlier;  // the slowest rank's elapsed seconds after the last chunk
  bool stopped = false;

  bool extendTo(uint32_t end) {
    while (done < end && !stopped) {
      const uint32_t next = std::min(end, done + chunk);
      renderer.renderDirect(job.rank(), job.size(), film, done, next);
      const uint32_t taken = next - done;
      done = next;
      const double before = agreed;
      const JobAgreement a = job.agree(earlier + secondsSince(start));
      agreed = a.elapsed;
      chunk = nextDirectChunk(taken, agreed - before);
      stopped = a.stop;
      if (chunkDone) chunkDone(DirectPass{int(done), agreed, stopped}, a.save || a.stop);
    }
    return !stopped;
  }
  double elapsed() const { return job.allreduceMax(earlier + secondsSince(start)); }
};

// Whether any rank's probe rays saw emission (a NaN sum was dropped by the film).
bool probeSeesEmission(Renderer& renderer, Job& job) {
  const RenderSettings& s = renderer.settings();
  Film probe(s.width, s.height);
  renderer.renderDirect(job.rank(), job.size(), probe, 0, uint32_t(kDirectProbeSpp), true);
  double seen = 0.0;
  for (double v : probe.data()) seen += v;
  return job.allreduceSum(seen) > 0.0;
}

}  // namespace

int fixedDirectSpp(const RenderSettings& s) {
  if (s.directSpp != kDirectSppAuto) return s.directSpp;
  if (s.seconds) return 0;
  // vcm and meb count iterations (--spp), the chains mutations per pixel; both default to 16.
  return autoDirectSpp(s.spp ? double(*s.spp) : s.mutationsPerPixel.value_or(kDefaultMutationsPerPixel));
}

DirectPass renderDirectPass(Renderer& renderer, Job& job, Film& film, const DirectPassStart& start,
                            const DirectChunkDone& chunkDone) {
  const RenderSettings& s = renderer.settings();
  DirectPass out;
  if (!directEmissionApart(s)) return out;
  ChunkedPass pass{renderer, job, film, chunkDone, start.seconds, Clock::now()};
  pass.done = uint32_t(start.spp);
  const bool automatic = s.directSpp == kDirectSppAuto;
  const int fixed = fixedDirectSpp(s);
  if (automatic && start.spp == 0 && !probeSeesEmission(renderer, job)) {  // none in view
    renderer.keepDirectEmissionInChains();
    out.seconds = pass.elapsed();
    return out;
  }
  if (fixed > 0) {
    pass.extendTo(uint32_t(fixed));
  } else if (pass.extendTo(std::max(uint32_t(kDirectMinSpp), std::bit_ceil(pass.done)))) {
    // A timed auto pass: doublings decided on the slowest rank's time (a resumed pass first ends
    // the doubling it was stopped in).
    while (pass.done < uint32_t(kDirectMaxSpp) && doubleDirectPass(pass.elapsed(), *s.seconds) &&
           pass.extendTo(2 * pass.done)) {
    }
  }
  out.spp = int(pass.done);
  out.stopped = pass.stopped;
  out.seconds = pass.elapsed();
  return out;
}

}  // namespace relt
