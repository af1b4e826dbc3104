#include "integrators/vcm/vcm_render.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "integrators/output/render_outputs.h"
#include "integrators/vcm/vcm_settings.h"
#include "mcmc/round_schedule.h"
#include "schedule/schedule.h"

namespace relt {
namespace {

// The iterations every rank renders: rounds of one per rank (iteration done + k on rank k) until
// the budget (a count, or time decided on the slowest rank's clock) is spent or a rank is asked to
// stop. After every round the ranks agree; snapshots and checkpoints are taken there.
struct VcmLoop {
  RenderContext& c;
  VcmRenderer& vcm;
  Film& film;
  uint64_t done = 0;       // iterations finished on every rank (a resumed render's included)
  double earlier = 0.0;    // seconds of the render this one continues
  int snapshots = 0;
  Clock::time_point start = Clock::now();

  const RenderSettings& settings() const { return c.settings; }
  Image image() {
    std::vector<double> sums = film.data();
    c.job.reduceSumToRoot(sums);
    return c.job.isRoot() ? Renderer::resolve(film, sums, double(std::max<uint64_t>(done, 1))) : Image();
  }
  void save(double elapsed) {
    saveCheckpoint(c.job, c.plan, "vcm", {{"iterations", done}, {"elapsed", elapsed}}, std::span<const Film>(&film, 1),
                   {});
  }
  void run();
  void printProgress(double agreed, uint64_t budget, double& lastPrint) const;
};

void VcmLoop::run() {
  Job& job = c.job;
  const RenderSettings& s = settings();
  const uint64_t ranks = uint64_t(job.size());
  const uint64_t budget = s.seconds ? UINT64_MAX : uint64_t(s.spp.value_or(kDefaultSpp));
  double agreed = earlier, lastRound = 0.0, lastPrint = 0.0, lastSnapshot = earlier, lastCheckpoint = earlier;
  bool first = true;
  while (done < budget) {
    if (s.seconds && !startAnotherPass(first ? 0 : 1, agreed, lastRound, *s.seconds)) break;
    first = false;
    const uint64_t i = done + uint64_t(job.rank());
    if (i < budget) vcm.render(i, film);
    done = std::min(budget, done + ranks);
    const JobAgreement a = job.agree(earlier + secondsSince(start));
    lastRound = a.elapsed - agreed;
    agreed = a.elapsed;
    const bool more = !a.stop && done < budget && !(s.seconds && agreed + lastRound > *s.seconds);
    // A save request always writes (an image must exist before the kill); the final image is
    // written after the loop.
    if (a.save || snapshotDue(s.snapshotEvery, agreed, lastSnapshot, more)) {
      const Image snapshot = image();
      if (job.isRoot()) writeImages(s, snapshot);
      lastSnapshot = agreed;
      ++snapshots;
    }
    if (checkpointNow(c.plan, agreed, lastCheckpoint, more, a.save)) save(agreed);
    if (a.stop) break;
    printProgress(agreed, budget, lastPrint);
  }
  if (job.isRoot() && lastPrint > 0.0 && ::isatty(STDERR_FILENO)) std::fprintf(stderr, "\n");
}

void VcmLoop::printProgress(double agreed, uint64_t budget, double& lastPrint) const {
  if (!c.job.isRoot() || agreed - lastPrint < 1.0) return;
  lastPrint = agreed;
  const RenderSettings& s = settings();
  const double fraction = s.seconds ? agreed / *s.seconds : double(done) / double(budget);
  // An iteration is one camera sample (and one light subpath) per pixel.
  const double samples = double(done) * double(s.width) * double(s.height);
  std::fprintf(stderr, ::isatty(STDERR_FILENO) ? "\r%s" : "%s\n",
               progressLine(std::min(fraction, 1.0), agreed, samples / agreed, "samples").c_str());
}

}  // namespace

void renderVcm(RenderContext& c) {
  Job& job = c.job;
  const RenderSettings& settings = c.settings;
  const VcmSettings& own = settings.own.get<VcmIntegratorSettings>().vcm;
  VcmRenderer vcm(c.renderer.context(), own, settings.seed, settings.width, settings.height, settings.threads);
  Film film(settings.width, settings.height);
  VcmLoop loop{c, vcm, film};
  if (c.resumed) {
    c.resumed->restoreFilms(std::span<Film>(&film, 1));
    loop.done = c.resumed->progress.at("iterations").get<uint64_t>();
    loop.earlier = c.resumed->progress.at("elapsed").get<double>();
  }
  const uint64_t resumedAt = loop.done;
  loop.run();
  const Image image = loop.image();
  const uint64_t lightVertices = job.allreduceSum(vcm.lightVertices());
  const uint64_t merges = job.allreduceSum(vcm.merges());
  const Gathered g = gatherAfterRender(job, loop.start, c.renderer, film, false);
  if (!job.isRoot()) return;
  nlohmann::json j = commonStats(settings, job, g, image);
  const uint64_t now = loop.done - resumedAt;
  j["iterations"] = loop.done;
  j["light_vertices"] = lightVertices;
  j["merges"] = merges;
  j["radius_first"] = vcm.firstRadius();
  j["radius_last"] = vcmRadius(vcm.firstRadius(), own.alpha, loop.done > 0 ? loop.done - 1 : 0);
  j["iterations_per_second"] = double(now) / std::max(g.renderSeconds, 1e-9);
  j["snapshots"] = loop.snapshots;
  addResumedFrom(j, c.resumed);
  writeOutputs(settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: %llu iterations, %.2f s, %.3f M light vertices/s, %.2f M rays/s; wrote %s\n",
               static_cast<unsigned long long>(loop.done), g.renderSeconds,
               double(lightVertices) / std::max(g.renderSeconds, 1e-9) * 1e-6,
               double(g.rays) / std::max(g.renderSeconds, 1e-9) * 1e-6, filesWritten(settings).c_str());
}

}  // namespace relt
