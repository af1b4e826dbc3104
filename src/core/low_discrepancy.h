#pragma once
// A (0,2)-sequence in base 2 (the first two Sobol dimensions) under a random digital shift. Its
// first 2^m points put one point in every elementary interval of area 2^-m (each grid of 2^a x
// 2^(m-a) cells), so an axis-aligned edge through a pixel is resolved to 2^-m of its area, where
// an n x n jittered grid of the same count leaves n cells in doubt. XOR with a random shift keeps
// that property and makes every point uniform on [0, 1)^2, so estimates stay unbiased.
#include <array>
#include <cstdint>

#include "core/math.h"

namespace relt {

inline uint32_t reverseBits(uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

// Point i as 32-bit binary fractions: van der Corput, and Sobol's second dimension (its generator
// matrix is Pascal's triangle mod 2: column k is the previous one XOR itself shifted by one).
inline std::array<uint32_t, 2> sobol02(uint32_t i) {
  uint32_t y = 0;
  for (uint32_t bits = i, column = 1u << 31; bits; bits >>= 1, column ^= column >> 1)
    if (bits & 1u) y ^= column;
  return {reverseBits(i), y};
}

// Point i shifted by (sx, sy), in [0, 1)^2 (24 bits, as Rng::uniform).
inline Vec2 shiftedSobol02(uint32_t i, uint32_t sx, uint32_t sy) {
  const std::array<uint32_t, 2> p = sobol02(i);
  return Vec2(static_cast<float>((p[0] ^ sx) >> 8) * 0x1p-24f, static_cast<float>((p[1] ^ sy) >> 8) * 0x1p-24f);
}

}  // namespace relt
