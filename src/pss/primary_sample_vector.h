#pragma once
// A lazy point u of primary sample space, one coordinate list per stream (camera, light,
// connection), mutated by Kelemen small and large steps (DESIGN §3.2, thesis digest §2.8).
//
// Coordinates are materialised on first use in an iteration. Each remembers the iteration that
// last set it; a coordinate untouched since before the last large step is redrawn uniformly, and
// one that missed some small steps catches up by applying them (up to 8 one by one, more as one
// normal step of the same variance), so its spread is what mutating it every iteration would give. Values changed in an
// iteration are backed up, so a rejected proposal restores the previous state exactly.
#include <array>
#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "core/sample_source.h"
#include "pss/kelemen.h"

namespace relt {

class PrimarySampleVector final : public SampleSource {
 public:
  // `key` seeds the vector's own random numbers (fresh values and mutation steps).
  explicit PrimarySampleVector(uint64_t key, KelemenSizes sizes = {});

  // Starts the next proposal: a large step (every coordinate fresh) or a small step.
  void startIteration(bool largeStep);
  // Small-step sizes from now on (a replica chain changes them with its level). Coordinates that
  // missed steps catch up with the new sizes: still a symmetric move.
  void setSizes(const KelemenSizes& sizes) {
    sizes_ = sizes;
    step_ = KelemenStep(sizes);
  }
  // Keeps the proposal as the new state.
  void accept();
  // Restores the state before the proposal, exactly.
  void reject();

  float next(SampleStream stream) override;

  // The current state of a stream's coordinates that exist so far (tests, exchange, checkpoints).
  struct Coordinate {
    float value = 0.0f;
    uint64_t modified = 0;  // iteration that last set the value
  };
  const std::vector<Coordinate>& coordinates(SampleStream stream) const {
    return streams_[static_cast<int>(stream)].coords;
  }
  uint64_t iteration() const { return iteration_; }
  uint64_t lastLargeStep() const { return lastLargeStep_; }

  // Serialised form: everything needed to continue the chain bit for bit.
  std::vector<uint64_t> serialize() const;
  static PrimarySampleVector deserialize(const std::vector<uint64_t>& data);

  // Makes the current state equal to the values an independent sampler produced (e.g. a bootstrap
  // sample regenerated from (seed, index)): iteration 0 is a large step that set them.
  void setState(SampleStream stream, const std::vector<float>& values);

 private:
  struct Stream {
    std::vector<Coordinate> coords;
    size_t cursor = 0;
  };
  struct Backup {
    uint8_t stream;
    uint32_t index;
    Coordinate old;
  };

  void materialise(Coordinate& c);
  static constexpr uint64_t kNeverSet = ~0ull;  // backup marker: the coordinate did not exist
  static constexpr uint64_t kExactSteps = 8;     // missed small steps applied one by one

  std::array<Stream, kSampleStreamCount> streams_;
  std::vector<Backup> backup_;
  Rng rng_;
  KelemenSizes sizes_;
  KelemenStep step_;
  uint64_t iteration_ = 0, lastLargeStep_ = 0, previousLargeStep_ = 0;
  bool largeStep_ = true;
};

}  // namespace relt
