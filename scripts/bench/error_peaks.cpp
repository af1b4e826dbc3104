// relt_bench_peaks REFERENCE.exr IMAGE.exr...: how much of each image's squared error sits in a few
// pixels. Per image: RMSE; the share of the squared error in its worst 0.1 % and 1 % of pixels;
// RMSE over the pixels whose reference value (mean of r, g, b) is below 3, i.e. without the
// emitters and their glints seen directly or through specular surfaces (a fixed mask, the same for
// every image); and its five worst pixels. docs/BENCHMARKS.md, "Where living-room's error sits".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.h"

namespace {

constexpr double kBrightReference = 3.0;

double pixelValue(const relt::Image& image, size_t i) {
  return (double(image.rgb[3 * i]) + image.rgb[3 * i + 1] + image.rgb[3 * i + 2]) / 3.0;
}

std::vector<double> squaredErrors(const relt::Image& image, const relt::Image& ref) {
  std::vector<double> e(size_t(ref.width) * size_t(ref.height));
  for (size_t i = 0; i < e.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(image.rgb[3 * i + c]) - ref.rgb[3 * i + c];
      e[i] += d * d / 3.0;
    }
  return e;
}

void report(const char* name, const relt::Image& image, const relt::Image& ref) {
  const std::vector<double> e = squaredErrors(image, ref);
  const size_t n = e.size();
  std::vector<size_t> worst(n);
  std::iota(worst.begin(), worst.end(), size_t(0));
  std::sort(worst.begin(), worst.end(), [&](size_t a, size_t b) { return e[a] > e[b]; });
  const double all = std::accumulate(e.begin(), e.end(), 0.0);
  auto shareOfWorst = [&](size_t count) {
    double s = 0.0;
    for (size_t k = 0; k < count; ++k) s += e[worst[k]];
    return all > 0.0 ? 100.0 * s / all : 0.0;
  };
  double dim = 0.0;
  size_t dimCount = 0;
  for (size_t i = 0; i < n; ++i)
    if (pixelValue(ref, i) < kBrightReference) dim += e[i], ++dimCount;
  std::printf("%s: rmse %.4f, worst 0.1 %% of pixels %.0f %% of the squared error, worst 1 %% %.0f %%, rmse where "
              "reference < %.0f %.4f (%zu pixels)\n",
              name, std::sqrt(all / double(n)), shareOfWorst(std::max<size_t>(n / 1000, 1)),
              shareOfWorst(std::max<size_t>(n / 100, 1)), kBrightReference,
              dimCount ? std::sqrt(dim / double(dimCount)) : 0.0, dimCount);
  for (size_t k = 0; k < std::min<size_t>(5, n); ++k) {
    const size_t i = worst[k];
    std::printf("  (%zu, %zu): %.0f %%, image %.2f, reference %.2f\n", i % size_t(ref.width), i / size_t(ref.width),
                all > 0.0 ? 100.0 * e[i] / all : 0.0, pixelValue(image, i), pixelValue(ref, i));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: relt_bench_peaks REFERENCE.exr IMAGE.exr...\n");
    return 2;
  }
  try {
    const relt::Image ref = relt::readExr(argv[1]);
    for (int k = 2; k < argc; ++k) {
      const relt::Image image = relt::readExr(argv[k]);
      if (image.width != ref.width || image.height != ref.height)
        throw std::runtime_error(std::string(argv[k]) + ": size differs from the reference's");
      report(argv[k], image, ref);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "relt_bench_peaks: %s\n", e.what());
    return 2;
  }
  return 0;
}
