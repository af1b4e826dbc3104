#include "pass_loop.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "mcmc/round_schedule.h"
#include "render/pace.h"
#include "render/schedule.h"

namespace relt::mpi {

int runPasses(const Session& session, const RenderSettings& settings,
              const std::function<void(uint64_t pass, int row)>& renderUnit,
              const std::function<double(double elapsed)>& rate,
              const std::function<void(int passes)>& snapshot, const PassStart& start,
              const std::function<void(int passes, double elapsed, bool more, bool save)>& passDone) {
  using Clock = std::chrono::steady_clock;
  const auto clockStart = Clock::now();
  auto since = [&] { return start.elapsed + std::chrono::duration<double>(Clock::now() - clockStart).count(); };
  const int height = settings.height;
  const bool timed = settings.seconds.has_value();
  const int spp = settings.spp.value_or(timed ? 0 : 16);
  const bool tty = ::isatty(STDERR_FILENO);
  const bool snapshots = snapshot && settings.snapshotEvery > 0.0;
  Pace pace;  // the passes' agreed durations: one that spanned a stall does not end the render early
  double lastElapsed = start.elapsed, lastPrint = start.elapsed, lastSnapshot = start.elapsed;
  int passes = start.passes;
  auto another = [&] { return timed ? startAnotherPass(passes, lastElapsed, pace.typical(), *settings.seconds) : passes < spp; };
  if (!another()) return passes;
  for (;;) {
    for (int row = 0; row < height; ++row)
      if (ownsUnit(static_cast<uint64_t>(passes), row, height, session.rank(), session.size()))
        renderUnit(static_cast<uint64_t>(passes), row);
    ++passes;
    // The ranks agree on the elapsed time and on a stop signal every pass, so all stop and write
    // snapshots and checkpoints after the same passes.
    const Agreement agreed = agree(since());
    const double elapsed = agreed.elapsed;
    pace.add(elapsed - lastElapsed);
    lastElapsed = elapsed;
    const bool more = !agreed.stop && another();
    const bool save = agreed.save && more;  // the last pass is written anyway
    if (snapshot && (save || (snapshots && snapshotDue(settings.snapshotEvery, elapsed, lastSnapshot, more)))) {
      lastSnapshot = elapsed;
      snapshot(passes);
    }
    if (rate && session.isRoot() && (elapsed - lastPrint >= 1.0)) {
      lastPrint = elapsed;
      const double fraction = timed ? std::min(1.0, elapsed / *settings.seconds) : double(passes) / spp;
      std::fprintf(stderr, tty ? "\r%s" : "%s\n", progressLine(fraction, elapsed, rate(elapsed)).c_str());
    }
    if (passDone) passDone(passes, elapsed, more, save);
    if (!more) break;
  }
  if (rate && session.isRoot() && tty) std::fprintf(stderr, "\n");
  return passes;
}

}  // namespace relt::mpi
