#include "meb/meb_renderer.h"

#include <algorithm>

#include "core/rng.h"
#include "meb/initial_set.h"
#include "parallel/workers.h"

namespace relt {
namespace {

constexpr uint64_t kInitialPurpose = 0x3eb5, kStartPurpose = 0x3eb6, kPairPurpose = 0x3eb7;

std::vector<MebLightPath> evaluators(int workers, const PathContext& ctx, const VcmTracer& tracer,
                                     const MebCameras& cameras) {
  std::vector<MebLightPath> out;
  out.reserve(size_t(workers));
  for (int w = 0; w < workers; ++w) out.emplace_back(ctx, tracer, cameras);
  return out;
}

void addCounts(MebStats& s, const std::vector<MebLightPath>& done) {
  for (const MebLightPath& e : done) {
    s.merges += e.merges();
    s.nonFinite += e.nonFinite();
  }
}

}  // namespace

void MebStats::add(const MebStats& o) {
  iterations += o.iterations;
  withoutChains += o.withoutChains;
  for (int k = 0; k < 2; ++k) {
    steps[k] += o.steps[k];
    accepted[k] += o.accepted[k];
    theta[k] += o.theta[k];
  }
  largeSteps += o.largeSteps;
  exchanges += o.exchanges;
  exchangesTried += o.exchangesTried;
  cameraVertices += o.cameraVertices;
  merges += o.merges;
  nonFinite += o.nonFinite;
  visibility += o.visibility;
  contribution += o.contribution;
}

MebRenderer::MebRenderer(const PathContext& ctx, const MebSettings& settings, uint64_t seed, int width, int height,
                         int threads)
    : ctx_(ctx),
      settings_(settings),
      seed_(seed),
      width_(width),
      height_(height),
      workers_(std::max(threads, 1)),
      radius1_(settings.vcm.radius * pixelFootprint(ctx)),
      cameras_(width, height, workers_) {
  for (int w = 0; w < workers_; ++w) {
    workerFilms_.emplace_back(width, height);
    chainFilms_[0].emplace_back(width, height);
    chainFilms_[1].emplace_back(width, height);
  }
}

void MebRenderer::render(uint64_t iteration, Film& film) {
  VcmIteration it;
  it.radius = float(vcmRadius(radius1_, settings_.vcm.alpha, iteration));
  it.lightPaths = double(width_) * height_;
  const VcmTracer plain(ctx_, it);
  cameras_.trace(plain, seed_, iteration, it.radius);
  InitialSet set = initialSet(plain, iteration);
  MebStats s;
  s.iterations = 1;
  s.cameraVertices = cameras_.vertexCount();
  // kappa does not change which subpaths contribute, so b'_vis is known before they are weighted.
  const double visible = set.sums().mean().visibility;
  it.lightSubpathFactor = visible > 0.0 ? 1.0 / visible : 1.0;
  const VcmTracer weighted(ctx_, it);
  if (visible > 0.0) rescore(set, weighted);
  if (visible > 0.0 && set.prepare()) {
    const MebNormalisers frozen = set.sums().mean();
    NormaliserSums all = set.sums();
    all.add(runChains(weighted, set, frozen, iteration, s));
    const MebNormalisers b = all.mean();
    s.visibility = b.visibility;
    s.contribution = b.contribution;
    // Each chain's splats were weighted with the frozen b'; its estimate is scaled by b / b'.
    const double scale[2] = {b.visibility / frozen.visibility, b.contribution / frozen.contribution};
    for (int k = 0; k < 2; ++k)
      for (Film& f : chainFilms_[k]) {
        film.addWeighted(f, scale[k]);
        f.clear();
      }
  } else {
    ++s.withoutChains;  // no light subpath of the initial set reached a camera subpath
  }
  cameras_.splatOwnTechniques(weighted.mis().lightSubpathTerm(), workerFilms_);
  for (Film& f : workerFilms_) {  // in worker order
    film.addWeighted(f, 1.0);
    f.clear();
  }
  stats_.add(s);
}

// The initial set in one block of its samples per worker, joined in sample order.
MebRenderer::InitialSet MebRenderer::initialSet(const VcmTracer& tracer, uint64_t iteration) {
  std::vector<InitialSet> parts(static_cast<size_t>(workers_));
  std::vector<MebLightPath> evaluate = evaluators(workers_, ctx_, tracer, cameras_);
  const uint64_t key = hashKey(seed_, kInitialPurpose, iteration);
  const uint64_t pixels = uint64_t(width_) * uint64_t(height_);
  const uint64_t n = settings_.initialPaths > 0 ? uint64_t(settings_.initialPaths) : std::min<uint64_t>(10000, pixels);
  runOnWorkers(workers_, [&](int w) {
    const uint32_t first = uint32_t(n * uint64_t(w) / uint64_t(workers_)), end = uint32_t(n * uint64_t(w + 1) / uint64_t(workers_));
    parts[size_t(w)].evaluate(key, first, end, [&](SampleSource& u, uint32_t) { return evaluate[size_t(w)](u); });
  });
  InitialSet set;
  for (InitialSet& part : parts) set.append(std::move(part));
  MebStats counts;
  addCounts(counts, evaluate);
  stats_.add(counts);
  return set;
}

void MebRenderer::rescore(InitialSet& set, const VcmTracer& tracer) {
  std::vector<MebLightPath> evaluate = evaluators(workers_, ctx_, tracer, cameras_);
  const size_t n = set.visibleCount();
  runOnWorkers(workers_, [&](int w) {
    set.rescore(n * size_t(w) / size_t(workers_), n * size_t(w + 1) / size_t(workers_),
                [&](SampleSource& u) { return evaluate[size_t(w)](u); });
  });
  set.rescored();
  MebStats counts;
  addCounts(counts, evaluate);
  stats_.add(counts);
}

// The iteration's N light subpaths split over the pairs (pair k: steps N k / K .. N (k + 1) / K),
// the pairs taken by the workers as they come free; their large steps' sums joined in pair order.
NormaliserSums MebRenderer::runChains(const VcmTracer& tracer, const InitialSet& set, const MebNormalisers& frozen,
                                      uint64_t iteration, MebStats& s) {
  const size_t pairs = size_t(std::max(settings_.pairs, 1));
  const uint64_t n = uint64_t(width_) * uint64_t(height_);
  std::vector<MebLightPath> evaluate = evaluators(workers_, ctx_, tracer, cameras_);
  std::vector<NormaliserSums> large(pairs);
  std::vector<MebStats> perPair(pairs);
  runInOrder(
      workers_, pairs,
      [&](size_t k, int w) {
        Rng pick(hashKey(seed_, kStartPurpose, iteration, k));
        MebChainPair<MebContribution> pair(hashKey(seed_, kPairPurpose, iteration, k), frozen,
                                           settings_.largeStepProbability);
        pair.start(set.visibilityStart(pick), set.contributionStart(pick));
        Film* films[2] = {&chainFilms_[0][size_t(w)], &chainFilms_[1][size_t(w)]};
        const auto splat = [&](MebChain chain, const MebContribution& c, double weight) {
          films[int(chain)]->addSample(c.sample, weight);
        };
        const uint64_t steps = n * (k + 1) / pairs - n * k / pairs;
        for (uint64_t i = 0; i < steps; ++i) pair.step(evaluate[size_t(w)], splat, large[k]);
        MebStats& p = perPair[k];
        for (MebChain c : {MebChain::Visibility, MebChain::Contribution}) {
          p.steps[int(c)] = pair.counters(c).steps;
          p.accepted[int(c)] = pair.counters(c).accepted;
          p.theta[int(c)] = pair.adaptation(c).theta() / double(pairs);
        }
        p.largeSteps = pair.counters(MebChain::Visibility).largeSteps;
        p.exchanges = pair.exchanges();
        p.exchangesTried = pair.exchangesTried();
      },
      [&](size_t k) { s.add(perPair[k]); });
  addCounts(s, evaluate);
  NormaliserSums sum;
  for (const NormaliserSums& l : large) sum.add(l);
  return sum;
}

}  // namespace relt
