#pragma once
// The loop of the integrators that render in whole iterations of the image (vcm, meb): rounds of
// one iteration per rank (iteration done + k on rank k) until the budget (--spp iterations, or
// --time decided on the slowest rank's clock) is spent or a rank is asked to stop. After every
// round the ranks agree; snapshots and checkpoints are taken there. A checkpoint holds the film
// and the iterations done, so a resumed render (on any number of ranks) goes on with the next.
// After the direct-emission pass (direct_driver.h) the loop has the budget less the pass's time,
// and its images have the pass's added.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "film/film.h"
#include "image/image.h"
#include "integrators/direct/direct_driver.h"
#include "integrators/integrator.h"
#include "integrators/output/render_outputs.h"
#include "schedule/schedule.h"

namespace relt {

class IterationLoop {
 public:
  // render(i) adds iteration i's estimate to `film`; `name` is the checkpoint's integrator;
  // `direct` the pass rendered before (its spp 0: none), `renderStart` when the render began.
  IterationLoop(RenderContext& c, const char* name, Film& film, std::function<void(uint64_t)> render,
                const DirectEstimate& direct, Clock::time_point renderStart);

  void run();
  // The image of the iterations done and the pass, on the root (the film reduced over the ranks).
  Image image();

  uint64_t done() const { return done_; }         // iterations finished on every rank
  uint64_t resumedAt() const { return resumedAt_; }  // of which a resumed render's
  int snapshots() const { return snapshots_; }
  Clock::time_point renderStart() const { return renderStart_; }
  const DirectEstimate& direct() const { return direct_; }

 private:
  void save(double elapsed);
  void printProgress(double agreed, uint64_t budget, double& lastPrint) const;

  RenderContext& c_;
  const char* name_;
  Film& film_;
  std::function<void(uint64_t)> render_;
  const DirectEstimate& direct_;
  Clock::time_point renderStart_;
  std::optional<double> budgetSeconds_;  // for the iterations (none: --spp)
  uint64_t done_ = 0, resumedAt_ = 0;
  double earlier_ = 0.0;  // seconds of the render this one continues
  int snapshots_ = 0;
  Clock::time_point start_ = Clock::now();
};

// What an iteration integrator's render does after its loop: `own` (on every rank, which may
// reduce over the ranks) gives its stats; on the root they are added to every render's and the
// iterations', the outputs written and `closing(stats, gathered)` printed with the files written.
void finishIterations(RenderContext& c, IterationLoop& loop, Film& film, const std::function<nlohmann::json()>& own,
                      const std::function<std::string(const nlohmann::json&, const Gathered&)>& closing);

}  // namespace relt
