#include "checkpoint/checkpoint_io.h"

#include "checkpoint/checkpoint.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/words.h"

namespace relt {
namespace {

CheckpointTally g_tally;

}  // namespace

void saveCheckpoint(Job& job, const CheckpointPlan& plan, const char* integrator, const nlohmann::json& progress,
                    std::span<const Film> films, const std::vector<uint64_t>& part) {
  const auto start = Clock::now();
  std::vector<const std::vector<double>*> sums;
  for (const Film& f : films) sums.push_back(&f.data());
  if (plan.directFilm) sums.push_back(&plan.directFilm->data());
  const std::vector<std::vector<uint64_t>> parts = job.gatherToRoot(part);
  // The films are reduced straight into the root's words: a large film is copied once, not thrice.
  const size_t length = sums.empty() ? 0 : sums[0]->size();
  size_t words = 3 + sums.size() * length;
  for (const std::vector<uint64_t>& p : parts) words += 1 + p.size();
  WordWriter w;
  if (job.isRoot()) {
    w.reserve(words);
    w.u64(sums.size());
    w.u64(length);
  }
  for (const std::vector<double>* s : sums)
    job.reduceSumToRoot(*s, job.isRoot() ? reinterpret_cast<double*>(w.slots(s->size())) : nullptr);
  std::string problem;
  if (job.isRoot()) {
    Checkpoint c;
    c.header = {{"format", 1},          {"integrator", integrator}, {"ranks", parts.size()},
                {"progress", progress}, {"identity", plan.identity}, {"settings", plan.settings}};
    if (!plan.direct.is_null()) c.header["progress"]["direct"] = plan.direct;
    w.u64(parts.size());
    for (const std::vector<uint64_t>& p : parts) w.block(p);
    c.words = std::move(w.words());
    try {
      writeCheckpoint(plan.dir, c);
    } catch (const InputError& e) {
      problem = std::string(e.what()) + "; the render stops here (an earlier checkpoint in " + plan.dir + " is intact)";
    }
  }
  job.shareRootProblem(problem);
  ++g_tally.written;
  g_tally.seconds += secondsSince(start);
}

const CheckpointTally& checkpointTally() { return g_tally; }

Resumed loadCheckpoint(Job& job, const CheckpointPlan& plan, const char* integrator) {
  Resumed out;
  out.file = checkpointFile(plan.resume);
  std::vector<uint64_t> parts;
  std::string problem, header;
  if (job.isRoot()) {
    try {
      const Checkpoint c = readCheckpoint(plan.resume);
      if (c.header.value("integrator", "") != integrator)
        throw InputError(out.file, "", "the checkpoint is of a " + c.header.value("integrator", std::string("?")) +
                                           " render, this one is " + integrator);
      checkSameRender(c.header.at("identity"), plan.identity, out.file);
      WordReader in(c.words);
      const uint64_t count = in.u64(), length = in.u64();
      for (uint64_t k = 0; k < count; ++k) out.films.push_back(in.f64s(length));
      WordWriter rest;
      for (uint64_t n = in.u64(); n > 0; --n) rest.block(in.block());
      parts = std::move(rest.words());
      nlohmann::json h = {{"progress", c.header.at("progress")}, {"films", count}, {"film_length", length}};
      header = h.dump();
    } catch (const InputError& e) {
      problem = e.what();
    } catch (const std::exception& e) {  // a malformed header or word stream of a valid checksum
      problem = out.file + ": the checkpoint does not read as one (" + e.what() + ")";
    }
  }
  job.shareRootProblem(problem);
  job.broadcastFromRoot(parts);
  job.broadcastFromRoot(header);
  const nlohmann::json h = nlohmann::json::parse(header);
  out.progress = h.at("progress");
  out.filmCount = h.at("films").get<size_t>();
  out.filmLength = h.at("film_length").get<size_t>();
  WordReader in(parts);
  while (!in.done()) out.parts.push_back(in.block());
  return out;
}

void Resumed::restoreFilms(std::span<Film> into) const {
  if (filmCount != into.size() || (filmCount > 0 && filmLength != into[0].data().size()))
    throw InputError(file, "", "the checkpoint's films do not match this render's");
  for (size_t k = 0; k < films.size(); ++k) into[k].data() = films[k];
}

std::vector<double> Resumed::takeLastFilm(Job& job) {
  if (filmCount == 0) throw InputError(file, "", "the checkpoint's films do not match this render's");
  std::vector<double> last(filmLength);
  if (!films.empty()) {
    last = std::move(films.back());
    films.pop_back();
  }
  --filmCount;
  job.broadcastFromRoot(last);
  return last;
}

}  // namespace relt
