#pragma once
// The sums of the pass loop (pt, bdpt, erpt) and what an image stopped inside a pass may show.
// pt's samples land in their own row, so rows done in a pass stand alone: the image divides each
// row by its own samples. bdpt's light paths and erpt's chains splat into any row, so the rows done
// lack the splats of the rows not done: inside a pass these show the whole passes only, kept as a
// copy of the sums at the last pass end (pass k's samples depend on k only, so that is exactly the
// image of a render of that many passes).
#include <optional>
#include <span>
#include <vector>

#include "film/film.h"
#include "schedule/schedule.h"
#include "render/settings.h"

namespace relt {

class PassFilm {
 public:
  // `tallySize`: per-pixel counts kept beside the film (erpt's proposal filter), or 0; `workers`:
  // the rank's worker threads, each rendering into sums of its own.
  PassFilm(int width, int height, bool rowsStandAlone, size_t tallySize = 0, int workers = 1);

  Film& live() { return films_[0]; }
  const Film& live() const { return films_[0]; }
  std::vector<double>& tally() { return tallies_[0]; }
  const std::vector<double>& tally() const { return tallies_[0]; }

  // The sums worker w adds to: the live ones for worker 0, its own for the others.
  Film& workerFilm(int w) { return w == 0 ? films_[0] : workerFilms_[size_t(w - 1)]; }
  std::vector<double>* workerTally(int w) {
    std::vector<double>& t = w == 0 ? tallies_[0] : workerTallies_[size_t(w - 1)];
    return t.empty() ? nullptr : &t;
  }
  // Adds the other workers' sums into the live ones and clears theirs: before the live sums are
  // read (at pass ends, snapshots, checkpoints and the end).
  void gatherWorkers();

  // At every pass end: the workers' sums are gathered and the live sums become the whole passes'
  // (a copy, where rows do not stand alone).
  void passEnded();

  // What an image at `at` shows: `at` where rows stand alone or at a pass end, else the whole passes.
  PassPoint shown(PassPoint at) const;
  // Whether an image at `at` shows samples that one at `last` (if any) did not: a periodic
  // snapshot with nothing new is not written (bdpt's inside its first pass would be black).
  bool showsNew(PassPoint at, std::optional<PassPoint> last) const;
  // This rank's sums and tally of the image at `at` (the live ones or the last pass end's).
  const std::vector<double>& sumsShown(PassPoint at) const { return films_[wholeIndex(at)].data(); }
  const std::vector<double>& tallyShown(PassPoint at) const { return tallies_[wholeIndex(at)]; }

  // The films a checkpoint at `at` holds: the live one, and the last pass end's if it differs.
  std::span<const Film> checkpointFilms(PassPoint at) const { return {films_.data(), filmsKept(at)}; }
  std::span<Film> checkpointFilms(PassPoint at) { return {films_.data(), filmsKept(at)}; }
  // The tallies a checkpoint at `at` holds, likewise.
  std::span<std::vector<double>> checkpointTallies(PassPoint at) { return {tallies_.data(), filmsKept(at)}; }
  std::span<const std::vector<double>> checkpointTallies(PassPoint at) const {
    return {tallies_.data(), filmsKept(at)};
  }
  // After a checkpoint at `at` was restored into checkpointFilms(at) and checkpointTallies(at).
  void restored(PassPoint at);

 private:
  size_t wholeIndex(PassPoint at) const { return shown(at).rows == at.rows ? 0 : 1; }
  size_t filmsKept(PassPoint at) const { return 1 + wholeIndex(at); }

  bool rowsStandAlone_;
  std::vector<Film> films_;                 // live, last pass end
  std::vector<std::vector<double>> tallies_;  // live, last pass end
  std::vector<Film> workerFilms_;               // workers 1 .. N - 1
  std::vector<std::vector<double>> workerTallies_;
};

}  // namespace relt
