#include "integrators/passes/pass_render.h"

#include <cstdio>

#include "integrators/output/render_outputs.h"
#include "integrators/passes/pass_loop.h"
#include "parallel/workers.h"

namespace relt {

// pass k's samples depend on k only, and inside a pass for bdpt the checkpoint also keeps the film
// of the whole passes (render/pass_film.h).
void renderPasses(RenderContext& c, RowEstimator estimator, bool rowsStandAlone) {
  Job& job = c.job;
  Renderer& renderer = c.renderer;
  const RenderSettings& settings = c.settings;
  PassFilm film(settings.width, settings.height, rowsStandAlone, 0, settings.threads);
  PassStart start;
  uint64_t earlierSamples = 0;
  if (c.resumed) {
    start = passStartOf(c.resumed->progress);
    c.resumed->restoreFilms(film.checkpointFilms(start.at));
    film.restored(start.at);
    earlierSamples = c.resumed->progress.at("samples").get<uint64_t>();
  }
  const auto renderStart = Clock::now();
  int snapshots = 0;
  PassHooks hooks;
  hooks.renderUnit = [&](uint64_t pass, int row) {
    renderer.renderRow(estimator, pass, row, film.workerFilm(currentWorker()));
  };
  hooks.rate = [&](double elapsed) { return double(renderer.samples()) * job.size() / std::max(elapsed, 1e-9); };
  hooks.snapshot = [&](PassPoint at) {
    const Image image = reducedPassImage(job, film, at);
    if (job.isRoot()) writeImages(settings, image);
    ++snapshots;
  };
  hooks.chunkDone = [&, lastCheckpoint = start.elapsed](PassPoint at, double elapsed, bool more, bool save) mutable {
    if (!checkpointNow(c.plan, elapsed, lastCheckpoint, more, save)) return;
    film.gatherWorkers();
    nlohmann::json progress = passProgress(at, elapsed);
    progress["samples"] = earlierSamples + job.allreduceSum(renderer.samples());
    saveCheckpoint(job, c.plan, settings.integrator.name.c_str(), progress, film.checkpointFilms(at), {});
  };
  const PassPoint end = runPasses(job, settings, film, hooks, start);
  const uint64_t samplesNow = job.allreduceSum(renderer.samples()), samples = earlierSamples + samplesNow;
  const Image image = reducedPassImage(job, film, end);
  const Gathered g = gatherAfterRender(job, renderStart, renderer, film.live(), false);
  if (!job.isRoot()) return;

  nlohmann::json j = commonStats(settings, job, g, image);
  addPassStats(j, end, film.shown(end));
  j["snapshots"] = snapshots;
  j["samples"] = samples;
  j["samples_per_second"] = samplesNow / std::max(g.renderSeconds, 1e-9);
  j["samples_per_second_per_rank"] = samplesNow / std::max(g.renderSeconds, 1e-9) / job.size();
  addResumedFrom(j, c.resumed);
  writeOutputs(settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: %d spp%s, %.2f s, %.3f M samples/s, %.2f M rays/s; wrote %s\n", end.passes,
               inPassNote(end, film.shown(end)).c_str(), g.renderSeconds,
               samplesNow / std::max(g.renderSeconds, 1e-9) * 1e-6, g.rays / std::max(g.renderSeconds, 1e-9) * 1e-6,
               filesWritten(settings).c_str());
}

}  // namespace relt
