#include "pass_loop.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "mcmc/round_schedule.h"
#include "render/schedule.h"

namespace relt::mpi {

int runPasses(const Session& session, const RenderSettings& settings,
              const std::function<void(uint64_t pass, int row)>& renderUnit,
              const std::function<double(double elapsed)>& rate,
              const std::function<void(int passes)>& snapshot) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto since = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const int height = settings.height;
  const bool timed = settings.seconds.has_value();
  const int spp = settings.spp.value_or(timed ? 0 : 16);
  const bool tty = ::isatty(STDERR_FILENO);
  const bool snapshots = snapshot && settings.snapshotEvery > 0.0;
  double lastElapsed = 0.0, lastPass = 0.0, lastPrint = 0.0, lastSnapshot = 0.0;
  int passes = 0;
  auto another = [&] { return timed ? startAnotherPass(passes, lastElapsed, lastPass, *settings.seconds) : passes < spp; };
  for (;;) {
    if (!another()) break;
    for (int row = 0; row < height; ++row)
      if (ownsUnit(static_cast<uint64_t>(passes), row, height, session.rank(), session.size()))
        renderUnit(static_cast<uint64_t>(passes), row);
    ++passes;
    // A timed render (or one with snapshots) agrees on the elapsed time every pass so all ranks stop
    // and write snapshots after the same passes.
    const double elapsed = timed || snapshots ? allreduceMax(since()) : since();
    lastPass = elapsed - lastElapsed;
    lastElapsed = elapsed;
    if (snapshots && snapshotDue(settings.snapshotEvery, elapsed, lastSnapshot, another())) {
      lastSnapshot = elapsed;
      snapshot(passes);
    }
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
