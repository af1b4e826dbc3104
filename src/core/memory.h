#pragma once
// Memory sizes for limits on absurd inputs: a scene or image that cannot fit is refused with a
// clear message before anything large is allocated.
#include <cstdint>
#include <string>

namespace relt {

// Physical memory of this machine in bytes (0 if unknown).
uint64_t physicalMemoryBytes();
// The most resident memory this process has held so far, in bytes (0 if unknown).
uint64_t peakResidentBytes();
// "12.3 GiB"
std::string formatGiB(double bytes);

// Bytes a triangle costs once loaded: positions and normals of three vertices at worst, the
// triangle record, the ray tracer's per-triangle data and Embree's buffers and BVH.
inline constexpr uint64_t kBytesPerTriangle = 256;
// Allowed share of physical memory for one rank's scene or film.
inline constexpr double kMemoryShare = 0.75;
// Whether `bytes` fit in that share of `memory` (an unknown memory, 0, fits everything).
inline bool fitsInMemory(double bytes, uint64_t memory) { return memory == 0 || bytes <= kMemoryShare * double(memory); }

}  // namespace relt
