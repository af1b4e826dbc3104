#include "integrators/vcm/vcm_render.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "integrators/output/render_outputs.h"
#include "integrators/vcm/vcm_settings.h"
#include "schedule/schedule.h"

namespace relt {
namespace {

// The iterations every rank renders: rounds of one per rank until the budget (a count, or time
// decided on the slowest rank's clock) is spent or a rank is asked to stop.
struct VcmLoop {
  Job& job;
  const RenderSettings& settings;
  VcmRenderer& vcm;
  Film& film;
  Clock::time_point start = Clock::now();
  uint64_t done = 0;  // iterations finished on every rank

  void run() {
    const uint64_t ranks = uint64_t(job.size());
    const uint64_t budget = settings.seconds ? UINT64_MAX : uint64_t(settings.spp.value_or(kDefaultSpp));
    double agreed = 0.0, lastRound = 0.0, lastPrint = 0.0;
    for (uint64_t round = 0; round * ranks < budget; ++round) {
      if (settings.seconds && !startAnotherPass(int(std::min<uint64_t>(round, 1)), agreed, lastRound, *settings.seconds))
        break;
      const uint64_t i = round * ranks + uint64_t(job.rank());
      if (i < budget) vcm.render(i, film);
      done = std::min(budget, (round + 1) * ranks);
      const JobAgreement a = job.agree(secondsSince(start));
      lastRound = a.elapsed - agreed;
      agreed = a.elapsed;
      if (a.stop) break;
      if (job.isRoot() && agreed - lastPrint >= 1.0) {
        lastPrint = agreed;
        const double fraction = settings.seconds ? agreed / *settings.seconds : double(done) / double(budget);
        std::fprintf(stderr, ::isatty(STDERR_FILENO) ? "\r%s" : "%s\n",
                     progressLine(std::min(fraction, 1.0), agreed, double(done) / agreed, "iterations").c_str());
      }
    }
    if (job.isRoot() && lastPrint > 0.0 && ::isatty(STDERR_FILENO)) std::fprintf(stderr, "\n");
  }
};

}  // namespace

void renderVcm(RenderContext& c) {
  Job& job = c.job;
  const RenderSettings& settings = c.settings;
  const VcmSettings& own = settings.own.get<VcmIntegratorSettings>().vcm;
  VcmRenderer vcm(c.renderer.context(), own, settings.seed, settings.width, settings.height, settings.threads);
  Film film(settings.width, settings.height);
  VcmLoop loop{job, settings, vcm, film};
  loop.run();
  std::vector<double> sums = film.data();
  job.reduceSumToRoot(sums);
  const double iterations = double(std::max<uint64_t>(loop.done, 1));
  const Image image = job.isRoot() ? Renderer::resolve(film, sums, iterations) : Image();
  const uint64_t lightVertices = job.allreduceSum(vcm.counters().lightVertices);
  const Gathered g = gatherAfterRender(job, loop.start, c.renderer, film, false);
  if (!job.isRoot()) return;
  nlohmann::json j = commonStats(settings, job, g, image);
  j["iterations"] = loop.done;
  j["light_vertices"] = lightVertices;
  j["radius_first"] = vcm.firstRadius();
  j["radius_last"] = vcmRadius(vcm.firstRadius(), own.alpha, loop.done > 0 ? loop.done - 1 : 0);
  j["iterations_per_second"] = double(loop.done) / std::max(g.renderSeconds, 1e-9);
  writeOutputs(settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: %llu iterations, %.2f s, %.3f M light vertices/s, %.2f M rays/s; wrote %s\n",
               static_cast<unsigned long long>(loop.done), g.renderSeconds,
               double(lightVertices) / std::max(g.renderSeconds, 1e-9) * 1e-6,
               double(g.rays) / std::max(g.renderSeconds, 1e-9) * 1e-6, filesWritten(settings).c_str());
}

}  // namespace relt
