#pragma once
// Pure decisions of the independent-sample render loop: which rank renders which unit of work,
// and when a timed render stops. The MPI layer feeds them gathered values, so every rank takes
// the same decision.
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

// "42.0%  3.1 s elapsed  ETA 4.2 s  1.23 M samples/s"
std::string progressLine(double fraction, double elapsedSeconds, double samplesPerSecond,
                         const char* unit = "samples");

}  // namespace relt
