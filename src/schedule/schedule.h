#pragma once
// Pure decisions of the independent-sample render loop: which rank renders which unit of work,
// and when a timed render stops. The MPI layer feeds them gathered values, so every rank takes
// the same decision.
#include <algorithm>
#include <cstdint>
#include <string>

namespace relt {

// Units are (sample index, row); they are dealt round-robin so each pass is split over all ranks.
inline bool ownsUnit(uint64_t sampleIndex, int row, int height, int rank, int ranks) {
  return (sampleIndex * static_cast<uint64_t>(height) + static_cast<uint64_t>(row)) % static_cast<uint64_t>(ranks) ==
         static_cast<uint64_t>(rank);
}

// A timed render starts another pass only if it is expected to finish within the budget
// (elapsed and pass time are the maxima over ranks). The first pass always runs.
inline bool startAnotherPass(int passesDone, double elapsedSeconds, double lastPassSeconds, double budgetSeconds) {
  if (passesDone == 0) return true;
  return elapsedSeconds + lastPassSeconds <= budgetSeconds;
}

// Where the pass loop of pt, bdpt and erpt has got to: passes done, and the rows 0 .. rows - 1 of
// the next one (every rank's units of them) done as well.
struct PassPoint {
  int passes = 0;
  int rows = 0;
};

// A pass is taken in chunks of rows, the ranks agreeing on stop and save requests after each (a
// large image's pass takes seconds): the next chunk's rows, from the slowest rank's `seconds` for
// the last `taken`, aimed at kPassChunkSeconds and at most 4 times the last, within one pass.
constexpr double kPassChunkSeconds = 0.1;  // a stop request waits about this long in a pass
constexpr int kFirstPassChunkRows = 4;
inline int nextPassChunk(int taken, double seconds, int height) {
  const double most = 4.0 * double(std::max(taken, 1));
  const double aimed = seconds > 0.0 ? kPassChunkSeconds * double(taken) / seconds : most;
  return int(std::clamp(std::min(aimed, most), 1.0, double(std::max(height, 1))));
}

// The direct-emission pass of pssmlt and relt left on auto (--direct-emission-spp auto). Its rays
// sit at the points of a (0,2)-sequence, whose error at an emitter's outline falls faster than
// 1/N, and each costs about 1/30 of a chain mutation (one camera ray, no connections). Measured at
// 16 and 64 mutations per pixel, 2M rays per pixel did about as well as 4M and far better than M/4
// (docs/BENCHMARKS.md, "The direct-emission pass on auto"): about 6 % of the render's time.
constexpr int kDirectProbeSpp = 4;          // first rays of every pixel; none sees emission: the chains do it all
constexpr int kDirectMinSpp = 16;           // fewer left emitters' outlines noisier than the chains did
constexpr int kDirectMaxSpp = 1 << 20;      // --direct-emission-spp's ceiling
constexpr double kDirectBudgetShare = 0.06;  // a timed render's pass stays within this share of the budget
constexpr double kDirectChunkSeconds = 0.1;  // a stop request waits about this long in the pass

// The pass takes its rays in chunks of every pixel, the ranks agreeing on a stop request after
// each: the next chunk's rays per pixel, from the slowest rank's `seconds` for the last `taken`,
// aimed at kDirectChunkSeconds and at most 4 times the last (a first chunk timed too short).
inline uint32_t nextDirectChunk(uint32_t taken, double seconds) {
  const double most = 4.0 * double(std::max<uint32_t>(taken, 1));
  if (!(seconds > 0.0)) return uint32_t(std::min<double>(most, double(kDirectMaxSpp)));
  const double aimed = kDirectChunkSeconds * double(taken) / seconds;
  return uint32_t(std::clamp(std::min(aimed, most), 1.0, double(kDirectMaxSpp)));
}

// A fixed budget: the power of two nearest 2 x mutationsPerPixel, at least kDirectMinSpp.
int autoDirectSpp(double mutationsPerPixel);

// A timed render: the pass has taken passSeconds (the slowest rank) for its rays so far; it doubles
// them (the doubling costs about as much again) while that keeps it within the budget's share.
inline bool doubleDirectPass(double passSeconds, double budgetSeconds) {
  return 2.0 * passSeconds <= kDirectBudgetShare * budgetSeconds;
}

// "42.0%  3.1 s elapsed  ETA 4.2 s  1.23 M samples/s"
std::string progressLine(double fraction, double elapsedSeconds, double samplesPerSecond,
                         const char* unit = "samples");

}  // namespace relt
