#include "mcmc/chain_pool.h"

#include <algorithm>
#include <span>
#include <stdexcept>

#include "core/words.h"
#include "parallel/workers.h"

namespace relt {
namespace {
constexpr uint64_t kPartVersion = 1;
}  // namespace

ChainPool::ChainPool(PerWorker<PssEvaluator>* pss, PerWorker<MmltEvaluator>* mmlt,
                     const std::vector<double>& bootstrapTargets, uint64_t seed, const PssmltSettings& settings,
                     const std::vector<int>& chains)
    : pss_(pss), mmlt_(mmlt), ids_(chains) {
  const Distribution1D bootstrap(bootstrapTargets);
  if (bootstrap.total() <= 0.0) return;  // nothing visible: no chains, the image stays black
  const MmltChainPlan plan =
      mmlt_ ? planMmltChains(bootstrapTargets, maxDepth(), settings.chains) : MmltChainPlan{};
  depthFilms_ = plan.stratified;
  const size_t depths = mmlt_ ? static_cast<size_t>(maxDepth()) : 0;
  // mmlt with a plan: a chain starts at one of its depth's bootstrap samples, in proportion to target.
  std::vector<Distribution1D> atDepth(depths);
  auto startsAtDepth = [&](int depth) -> const Distribution1D& {
    Distribution1D& dist = atDepth[static_cast<size_t>(depth - 1)];
    if (dist.empty()) {
      std::vector<double> masked(bootstrapTargets.size(), 0.0);
      for (size_t i = static_cast<size_t>(depth - 1); i < masked.size(); i += depths) masked[i] = bootstrapTargets[i];
      dist = Distribution1D(masked);
    }
    return dist;
  };
  chains_.reserve(chains.size());
  for (int c : chains) {
    McmcChain& chain = chains_.emplace_back(seed, c, settings);
    if (!mmlt_) {
      depth_.push_back(0);
      chain.start((*pss_)[0], bootstrapKey(seed, chain.pickBootstrap(bootstrap)));
      continue;
    }
    int depth;
    size_t index;
    if (plan.stratified) {
      depth = plan.depth[static_cast<size_t>(c)];
      index = chain.pickBootstrap(startsAtDepth(depth));
    } else {
      index = chain.pickBootstrap(bootstrap);
      depth = mmltDepthOfBootstrap(index, maxDepth());
    }
    depth_.push_back(depth);
    const auto eval = [&](SampleSource& u, PathSample& out) { return (*mmlt_)[0](depth, u, out); };
    chain.start(eval, bootstrapKey(seed, index));
  }
}

template <class F>
void ChainPool::withEvaluator(size_t i, int worker, F&& f) {
  if (!mmlt_) return f((*pss_)[worker]);
  MmltEvaluator& eval = (*mmlt_)[worker];
  const int depth = depth_[i];
  f([&eval, depth](SampleSource& u, PathSample& out) { return eval(depth, u, out); });
}

std::vector<Film>& ChainPool::depthFilms(int width, int height) {
  if (depthFilms_ && films_.empty()) films_.assign(static_cast<size_t>(maxDepth()), Film(width, height));
  return films_;
}

Film& ChainPool::filmOf(size_t i, Film& film) {
  return depthFilms_ ? films_[static_cast<size_t>(depth_[i] - 1)] : film;
}

void ChainPool::run(const std::vector<uint64_t>& steps, Film& film) {
  depthFilms(film.width(), film.height());
  const int workers = std::min(this->workers(), std::max(int(chains_.size()), 1));
  auto stepChain = [&](size_t i, int w, auto& sink) {
    withEvaluator(i, w, [&](auto&& eval) {
      for (uint64_t k = 0; k < steps[i]; ++k) chains_[i].step(eval, sink);
    });
  };
  if (workers == 1) {
    for (size_t i = 0; i < chains_.size(); ++i) stepChain(i, 0, filmOf(i, film));
    return;
  }
  logs_.resize(chains_.size());
  runInOrder(
      workers, chains_.size(),
      [&](size_t i, int w) {
        logs_[i].clear();
        stepChain(i, w, logs_[i]);
      },
      [&](size_t i) { logs_[i].replayInto(filmOf(i, film)); });
}

std::vector<uint64_t> ChainPool::checkpointPart() const {
  WordWriter w;
  w.u64(kPartVersion);
  w.u64(chains_.size());
  for (size_t i = 0; i < chains_.size(); ++i) {
    w.u64(static_cast<uint64_t>(ids_[i]));
    w.u64(static_cast<uint64_t>(depth_[i]));
    w.block(chains_[i].serialize());
  }
  return std::move(w.words());
}

void ChainPool::restore(const std::vector<std::vector<uint64_t>>& parts) {
  if (chains_.empty()) return;  // nothing visible: no chains were made, none were saved
  std::vector<size_t> index;  // global id -> position here (size(): not held here)
  for (size_t i = 0; i < ids_.size(); ++i) {
    const size_t id = static_cast<size_t>(ids_[i]);
    if (index.size() <= id) index.resize(id + 1, chains_.size());
    index[id] = i;
  }
  std::vector<char> found(chains_.size(), 0);
  for (const std::vector<uint64_t>& part : parts) {
    WordReader in(part);
    if (in.u64() != kPartVersion) throw std::runtime_error("the checkpoint's chains are of another format");
    for (uint64_t n = in.u64(); n > 0; --n) {
      const uint64_t id = in.u64(), depth = in.u64();
      const std::vector<uint64_t> state = in.block();
      if (id >= index.size() || index[id] == chains_.size()) continue;  // another rank's chain now
      const size_t i = index[id];
      if (found[i] || (mmlt_ && depth != static_cast<uint64_t>(depth_[i])))
        throw std::runtime_error("the checkpoint's chains are not this render's");
      found[i] = 1;
      withEvaluator(i, 0, [&](auto&& eval) { chains_[i].restore(eval, state); });
    }
    if (!in.done()) throw std::runtime_error("the checkpoint's chain state has trailing data");
  }
  for (char f : found)
    if (!f) throw std::runtime_error("the checkpoint misses chains");
}

void ChainPool::mergeDepthFilms(const std::vector<double>& weight, Film& into) const {
  for (size_t d = 0; d < films_.size(); ++d) into.addWeighted(films_[d], d < weight.size() ? weight[d] : 0.0);
}

ChainCounters ChainPool::counters() const {
  ChainCounters total;
  for (const McmcChain& c : chains_) total.add(c.counters());
  return total;
}

std::vector<ChainCounters> ChainPool::perDepth() const {
  if (!mmlt_) return {};
  std::vector<ChainCounters> d(static_cast<size_t>(maxDepth()));
  for (size_t i = 0; i < chains_.size(); ++i) d[static_cast<size_t>(depth_[i] - 1)].add(chains_[i].counters());
  return d;
}

}  // namespace relt
