#include "integrators/direct/direct_driver.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "render/direct_pass.h"
#include "schedule/schedule.h"

namespace relt {
namespace {

// The rows of a film (every rank's, from a checkpoint) this rank renders; the others 0, so that
// the ranks' films still sum to it and each goes on adding its rays in the order of a render that
// never stopped.
void keepOwnRows(const std::vector<double>& all, Film& film, int firstRow, int rowStride, const std::string& file) {
  if (all.size() != film.data().size()) throw InputError(file, "", "the checkpoint's films do not match this render's");
  const size_t row = size_t(3) * film.width();
  for (int y = firstRow; y < film.height(); y += rowStride)
    std::copy_n(all.begin() + ptrdiff_t(row * y), row, film.data().begin() + ptrdiff_t(row * y));
}

// The pass a checkpoint holds: its film rows (none kept for no pass) into `out`, where it got to
// (spp, seconds, dropped).
DirectPassStart restorePass(Resumed& resumed, Job& job, DirectEstimate& out) {
  const nlohmann::json& d = resumed.progress.at("direct");
  if (d.at("spp").get<int>() > 0)
    keepOwnRows(resumed.takeLastFilm(job), out.film, job.rank(), job.size(), resumed.file);
  out.inChains = d.at("in_chains").get<bool>();
  out.dropped = d.at("dropped").get<uint64_t>();
  return {d.at("spp").get<int>(), d.at("seconds").get<double>()};
}

// The pass's image of `spp` rays per pixel on the root (empty elsewhere and for none; collective).
Image reducedImage(Job& job, const Film& film, int spp) {
  std::vector<double> sums = film.data();
  job.reduceSumToRoot(sums);
  return job.isRoot() && spp > 0 ? Renderer::resolve(film, sums, spp) : Image();
}

nlohmann::json directProgress(int spp, double seconds, bool inChains, uint64_t dropped) {
  return {{"spp", spp}, {"seconds", seconds}, {"in_chains", inChains}, {"dropped", dropped}};
}

// A checkpoint of the pass so far (no chain yet) and, on a save request, the image of it.
struct PassSaver {
  Job& job;
  const RenderSettings& settings;
  const CheckpointPlan& plan;
  const std::function<void(const Image&)>& snapshot;
  DirectEstimate& out;
  double lastCheckpoint;
  double lastPrint = 0.0;
  bool tty = ::isatty(STDERR_FILENO);

  // The root's progress line, once a second: the share of the rays per pixel it will take (of a
  // timed pass's share of the budget) done.
  void print(const DirectPass& sofar) {
    if (!job.isRoot() || sofar.seconds - lastPrint < 1.0) return;
    lastPrint = sofar.seconds;
    const int target = fixedDirectSpp(settings);
    const double fraction = target > 0 ? double(sofar.spp) / target
                                       : std::min(1.0, sofar.seconds / (kDirectBudgetShare * settings.seconds.value_or(1.0)));
    const double rays = double(sofar.spp) * settings.width * settings.height;
    std::fprintf(stderr, tty ? "\rdirect emission  %s" : "direct emission  %s\n",
                 progressLine(fraction, sofar.seconds, rays / std::max(sofar.seconds, 1e-9), "rays").c_str());
  }

  void chunkDone(const DirectPass& sofar, bool save) {
    print(sofar);
    if (save && !sofar.stopped) {  // a stopped render writes its image at the end
      const Image image = reducedImage(job, out.film, sofar.spp);
      if (job.isRoot()) snapshot(image);
    }
    if (!checkpointNow(plan, sofar.seconds, lastCheckpoint, !sofar.stopped, save)) return;
    CheckpointPlan p = plan;
    p.directFilm = &out.film;
    p.direct = directProgress(sofar.spp, sofar.seconds, false, out.dropped + job.allreduceSum(out.film.droppedSamples()));
    saveCheckpoint(job, p, settings.integrator.name.c_str(), {{"phase", "direct"}}, {}, {});
  }
};

}  // namespace

nlohmann::json DirectEstimate::progress() const { return directProgress(spp, seconds, inChains, dropped); }

DirectEstimate directEmission(Job& job, Renderer& renderer, const RenderSettings& settings,
                              const CheckpointPlan& plan, std::optional<Resumed>& resumed,
                              const std::function<void(const Image&)>& snapshot) {
  DirectEstimate out;
  out.film = Film(settings.width, settings.height);
  if (!directEmissionApart(settings)) return out;
  DirectPassStart start;
  // A checkpoint of an earlier release has no "direct": its pass is rendered again.
  if (resumed && resumed->progress.contains("direct")) {
    start = restorePass(*resumed, job, out);
    if (resumed->progress.value("phase", "") == "direct") {
      resumed.reset();  // the pass alone: it goes on, then the chains start afresh
    } else {           // the chains': the pass is done
      out.spp = start.spp;
      out.seconds = start.seconds;
      if (out.inChains) renderer.keepDirectEmissionInChains();
      out.image = reducedImage(job, out.film, out.spp);
      return out;
    }
  }
  PassSaver saver{job, settings, plan, snapshot, out, start.seconds};
  const DirectPass pass = renderDirectPass(renderer, job, out.film, start,
                                           [&](const DirectPass& sofar, bool save) { saver.chunkDone(sofar, save); });
  if (saver.lastPrint > 0.0 && saver.tty) std::fprintf(stderr, "\n");
  out.image = reducedImage(job, out.film, pass.spp);
  out.spp = pass.spp;
  out.inChains = pass.spp == 0;
  out.stopped = pass.stopped;
  out.dropped += job.allreduceSum(out.film.droppedSamples());
  out.seconds = pass.seconds;
  // It is not cut short (a part of the image would lack it), so a large N can eat a short budget.
  if (job.isRoot() && settings.seconds && out.seconds > 0.5 * *settings.seconds)
    std::fprintf(stderr,
                 "relt: warning: --direct-emission-spp %d took %.1f s of the %.1f s budget, leaving the chains %.1f s\n",
                 pass.spp, out.seconds, *settings.seconds, std::max(0.0, *settings.seconds - out.seconds));
  return out;
}

}  // namespace relt
