#pragma once
// Checkpoints through the job (the format and its decisions are in checkpoint.h): films reduced
// onto the root, every rank's state gathered there and written by the root; read back by the root,
// checked against this render, and shared with every rank. Collective; a failure throws the same
// InputError on every rank.
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "checkpoint/checkpoint.h"
#include "film/film.h"
#include "parallel/job.h"

namespace relt {

struct CheckpointPlan {
  std::string dir;          // --checkpoint: where to write ("" = never)
  double every = 0.0;       // --checkpoint-every seconds (0: only when the render ends)
  std::string resume;       // --resume: the checkpoint to continue ("" = start afresh)
  nlohmann::json identity;  // imageIdentity() of this render (the root's; only it reads and writes)
  nlohmann::json settings;  // this render's settings, for the reader of the file (the root's)
  // pssmlt and relt: the direct-emission pass, in every checkpoint: its progress under "direct"
  // (direct_driver.h says what is in it) and its film, if it has rays, after the integrator's.
  nlohmann::json direct;
  const Film* directFilm = nullptr;
};

struct Resumed {
  std::string file;                          // the checkpoint read
  nlohmann::json progress;                   // how far the render got (the integrator's keys)
  size_t filmCount = 0, filmLength = 0;      // every rank knows them
  std::vector<std::vector<double>> films;    // the root: the reduced films; other ranks: none
  std::vector<std::vector<uint64_t>> parts;  // every rank: every rank's part, in the rank order of then
  // Puts the reduced films into the root's `films` (the other ranks' stay empty to add to them);
  // throws InputError on every rank if their number or size differs.
  void restoreFilms(std::span<Film> films) const;
  // Takes the last film out (the direct-emission pass) and returns it on every rank (collective).
  std::vector<double> takeLastFilm(Job& job);
};

// Whether the pass or round that just ended writes a checkpoint: the plan has a folder, and the
// ranks agreed on a save request or checkpointDue says one is due; `last` then becomes `elapsed`.
inline bool checkpointNow(const CheckpointPlan& plan, double elapsed, double& last, bool more, bool save = false) {
  if (plan.dir.empty() || !(save || checkpointDue(plan.every, elapsed, last, more))) return false;
  last = elapsed;
  return true;
}

// `progress` is the integrator's (rounds or passes, elapsed time, ...); `part` this rank's state.
// The plan's direct-emission pass, if any, is added to both.
void saveCheckpoint(Job& job, const CheckpointPlan& plan, const char* integrator, const nlohmann::json& progress,
                    std::span<const Film> films, const std::vector<uint64_t>& part);
// Checkpoints this process wrote (or took part in) and the seconds they took, for stats.json.
struct CheckpointTally {
  int written = 0;
  double seconds = 0.0;
};
const CheckpointTally& checkpointTally();

// Refuses a checkpoint of another integrator, scene or settings (before any rendering work).
Resumed loadCheckpoint(Job& job, const CheckpointPlan& plan, const char* integrator);

}  // namespace relt
