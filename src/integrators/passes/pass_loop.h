#pragma once
// The pass loop of the per-pixel integrators (pt, bdpt, erpt): pass k renders the work units
// (k, row) this rank owns; --spp N runs N passes, --time decides collectively after each pass.
// A pass is taken in chunks of rows (schedule/schedule.h, nextPassChunk), the ranks agreeing on the
// elapsed time and on stop and save requests after each, so a request waits about 0.1 s however
// long a pass takes; a render stopped inside a pass keeps the rows it did (its image shows what
// render/pass_film.h says).
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "parallel/job.h"
#include "film/film.h"
#include "image/image.h"
#include "render/pass_film.h"
#include "schedule/schedule.h"
#include "render/settings.h"

namespace relt {

// A render resumed from a checkpoint starts at `at` (a pass, possibly inside it) after `elapsed`.
struct PassStart {
  PassPoint at;
  double elapsed = 0.0;
};

// A checkpoint's progress of passes, and where a render resumed from it starts (a checkpoint of
// an earlier release, taken between passes only, has no "rows").
nlohmann::json passProgress(PassPoint at, double elapsed);
PassStart passStartOf(const nlohmann::json& progress);

// The image at `at` on the root (empty elsewhere; collective): the ranks' sums of what `film`
// shows there, summed, each row divided by its own samples.
Image reducedPassImage(Job& job, const PassFilm& film, PassPoint at);

struct PassHooks {
  // Every owned unit of every pass, on the rank's worker threads at once (settings.threads): worker
  // currentWorker() renders into film.workerFilm(currentWorker()).
  std::function<void(uint64_t pass, int row)> renderUnit;
  // Optional: the root prints a progress line at most once a second with rate(elapsed) samples/s.
  std::function<double(double elapsed)> rate = {};
  const char* rateUnit = "samples";
  // Optional: on every rank after the same chunks, the image so far (on a save request, and every
  // --snapshot-every seconds).
  std::function<void(PassPoint)> snapshot = {};
  // Optional: on every rank after every chunk (the last one with more = false: the budget is spent
  // or a rank was signalled to stop; save: a rank was asked to save and the snapshot was written:
  // checkpoint now). A checkpoint gathers the workers' sums first (PassFilm::gatherWorkers).
  std::function<void(PassPoint, double elapsed, bool more, bool save)> chunkDone = {};
};

// Runs the passes and returns where they ended: whole passes, or inside one if a rank was stopped.
// `film` (which renderUnit fills) is told of every pass end before the hooks see it, and has the
// workers' sums gathered before a snapshot and at the end.
PassPoint runPasses(Job& job, const RenderSettings& settings, PassFilm& film, const PassHooks& hooks,
                    const PassStart& start = {});

}  // namespace relt
