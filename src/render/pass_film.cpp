#include "pass_film.h"

#include <algorithm>

namespace relt {

PassFilm::PassFilm(int width, int height, bool rowsStandAlone, size_t tallySize, int workers)
    : rowsStandAlone_(rowsStandAlone),
      films_(rowsStandAlone ? 1 : 2, Film(width, height)),
      tallies_(rowsStandAlone ? 1 : 2, std::vector<double>(tallySize, 0.0)),
      workerFilms_(size_t(std::max(workers, 1) - 1), Film(width, height)),
      workerTallies_(workerFilms_.size(), std::vector<double>(tallySize, 0.0)) {}

void PassFilm::gatherWorkers() {
  for (size_t w = 0; w < workerFilms_.size(); ++w) {
    gatherWorkerFilms({&films_[0], 1}, {&workerFilms_[w], 1});
    gatherWorkerTally(tallies_[0], workerTallies_[w]);
  }
}

void PassFilm::passEnded() {
  gatherWorkers();
  if (rowsStandAlone_) return;
  films_[1] = films_[0];
  tallies_[1] = tallies_[0];
}

PassPoint PassFilm::shown(PassPoint at) const { return rowsStandAlone_ ? at : PassPoint{at.passes, 0}; }

bool PassFilm::showsNew(PassPoint at, std::optional<PassPoint> last) const {
  const PassPoint now = shown(at);
  if (now.passes == 0 && now.rows == 0) return false;
  if (!last) return true;
  const PassPoint before = shown(*last);
  return now.passes != before.passes || now.rows != before.rows;
}

void PassFilm::restored(PassPoint at) {
  if (at.rows == 0) passEnded();  // a checkpoint between passes holds the live sums only
}

}  // namespace relt
