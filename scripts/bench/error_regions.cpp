// relt_bench_regions REFERENCE.exr LAYERED.exr IMAGE.exr...: where each image's squared error sits.
// LAYERED is a relt render with --per-level (kitaoka): a pixel is an "L0 pixel" when the specific
// level's layer (level0) makes over half its value. Per image: RMSE, RMSE in the L0 pixels and
// their share of the squared error, RMSE elsewhere, and the share of the pixels where the
// reference's luminance is 3 or more (an emitter seen directly or its outline).
// docs/BENCHMARKS.md, "Against converged references".
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.h"

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: relt_bench_regions REFERENCE.exr LAYERED.exr IMAGE.exr...\n");
    return 2;
  }
  try {
    const relt::Image ref = relt::readExr(argv[1]), total = relt::readExr(argv[2]),
                      specific = relt::readExr(argv[2], "level0");
    const size_t n = size_t(ref.width) * size_t(ref.height);
    std::vector<char> l0(n), emitter(n);
    size_t l0Count = 0;
    for (size_t i = 0; i < n; ++i) {
      double t = 0, s = 0, r = 0;
      for (int c = 0; c < 3; ++c) t += total.rgb[3 * i + c], s += specific.rgb[3 * i + c], r += ref.rgb[3 * i + c];
      l0[i] = t > 0 && s / t > 0.5;
      emitter[i] = r / 3 >= 3.0;
      l0Count += size_t(l0[i]);
    }
    std::printf("L0 pixels: %zu of %zu\n", l0Count, n);
    for (int k = 3; k < argc; ++k) {
      const relt::Image a = relt::readExr(argv[k]);
      if (a.width != ref.width || a.height != ref.height) throw std::runtime_error(std::string(argv[k]) + ": size differs");
      double inL0 = 0, rest = 0, atEmitter = 0;
      for (size_t i = 0; i < n; ++i) {
        double e = 0;
        for (int c = 0; c < 3; ++c) {
          const double d = double(a.rgb[3 * i + c]) - ref.rgb[3 * i + c];
          e += d * d / 3;
        }
        (l0[i] ? inL0 : rest) += e;
        if (emitter[i]) atEmitter += e;
      }
      const double all = inL0 + rest;
      std::printf("%s: rmse %.4f, L0 pixels %.4f (%.0f %% of the squared error), elsewhere %.4f, emitter pixels %.0f %%\n",
                  argv[k], std::sqrt(all / double(n)), l0Count ? std::sqrt(inL0 / double(l0Count)) : 0.0,
                  all > 0 ? 100 * inL0 / all : 0.0, n > l0Count ? std::sqrt(rest / double(n - l0Count)) : 0.0,
                  all > 0 ? 100 * atEmitter / all : 0.0);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "relt_bench_regions: %s\n", e.what());
    return 2;
  }
  return 0;
}
