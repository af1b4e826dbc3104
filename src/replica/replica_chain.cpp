#include "replica/replica_chain.h"

#include <array>
#include <stdexcept>

#include "mcmc/metropolis.h"

namespace relt {
namespace {
constexpr uint64_t kReplicaChainPurpose = 0x4e1a;
using Clock = std::chrono::steady_clock;
}  // namespace

uint64_t replicaChainKey(uint64_t seed, int chain) { return hashKey(seed, kReplicaChainPurpose, uint64_t(chain)); }

void LevelCounters::add(const LevelCounters& o) {
  ChainCounters::add(o);
  nonFinite += o.nonFinite;
  seconds += o.seconds;
}

LevelEvaluator::LevelEvaluator(PssEvaluator& eval, const LevelFamily& family) : eval_(eval), family_(family) {
  if (family.tempering() != nullptr) tempered_.emplace(*family.tempering());
}

bool LevelEvaluator::features(SampleSource& u, PathSample& out, double* f) const {
  eval_(u, out, tempered_ ? &*tempered_ : nullptr);
  return family_.features(out, tempered_ ? tempered_->levelTargets() : std::span<const double>(), f);
}

bool LevelEvaluator::operator()(SampleSource& u, PathSample& out, double* q) const {
  std::array<double, kMaxLevels> f;
  const bool finite = features(u, out, f.data());
  if (finite) {
    family_.targets(f.data(), q);
  } else {
    for (int k = 0; k < family_.levels(); ++k) q[k] = 0.0;
  }
  return finite;
}

ReplicaChain::ReplicaChain(uint64_t key, int level, const LevelFamily& family)
    : family_(family),
      u_(key, family.sizes(level)),
      rng_(key, 1),
      level_(level),
      counters_(size_t(family.levels())) {
  current_.q.assign(size_t(family.levels()), 0.0);
  proposal_.q.assign(size_t(family.levels()), 0.0);
}

ReplicaChain::ReplicaChain(const std::vector<uint64_t>& serialized, const LevelFamily& family,
                           const LevelEvaluator& eval)
    : ReplicaChain(0, 0, family) {
  if (serialized.size() < 3) throw std::runtime_error("truncated replica-chain state");
  rng_.restore(serialized[0], serialized[1]);
  level_ = int(serialized[2]);
  u_ = PrimarySampleVector::deserialize(std::vector<uint64_t>(serialized.begin() + 3, serialized.end()));
  RecordingSource replay(0, state());  // the state holds every number the current path used
  eval(replay, current_.path, current_.q.data());
}

std::vector<uint64_t> ReplicaChain::serialize() const {
  std::vector<uint64_t> out = {rng_.state(), rng_.increment(), uint64_t(level_)};
  const std::vector<uint64_t> u = u_.serialize();
  out.insert(out.end(), u.begin(), u.end());
  return out;
}

void ReplicaChain::setLevel(int level) {
  if (level == level_) return;
  level_ = level;
  u_.setSizes(family_.sizes(level));
}

void ReplicaChain::start(const LevelEvaluator& eval, uint64_t key, const StreamValues& prefix) {
  RecordingSource source(key, prefix);
  eval(source, current_.path, current_.q.data());
  for (int s = 0; s < kSampleStreamCount; ++s)
    u_.setState(static_cast<SampleStream>(s), source.values(static_cast<SampleStream>(s)));
}

void ReplicaChain::refresh(const LevelEvaluator& eval) {
  const uint64_t key = (uint64_t(rng_.nextU32()) << 32) | rng_.nextU32();  // only if the path needs more numbers
  start(eval, key, state());
}

template <class Output>
void ReplicaChain::run(uint64_t steps, const LevelEvaluator& eval, const LevelEstimator& estimator, Output& out) {
  const auto t0 = Clock::now();
  for (uint64_t i = 0; i < steps; ++i) step(eval, &estimator, &out);
  counters_[size_t(level_)].seconds += std::chrono::duration<double>(Clock::now() - t0).count();
}

void ReplicaChain::explore(uint64_t steps, const LevelEvaluator& eval) {
  for (uint64_t i = 0; i < steps; ++i) step<DirectOutput>(eval, nullptr, nullptr);
}

StreamValues ReplicaChain::state() const {
  StreamValues values;
  for (int s = 0; s < kSampleStreamCount; ++s)
    for (const PrimarySampleVector::Coordinate& c : u_.coordinates(static_cast<SampleStream>(s)))
      values[size_t(s)].push_back(c.value);
  return values;
}

template <class Output>
void ReplicaChain::step(const LevelEvaluator& eval, const LevelEstimator* estimator, Output* out) {
  const size_t k = size_t(level_);
  const bool isLarge = rng_.uniform() < family_.largeStepProbability(level_);
  u_.startIteration(isLarge);
  const bool finite = eval(u_, proposal_.path, proposal_.q.data());
  LevelCounters& c = counters_[k];
  if (!finite) ++c.nonFinite;
  (isLarge ? c.largeProposed : c.smallProposed)++;
  if (isLarge && out) out->addLargeStep(proposal_.q);
  const double a = acceptance(current_.q[k], proposal_.q[k]);
  if (!(proposal_.q[k] > 0.0)) ++c.invalidProposals;
  // Expected values: the current state with 1 - a, the proposal with a (thesis digest §2.7).
  if (estimator && out) {
    if (current_.q[k] > 0.0 && a < 1.0) estimator->splat(current_.path, current_.q.data(), level_, 1.0 - a, *out);
    if (a > 0.0) estimator->splat(proposal_.path, proposal_.q.data(), level_, a, *out);
  }
  if (keepOrRevert(rng_.uniformDouble() < a, u_, current_, proposal_)) (isLarge ? c.largeAccepted : c.smallAccepted)++;
}

// The outputs a pool steps its chains into: one worker's straight, several workers' kept in order.
template void ReplicaChain::run(uint64_t, const LevelEvaluator&, const LevelEstimator&, DirectOutput&);
template void ReplicaChain::run(uint64_t, const LevelEvaluator&, const LevelEstimator&, ChainLog&);

}  // namespace relt
