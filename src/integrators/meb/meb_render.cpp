#include "integrators/meb/meb_render.h"

#include <algorithm>
#include <cstdio>

#include "integrators/direct/direct_then_chains.h"
#include "integrators/meb/meb_settings.h"
#include "integrators/passes/iteration_loop.h"

namespace relt {
namespace {

// The chains' statistics summed over the ranks, as rates.
nlohmann::json chainStats(Job& job, const MebStats& mine) {
  MebStats s;
  const auto sum = [&](uint64_t v) { return job.allreduceSum(v); };
  s.iterations = sum(mine.iterations);
  s.withoutChains = sum(mine.withoutChains);
  for (int k = 0; k < 2; ++k) {
    s.steps[k] = sum(mine.steps[k]);
    s.accepted[k] = sum(mine.accepted[k]);
  }
  s.largeSteps = sum(mine.largeSteps);
  s.exchanges = sum(mine.exchanges);
  s.exchangesTried = sum(mine.exchangesTried);
  s.cameraVertices = sum(mine.cameraVertices);
  s.merges = sum(mine.merges);
  s.nonFinite = sum(mine.nonFinite);
  std::vector<double> means = {mine.visibility, mine.contribution, mine.theta[0], mine.theta[1]};
  job.allreduceSum(means);
  const auto rate = [](uint64_t a, uint64_t b) { return b ? double(a) / double(b) : 0.0; };
  const double iterations = double(std::max<uint64_t>(s.iterations - s.withoutChains, 1));
  return {{"iterations_without_chains", s.withoutChains},
          {"steps", {{"visibility", s.steps[0]}, {"contribution", s.steps[1]}}},
          {"acceptance", {{"visibility", rate(s.accepted[0], s.steps[0])}, {"contribution", rate(s.accepted[1], s.steps[1])}}},
          {"large_steps", s.largeSteps},
          {"exchange_rate", rate(s.exchanges, s.exchangesTried)},
          {"normaliser_mean", {{"visibility", means[0] / iterations}, {"contribution", means[1] / iterations}}},
          {"theta_mean", {{"visibility", means[2] / iterations}, {"contribution", means[3] / iterations}}},
          {"camera_vertices", s.cameraVertices},
          {"merges", s.merges},
          {"non_finite_dropped", s.nonFinite}};
}

void renderMebIterations(RenderContext& c, const DirectEstimate& direct, Clock::time_point renderStart) {
  const RenderSettings& settings = c.settings;
  const MebSettings& own = settings.own.get<MebIntegratorSettings>().meb;
  MebRenderer meb(c.renderer.context(), own, settings.seed, settings.width, settings.height, settings.threads);
  Film film(settings.width, settings.height);
  IterationLoop loop(c, "meb", film, [&](uint64_t i) { meb.render(i, film); }, direct, renderStart);
  loop.run();
  const auto stats = [&] {
    const uint64_t last = loop.done() > 0 ? loop.done() - 1 : 0;
    return nlohmann::json{{"chains", chainStats(c.job, meb.stats())},
                          {"radius_first", meb.firstRadius()},
                          {"radius_last", vcmRadius(meb.firstRadius(), own.vcm.alpha, last)}};
  };
  const auto closing = [](const nlohmann::json& j, const Gathered& g) {
    char line[128];
    std::snprintf(line, sizeof line, "exchange rate %.3f, %.2f M rays/s", j["chains"]["exchange_rate"].get<double>(),
                  double(g.rays) / std::max(g.renderSeconds, 1e-9) * 1e-6);
    return std::string(line);
  };
  finishIterations(c, loop, film, stats, closing);
}

}  // namespace

void renderMeb(RenderContext& c) { renderDirectThenChains(c, renderMebIterations); }

}  // namespace relt
