#include "integrators/passes/pass_loop.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <vector>

#include "mcmc/round_schedule.h"
#include "parallel/workers.h"
#include "schedule/pace.h"
#include "render/renderer.h"

namespace relt {
namespace {

// The root's progress line: passes done (and the share of the current one) of the budget.
struct ProgressPrinter {
  Job& job;
  const RenderSettings& settings;
  const std::function<double(double)>& rate;
  const char* unit;
  double lastPrint;
  bool tty = ::isatty(STDERR_FILENO);
  bool printed = false;

  void print(PassPoint at, double elapsed) {
    if (!rate || !job.isRoot() || elapsed - lastPrint < 1.0) return;
    lastPrint = elapsed;
    printed = true;
    const double passes = at.passes + double(at.rows) / std::max(settings.height, 1);
    const double fraction = settings.seconds ? std::min(1.0, elapsed / *settings.seconds)
                                             : passes / settings.spp.value_or(kDefaultSpp);
    std::fprintf(stderr, tty ? "\r%s" : "%s\n", progressLine(fraction, elapsed, rate(elapsed), unit).c_str());
  }
  ~ProgressPrinter() {
    if (printed && tty) std::fprintf(stderr, "\n");
  }
};

// The units of rows first .. end - 1 of pass `pass` this rank owns, dealt in turn to its workers.
void renderChunk(Job& job, const RenderSettings& settings, const PassHooks& hooks, int pass, int first,
                 int end) {
  std::vector<int> rows;
  for (int row = first; row < end; ++row)
    if (ownsUnit(uint64_t(pass), row, settings.height, job.rank(), job.size())) rows.push_back(row);
  const int workers = std::clamp(settings.threads, 1, std::max(int(rows.size()), 1));
  runOnWorkers(workers, [&](int w) {
    for (size_t k = size_t(w); k < rows.size(); k += size_t(workers)) hooks.renderUnit(uint64_t(pass), rows[k]);
  });
}

}  // namespace

nlohmann::json passProgress(PassPoint at, double elapsed) {
  return {{"passes", at.passes}, {"rows", at.rows}, {"elapsed", elapsed}};
}

PassStart passStartOf(const nlohmann::json& progress) {
  return {{progress.at("passes").get<int>(), progress.value("rows", 0)}, progress.at("elapsed").get<double>()};
}

Image reducedPassImage(Job& job, const PassFilm& film, PassPoint at) {
  std::vector<double> sums = film.sumsShown(at);
  job.reduceSumToRoot(sums);
  const PassPoint shown = film.shown(at);
  return job.isRoot() ? Renderer::resolve(film.live(), sums, shown.passes, shown.rows) : Image();
}

PassPoint runPasses(Job& job, const RenderSettings& settings, PassFilm& film, const PassHooks& hooks,
                    const PassStart& start) {
  using Clock = std::chrono::steady_clock;
  const auto clockStart = Clock::now();
  auto since = [&] { return start.elapsed + std::chrono::duration<double>(Clock::now() - clockStart).count(); };
  const int height = settings.height;
  const bool timed = settings.seconds.has_value();
  const int spp = settings.spp.value_or(timed ? 0 : kDefaultSpp);
  const bool snapshots = hooks.snapshot && settings.snapshotEvery > 0.0;
  Pace pace;  // the passes' agreed durations: one that spanned a stall does not end the render early
  double passStart = start.elapsed, chunkStart = start.elapsed, lastSnapshot = start.elapsed;
  PassPoint at = start.at;
  std::optional<PassPoint> lastShown;  // where the last snapshot was taken
  auto another = [&] {
    return timed ? startAnotherPass(at.passes, passStart, pace.typical(), *settings.seconds) : at.passes < spp;
  };
  // A pass begun (and checkpointed inside) is finished whatever the budget: it was started within it.
  if (at.rows == 0 && !another()) return at;
  ProgressPrinter printer{job, settings, hooks.rate, hooks.rateUnit, start.elapsed};
  int chunk = kFirstPassChunkRows;
  for (;;) {
    const int first = at.rows, end = std::min(height, first + chunk);
    renderChunk(job, settings, hooks, at.passes, first, end);
    at.rows = end;
    const bool passEnd = end == height;
    if (passEnd) {
      at = {at.passes + 1, 0};
      film.passEnded();
    }
    // The ranks agree after every chunk, so all stop, snapshot and checkpoint at the same point.
    const JobAgreement agreed = job.agree(since());
    const double elapsed = agreed.elapsed;
    chunk = nextPassChunk(end - first, elapsed - chunkStart, height);
    chunkStart = elapsed;
    if (passEnd) {
      pace.add(elapsed - passStart);
      passStart = elapsed;
    }
    const bool more = !agreed.stop && (!passEnd || another());
    const bool save = agreed.save && more;  // the last chunk is written anyway
    // A save request always writes (an image must exist before the kill); a periodic snapshot only
    // when it would show something new.
    const bool due = snapshots && snapshotDue(settings.snapshotEvery, elapsed, lastSnapshot, more);
    if (hooks.snapshot && (save || (due && film.showsNew(at, lastShown)))) {
      lastSnapshot = elapsed;
      lastShown = at;
      film.gatherWorkers();
      hooks.snapshot(at);
    }
    printer.print(at, elapsed);
    if (!more) film.gatherWorkers();
    if (hooks.chunkDone) hooks.chunkDone(at, elapsed, more, save);
    if (!more) return at;
  }
}

}  // namespace relt
