#pragma once
// The tempered family's "evaluate all levels" (DESIGN §3.1): a connection hook (path/
// connection_hook.h) that, while BDPT traces one path, sums for every level k the luminance of each
// strategy's MIS-weighted contribution with its connection BSDFs tempered for level k. One traced
// path and one visibility ray per strategy give every level's target.
#include <optional>
#include <span>
#include <vector>

#include "path/connection_hook.h"
#include "replica/tempering.h"

namespace relt {

class TemperedTargets final : public ConnectionHook {
 public:
  // `tempering` is read at every path (the regularisation floor moves during a render).
  explicit TemperedTargets(const Tempering& tempering) : tempering_(tempering) {}

  void beginPath() override;
  bool prepare(const ConnectionEnds& c) override;
  void add(const ConnectionEnds& c, double own) override;

  // Every level's target for the path traced last.
  std::span<const double> levelTargets() const { return targets_; }

 private:
  const Tempering& tempering_;
  std::vector<double> targets_;
  // The connection being prepared: levels filled (0: every level keeps the vertices' own BSDFs),
  // each level's contribution and end BSDFs (none: the vertex's own), and whether it is the path's own.
  int levels_ = 0;
  std::vector<Color> value_;
  std::vector<uint8_t> own_;
  std::vector<std::optional<Bsdf>> atLight_, atCamera_;
};

}  // namespace relt
