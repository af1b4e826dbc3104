#include "replica/round_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace relt {
namespace {

using Clock = std::chrono::steady_clock;

struct Stepper {
  ReplicaPool& pool;
  const ReplicaSchedule& schedule;
  RoundTransport& transport;
  std::vector<Film>& films;
  const RoundLoopHooks& hooks;
  double steppings = 0.0, sum = 0.0, sumSquares = 0.0;  // per-group-round stepping times
  double finishes = 0.0, finishSum = 0.0;                // time in finishRound
  std::vector<double> trace = {};                        // the first hooks.traceLimit stepping times
  std::vector<std::vector<size_t>> lengths = {};         // per group, every rank's message length
  bool stopRequested = false;

  // Message lengths change only when chains move.
  void measureLengths() {
    lengths.assign(size_t(pool.groups()), {});
    for (int g = 0; g < pool.groups(); ++g)
      for (int r = 0; r < pool.rankCount(); ++r) lengths[size_t(g)].push_back(pool.messageLength(g, r));
  }

  // Steps a group's chains for round `round` and starts its collective.
  void stepAndPost(int group, uint64_t round) {
    const auto t0 = Clock::now();
    pool.runRound(group, schedule.stepsInRound(round), films, [this] { transport.progress(); });
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    steppings += 1.0;
    sum += seconds;
    sumSquares += seconds * seconds;
    if (trace.size() < hooks.traceLimit) trace.push_back(seconds);
    const bool stop = hooks.stop && hooks.stop();
    transport.post(group, pool.roundMessage(group, hooks.elapsed(), seconds, stop), lengths[size_t(group)]);
  }
  // Completes a group's collective for round `round`: exchanges, normalisers, chain moves.
  // Returns the agreed elapsed time; a stop request of any group's round is remembered (every rank
  // reads the same messages in the same order, so all see it at the same point).
  double finish(int group, uint64_t round) {
    const std::vector<std::vector<double>> messages = transport.wait(group);
    const auto t0 = Clock::now();
    const RoundAgreement agreed = pool.finishRound(group, messages, round);
    stopRequested |= agreed.stop;
    const double elapsed = agreed.elapsed;
    finishes += 1.0;
    finishSum += std::chrono::duration<double>(Clock::now() - t0).count();
    if (!pool.plannedMoves().empty()) {
      transport.migrate(pool);
      measureLengths();
    }
    return elapsed;
  }
};

}  // namespace

RoundLoopResult runRoundLoop(ReplicaPool& pool, const ReplicaSchedule& schedule, RoundTransport& transport,
                             std::vector<Film>& films, const RoundLoopHooks& hooks, const RoundLoopStart& start) {
  RoundLoopResult out;
  out.rounds = start.rounds;
  out.elapsed = start.elapsed;
  if (!pool.active() || !schedule.anotherRound(start.rounds, start.elapsed, 0.0)) return out;
  Stepper s{pool, schedule, transport, films, hooks};
  s.measureLengths();
  const int groups = pool.groups();
  int first = 0;  // the group the first pass of the loop below starts with
  if (start.rounds == 0) {
    for (int g = 0; g < groups; ++g) s.stepAndPost(g, 0);
  } else {
    // As at roundDone of the checkpoint: groups 1 .. G-1 owe round rounds - 1's collective, and
    // group 0 steps round `rounds` next.
    for (int g = 1; g < groups; ++g)
      transport.post(g, pool.roundMessage(g, hooks.elapsed(), 0.0), s.lengths[size_t(g)]);
    s.stepAndPost(0, start.rounds);
    first = 1;
  }
  double lastRound = 0.0;
  for (;;) {
    for (int g = first; g < groups; ++g) {
      // Group 0 finishes the round it just stepped; the others the round before (still pending).
      const double now = s.finish(g, g == 0 ? out.rounds : out.rounds - 1);
      if (g == 0) {
        // Every group has stepped rounds + 1 rounds; group 0's messages give the agreed time.
        ++out.rounds;
        lastRound = now - out.elapsed;
        out.elapsed = now;
        out.stopped = s.stopRequested;
        const bool more = !s.stopRequested && schedule.anotherRound(out.rounds, out.elapsed, lastRound);
        if (hooks.roundDone) hooks.roundDone(out.rounds, out.elapsed, more);
        if (!more) {
          for (int h = 1; h < groups; ++h) s.finish(h, out.rounds - 1);
          out.stepMean = s.sum / s.steppings;
          out.finishMean = s.finishSum / s.finishes;
          out.stepDeviation = std::sqrt(std::max(0.0, s.sumSquares / s.steppings - out.stepMean * out.stepMean));
          out.stepTrace = std::move(s.trace);
          return out;
        }
      }
      s.stepAndPost(g, out.rounds);
    }
    first = 0;
  }
}

void LocalTransport::post(int group, std::vector<double> mine, const std::vector<size_t>&) {
  if (posted_.size() <= size_t(group)) posted_.resize(size_t(group) + 1);
  posted_[size_t(group)] = std::move(mine);
}

std::vector<std::vector<double>> LocalTransport::wait(int group) { return {std::move(posted_[size_t(group)])}; }

}  // namespace relt
