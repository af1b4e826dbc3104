#include "pass_loop.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "render/schedule.h"

namespace relt::mpi {

int runPasses(const Session& session, const RenderSettings& settings,
              const std::function<void(uint64_t pass, int row)>& renderUnit,
              const std::function<double(double elapsed)>& rate) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto since = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const int height = settings.height;
  const bool timed = settings.seconds.has_value();
  const int spp = settings.spp.value_or(timed ? 0 : 16);
  const bool tty = ::isatty(STDERR_FILENO);
  double lastElapsed = 0.0, lastPass = 0.0, lastPrint = 0.0;
  int passes = 0;
  for (;;) {
    if (timed ? !startAnotherPass(passes, lastElapsed, lastPass, *settings.seconds) : passes >= spp) break;
    for (int row = 0; row < height; ++row)
      if (ownsUnit(static_cast<uint64_t>(passes), row, height, session.rank(), session.size()))
        renderUnit(static_cast<uint64_t>(passes), row);
    ++passes;
    // A timed render agrees on the elapsed time every pass so all ranks stop after the same pass.
    const double elapsed = timed ? allreduceMax(since()) : since();
    lastPass = elapsed - lastElapsed;
    lastElapsed = elapsed;
    if (rate && session.isRoot() && (elapsed - lastPrint >= 1.0)) {
      lastPrint = elapsed;
      const double fraction = timed ? std::min(1.0, elapsed / *settings.seconds) : double(passes) / spp;
      std::fprintf(stderr, tty ? "\r%s" : "%s\n", progressLine(fraction, elapsed, rate(elapsed)).c_str());
    }
  }
  if (rate && session.isRoot() && tty) std::fprintf(stderr, "\n");
  return passes;
}

}  // namespace relt::mpi
