#include "meb/meb_cameras.h"

#include <cmath>

#include "camera/film_position.h"
#include "core/low_discrepancy.h"
#include "core/rng.h"
#include "parallel/workers.h"

namespace relt {
namespace {

constexpr uint64_t kCameraPathPurpose = 0x3eb1, kPixelShiftPurpose = 0x3eb2;

}  // namespace

MebCameras::MebCameras(int width, int height, int workers)
    : width_(width),
      height_(height),
      workers_(std::max(workers, 1)),
      workerVertices_(size_t(workers_)),
      workerDeferred_(size_t(workers_)),
      paths_(size_t(width) * size_t(height)),
      films_(size_t(width) * size_t(height)) {}

// Rows dealt to the workers in turn, each worker's vertices in a block of its own; the blocks are
// then indexed by pixel (not copied).
void MebCameras::trace(const VcmTracer& tracer, uint64_t seed, uint64_t iteration, float radius) {
  std::vector<std::vector<uint32_t>> starts(static_cast<size_t>(workers_));
  runOnWorkers(workers_, [&](int w) {
    std::vector<CameraVertex>& mine = workerVertices_[size_t(w)];
    std::vector<DeferredSplat>& deferred = workerDeferred_[size_t(w)];
    mine.clear();
    deferred.clear();
    for (int row = w; row < height_; row += workers_)
      for (int x = 0; x < width_; ++x) {
        const uint32_t pixel = uint32_t(row) * uint32_t(width_) + uint32_t(x);
        starts[size_t(w)].push_back(uint32_t(mine.size()));
        IndependentSource u(hashKey(seed, kCameraPathPurpose, iteration, pixel));
        Rng shift(hashKey(seed, kPixelShiftPurpose, pixel));
        const uint32_t sx = shift.nextU32(), sy = shift.nextU32();
        const Vec2 film = positionInPixel(x, row, shiftedSobol02(uint32_t(iteration), sx, sy));
        films_[pixel] = film;
        const auto onEmitter = [&](const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo, const Color& le) {
          const CameraTechniqueWeight weight = tracer.mis().emissionWeightParts(s, hit, wo);
          if (weight.possible) deferred.push_back({film, s.beta * le, weight, s.specular ? PathClass::L0 : PathClass::L1});
        };
        const auto onSurface = [&](const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo, const Bsdf& bsdf) {
          const WeightedLater nee = tracer.nextEventLater(s, hit, wo, bsdf, u);
          if (nee.weight.possible && !isBlack(nee.value)) deferred.push_back({film, nee.value, nee.weight, PathClass::L2});
          mine.push_back(CameraVertex{hit, wo, s, pixel});
          return true;
        };
        tracer.walkCamera(film, u, onEmitter, onSurface);
      }
  });
  for (int w = 0; w < workers_; ++w) {
    const std::vector<CameraVertex>& block = workerVertices_[size_t(w)];
    const std::vector<uint32_t>& start = starts[size_t(w)];
    size_t j = 0;
    for (int row = w; row < height_; row += workers_)
      for (int x = 0; x < width_; ++x, ++j) {
        const size_t end = j + 1 < start.size() ? start[j + 1] : block.size();
        paths_[size_t(row) * size_t(width_) + size_t(x)] = std::span<const CameraVertex>(block.data() + start[j], end - start[j]);
      }
  }
  // In pixel order, not the workers': the grid then lists neighbours in the same order on any
  // split, so a light subpath's merges add up the same and the chains take the same decisions.
  std::vector<const CameraVertex*> inPixelOrder;
  for (const std::span<const CameraVertex>& path : paths_)
    for (const CameraVertex& v : path) inPixelOrder.push_back(&v);
  positions_.resize(inPixelOrder.size());
  for (size_t i = 0; i < inPixelOrder.size(); ++i) positions_[i] = inPixelOrder[i]->sp.p;
  grid_.build(positions_, radius);
  grid_.gatherBySlot<CameraVertex>(inPixelOrder, bySlot_);
}

void MebCameras::splatOwnTechniques(float kappaTerm, std::span<Film> films) const {
  runOnWorkers(workers_, [&](int w) {
    for (const DeferredSplat& d : workerDeferred_[size_t(w)]) {
      const double weight = double(d.weight.weight(kappaTerm));
      if (isFinite(d.value) && std::isfinite(weight)) films[size_t(w)].addSplat(d.film, d.value, weight);
      else films[size_t(w)].addDropped(1);  // a bad number is counted, never splatted
    }
  });
}

}  // namespace relt
