#pragma once
// Values as 64-bit words and back: the form in which chain states move between ranks and go into
// checkpoints. Doubles keep their exact bits.
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace relt {

class WordWriter {
 public:
  void u64(uint64_t v) { words_.push_back(v); }
  void f64(double v) { words_.push_back(std::bit_cast<uint64_t>(v)); }
  void f64s(const std::vector<double>& v) {
    words_.reserve(words_.size() + v.size());
    for (double x : v) f64(x);
  }
  // Room for `n` words, to be filled in place (a reduction into a checkpoint's words).
  uint64_t* slots(size_t n) {
    words_.resize(words_.size() + n);
    return words_.data() + words_.size() - n;
  }
  void reserve(size_t n) { words_.reserve(n); }
  // A length, then the words.
  void block(const std::vector<uint64_t>& v) {
    u64(v.size());
    words_.insert(words_.end(), v.begin(), v.end());
  }
  std::vector<uint64_t>& words() { return words_; }

 private:
  std::vector<uint64_t> words_;
};

// Reads what a WordWriter wrote; throws std::runtime_error when the words run out.
class WordReader {
 public:
  explicit WordReader(const std::vector<uint64_t>& words, size_t at = 0) : words_(words), at_(at) {}
  uint64_t u64() {
    need(1);
    return words_[at_++];
  }
  double f64() { return std::bit_cast<double>(u64()); }
  std::vector<double> f64s(size_t n) {
    need(n);
    std::vector<double> v(n);
    for (double& x : v) x = f64();
    return v;
  }
  std::vector<uint64_t> block() {
    const uint64_t n = u64();
    need(n);
    std::vector<uint64_t> v(words_.begin() + long(at_), words_.begin() + long(at_ + n));
    at_ += n;
    return v;
  }
  bool done() const { return at_ == words_.size(); }

 private:
  void need(uint64_t n) const {
    if (n > words_.size() - at_) throw std::runtime_error("truncated state");
  }
  const std::vector<uint64_t>& words_;
  size_t at_;
};

}  // namespace relt
