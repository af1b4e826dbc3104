#pragma once
// PCG32 random streams. Every random decision in relt draws from a stream whose seed is a hash
// of (user seed, purpose, index...), so results do not depend on which rank does the work.
#include <cstdint>

namespace relt {

// SplitMix64 finaliser: a good 64-bit mixing function for deriving stream seeds.
inline uint64_t mix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
inline uint64_t hashKey(uint64_t a, uint64_t b) { return mix64(a ^ mix64(b)); }
inline uint64_t hashKey(uint64_t a, uint64_t b, uint64_t c) { return hashKey(hashKey(a, b), c); }
inline uint64_t hashKey(uint64_t a, uint64_t b, uint64_t c, uint64_t d) { return hashKey(hashKey(a, b, c), d); }

class Rng {
 public:
  Rng() { seed(0, 0); }
  explicit Rng(uint64_t key, uint64_t stream = 0) { seed(key, stream); }

  // The starting state comes from key and stream together. Two PCG sequences whose states differ
  // by the same amount for every key are correlated whatever their increments: with the state from
  // the key alone, the first numbers of streams 0 and 1 over 2^20 keys fell in a 16 x 16 grid with a
  // chi-square of 95355 (255 degrees of freedom; tests/unit/core_rng_test.cpp), and pt's film
  // position steered its light sample.
  void seed(uint64_t key, uint64_t stream) {
    state_ = 0;
    inc_ = (mix64(stream) << 1u) | 1u;
    nextU32();
    state_ += hashKey(key, stream);
    nextU32();
  }
  uint32_t nextU32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }
  // Uniform in [0, 1): 24 random mantissa bits, never returns 1.
  float uniform() { return static_cast<float>(nextU32() >> 8) * 0x1p-24f; }
  double uniformDouble() {
    const uint64_t hi = nextU32(), lo = nextU32();
    return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1p-53;
  }
  // Uniform integer in [0, n).
  uint32_t below(uint32_t n) { return static_cast<uint32_t>((static_cast<uint64_t>(nextU32()) * n) >> 32); }

  uint64_t state() const { return state_; }
  uint64_t increment() const { return inc_; }
  void restore(uint64_t state, uint64_t inc) { state_ = state; inc_ = inc; }

 private:
  uint64_t state_ = 0, inc_ = 1;
};

}  // namespace relt
