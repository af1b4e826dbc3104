#include "replica/round_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "schedule/pace.h"

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
  bool stopRequested = false, saveRequested = false;

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
    // With local decisions the requests travel apart from the messages (askApart).
    const bool inMessages = !pool.localDecisions();
    const bool stop = inMessages && hooks.stop && hooks.stop(), save = inMessages && hooks.save && hooks.save();
    transport.post(group, pool.roundMessage(group, hooks.elapsed(), seconds, stop, save), lengths[size_t(group)]);
    // A stop waits for the slowest rank to catch up: bound the lead (leadCapRounds).
    if (!inMessages) transport.settle(group, leadCapRounds(sum / steppings * double(pool.groups())));
  }
  // Completes a group's collective for round `round`: exchanges, normalisers, chain moves.
  // Returns the agreement; a stop request of any group's round is remembered (every rank reads the
  // same messages in the same order, so all see it at the same point).
  RoundAgreement finish(int group, uint64_t round) {
    // Spread: this round's messages (its exchanges need the targets); local decisions: the
    // collectives of the rounds whose sums are due.
    std::vector<std::vector<double>> messages;
    std::vector<std::vector<std::vector<double>>> readBacks;
    if (!pool.localDecisions())
      messages = transport.wait(group);
    else
      for (size_t i = pool.dueReadBacks(group, round); i > 0; --i) readBacks.push_back(transport.wait(group));
    const auto t0 = Clock::now();
    const RoundAgreement agreed = pool.finishRound(group, messages, round, readBacks);
    stopRequested |= agreed.stop;
    saveRequested |= agreed.save;
    finishes += 1.0;
    finishSum += std::chrono::duration<double>(Clock::now() - t0).count();
    if (!pool.plannedMoves().empty()) {
      transport.migrate(pool);
      measureLengths();
    }
    return agreed;
  }
  // Local decisions: this rank's requests to the transport after group 0's round; what the ranks
  // agreed to do here is remembered as a request in the messages would be.
  void askApart(uint64_t rounds) {
    if (!pool.localDecisions()) return;
    const bool stop = hooks.stop && hooks.stop(), save = hooks.save && hooks.save();
    if (const std::optional<RequestAgreement> agreed = transport.requests(rounds, stop, save)) {
      stopRequested |= agreed->stop;
      saveRequested |= agreed->save;
    }
  }
};

// The agreed elapsed time after each of group 0's rounds. Spread placement reads it from the
// round's own messages. With local decisions the latest time comes back lag rounds late and is
// carried over the rounds not read back yet by the typical duration of a round (Pace: a round that
// spanned a stall neither ends a time budget early nor stays in the estimate).
struct AgreedClock {
  double at = 0.0;  // the latest agreed time
  uint64_t readAt = 0;
  Pace pace;

  double update(const RoundAgreement& agreed, uint64_t read, size_t unread) {
    if (agreed.fresh) {
      if (agreed.elapsed > at) pace.add(agreed.elapsed - at);
      at = std::max(at, agreed.elapsed);
      return at;
    }
    // Rounds restored from a checkpoint carry no newer time: they only move the count on.
    if (read > readAt && agreed.elapsed > at) {
      pace.add(agreed.elapsed - at, size_t(read - readAt));
      at = agreed.elapsed;
    }
    readAt = std::max(readAt, read);
    return at + pace.typical() * double(unread);
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
    // As at roundDone of the checkpoint: the collectives of the rounds not read back yet go out
    // again (group 0's last round is finished, the other groups' is not), and group 0 steps round
    // `rounds` next.
    for (int g = 0; g < groups; ++g)
      for (std::vector<double>& msg : pool.resumeMessages(g, start.elapsed)) transport.post(g, std::move(msg), s.lengths[size_t(g)]);
    s.stepAndPost(0, start.rounds);
    first = 1;
  }
  AgreedClock clock{start.elapsed, pool.roundsReadBack(0), {}};
  if (start.secondsPerRound > 0.0) clock.pace.add(start.secondsPerRound);  // until rounds are timed
  for (;;) {
    for (int g = first; g < groups; ++g) {
      // Group 0 finishes the round it just stepped; the others the round before (still pending).
      const RoundAgreement agreed = s.finish(g, g == 0 ? out.rounds : out.rounds - 1);
      if (g == 0) {
        ++out.rounds;
        out.elapsed = clock.update(agreed, pool.roundsReadBack(0), pool.unread(0));
        s.askApart(out.rounds);
        out.stopped = s.stopRequested;
        const bool more = !s.stopRequested && schedule.anotherRound(out.rounds, out.elapsed, clock.pace.typical());
        if (hooks.roundDone) hooks.roundDone(out.rounds, out.elapsed, more);
        if (s.saveRequested && more && hooks.saveNow) hooks.saveNow(out.rounds, out.elapsed);
        s.saveRequested = false;
        if (!more) {
          for (int h = 1; h < groups; ++h) s.finish(h, out.rounds - 1);
          // Rounds whose messages were still travelling: every rank takes part, nobody reads them.
          for (int h = 0; h < groups; ++h)
            for (size_t i = pool.inFlight(h); i > 0; --i) transport.wait(h);
          if (pool.localDecisions()) transport.endRequests();
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

RequestAgreement agreeOnOffers(const std::vector<RequestOffer>& offers) {
  RequestAgreement agreed;
  for (const RequestOffer& o : offers) {
    agreed.round = std::max(agreed.round, o.round);
    agreed.stop |= o.stop;
    agreed.save |= o.save;
  }
  return agreed;
}

void LocalTransport::post(int group, std::vector<double> mine, const std::vector<size_t>&) {
  if (posted_.size() <= size_t(group)) posted_.resize(size_t(group) + 1);
  posted_[size_t(group)].push_back(std::move(mine));
}

std::vector<std::vector<double>> LocalTransport::wait(int group) {
  std::vector<std::vector<double>> out{std::move(posted_[size_t(group)].front())};
  posted_[size_t(group)].pop_front();
  return out;
}

}  // namespace relt
