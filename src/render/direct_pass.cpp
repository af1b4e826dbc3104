#include "render/direct_pass.h"

#include <algorithm>
#include <chrono>

#include "render/schedule.h"

namespace relt {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DirectPass renderDirectPass(Renderer& renderer, int firstRow, int rowStride, Film& film, const RankReduce& reduce) {
  const RenderSettings& s = renderer.settings();
  DirectPass out;
  if (!directEmissionApart(s)) return out;
  const auto start = std::chrono::steady_clock::now();
  const bool automatic = s.directSpp == kDirectSppAuto;
  const int fixed = !automatic ? s.directSpp : s.seconds ? 0 : autoDirectSpp(s.mutationsPerPixel.value_or(16.0));
  uint32_t done = 0;
  auto extendTo = [&](uint32_t end) {
    renderer.renderDirect(firstRow, rowStride, film, done, end);
    done = end;
  };
  if (automatic) {
    extendTo(uint32_t(kDirectProbeSpp));
    double seen = 0.0;
    for (double v : film.data()) seen += v;
    if (!(reduce.sum(seen) > 0.0)) {  // no emitter in view (a NaN sum was dropped by the film)
      renderer.keepDirectEmissionInChains();
      film = Film(s.width, s.height);
      out.seconds = reduce.max(secondsSince(start));
      return out;
    }
  }
  if (fixed > 0) {
    extendTo(uint32_t(std::max(fixed, int(done))));
  } else {  // a timed auto pass: at least kDirectMinSpp, then doublings decided on the slowest rank's time
    extendTo(uint32_t(kDirectMinSpp));
    while (done < uint32_t(kDirectMaxSpp) && doubleDirectPass(reduce.max(secondsSince(start)), *s.seconds)) extendTo(2 * done);
  }
  out.spp = int(done);
  out.seconds = reduce.max(secondsSince(start));
  return out;
}

}  // namespace relt
