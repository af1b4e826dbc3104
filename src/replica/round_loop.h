#pragma once
// The order of a replica render's rounds, shared by the MPI driver and the in-process renderer.
// The ladders form G groups (kRoundGroups, fewer with fewer ladders) whose rounds are staggered: a
// rank steps group 0 and starts its collective, steps groups 1 .. G-1 likewise, and only then
// waits for group 0's. A rank therefore waits only when another is more than (G-1)/G of a round
// behind, not at every round's slowest rank, and the collective's latency hides behind the other
// groups' work. Every group still
// takes the same steps per round; exchanges, normalisers and placement follow the same fixed order
// on every rank, so the image does not depend on timing or rank count.
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "film/film.h"
#include "parallel/job.h"
#include "replica/replica_pool.h"
#include "replica/replica_schedule.h"

namespace relt {

// A rank's offer: the next round it reaches (where it can still act) and its requests. All act at
// the largest offered round, on every rank's requests together.
struct RequestOffer {
  uint64_t round = 0;
  bool stop = false, save = false;
};
RequestAgreement agreeOnOffers(const std::vector<RequestOffer>& offers);

// How a rank's pool meets the others: the MPI layer's collectives, or one process playing all.
class RoundTransport {
 public:
  virtual ~RoundTransport() = default;
  // Starts the collective of a group's round: every rank's message, rank r's `lengths[r]` long.
  // A group may have several in flight (ReplicaSettings::normaliserLag).
  virtual void post(int group, std::vector<double> mine, const std::vector<size_t>& lengths) = 0;
  // Completes the group's oldest: every rank's message, in rank order.
  virtual std::vector<std::vector<double>> wait(int group) = 0;
  // Carries out pool.plannedMoves() (chain states travel) and commits them on every rank.
  virtual void migrate(ReplicaPool& pool) = 0;
  // Called between chains while stepping: nonblocking collectives advance only inside MPI calls,
  // so without it a posted collective would wait for the next wait().
  virtual void progress() {}
  // Local decisions only: their messages are read back lag rounds late, too late for a stop that
  // must beat mpirun's kill, so requests travel apart. Called on every rank after every round
  // (group 0 has finished round `rounds` - 1) with this rank's requests since the last call;
  // returns the agreement the ranks act on here, if any. One process acts at once.
  virtual std::optional<RequestAgreement> requests(uint64_t rounds, bool stop, bool save) {
    if (!stop && !save) return std::nullopt;
    return RequestAgreement{rounds, stop, save};
  }
  // Local decisions only: completes (keeping them for wait) all but the newest `newest` of the
  // group's collectives in flight, so this rank leads the slowest by at most that many rounds.
  virtual void settle(int /*group*/, size_t /*newest*/) {}
  // Local decisions only: the loop's end, on every rank after the same round (an agreement under
  // way is completed and dropped).
  virtual void endRequests() {}
};

struct RoundLoopHooks {
  std::function<double()> elapsed;  // this rank's seconds since the loop started
  std::function<bool()> stop;       // this rank was asked to stop (optional): all end after this round
  std::function<bool()> save;       // this rank was asked to save (optional; true once per request)
  // After the round at which the ranks agreed on a save request, when another round follows (the
  // last round's outputs are written anyway): write the image so far and a checkpoint.
  std::function<void(uint64_t rounds, double elapsed)> saveNow;
  // After each round every group has stepped: rounds so far, the ranks' agreed elapsed time (the
  // latest read back, carried forward by the agreed duration of the rounds not read back yet), and
  // whether another round follows (snapshots, progress, checkpoints: group 0 has finished round
  // `rounds` - 1 and the other groups' collectives of that round are pending).
  std::function<void(uint64_t rounds, double elapsed, bool more)> roundDone;
  // Record the stepping time of the first this many group rounds (the scaling model replays them).
  size_t traceLimit = 0;
};

// Where the loop starts: at the beginning, or where a checkpoint was taken (after `rounds` rounds,
// `elapsed` seconds; the pool restored from it). A resumed loop posts the pending groups' messages
// again and goes on exactly as the interrupted one would have.
struct RoundLoopStart {
  uint64_t rounds = 0;
  double elapsed = 0.0;
  // An agreed first guess of a round's duration (0: none). Elapsed times arrive with the messages
  // read back, lag rounds late; until two have arrived a time budget relies on this guess.
  double secondsPerRound = 0.0;
};

struct RoundLoopResult {
  uint64_t rounds = 0;   // rounds every chain took
  bool stopped = false;  // ended early because a rank was asked to stop
  double elapsed = 0.0;  // agreed elapsed time at the end
  // This rank's time stepping one group for one round: mean and standard deviation over the
  // render (inputs of the scaling model: compute per round and its spread).
  double stepMean = 0.0, stepDeviation = 0.0;
  // Mean time this rank spent in finishRound per group round (exchanges of every ladder of the
  // group, normalisers, placement): replicated work, it grows with the total ladder count.
  double finishMean = 0.0;
  // This rank's stepping time of each group round in loop order, the first hooks.traceLimit.
  std::vector<double> stepTrace;
};

RoundLoopResult runRoundLoop(ReplicaPool& pool, const ReplicaSchedule& schedule, RoundTransport& transport,
                             std::vector<Film>& films, const RoundLoopHooks& hooks, const RoundLoopStart& start = {});

// One process plays every rank (rank 0 of 1): the in-process renderer and tests.
class LocalTransport final : public RoundTransport {
 public:
  void post(int group, std::vector<double> mine, const std::vector<size_t>&) override;
  std::vector<std::vector<double>> wait(int group) override;
  void migrate(ReplicaPool& pool) override { pool.commitMoves(); }

 private:
  std::vector<std::deque<std::vector<double>>> posted_;
};

}  // namespace relt
