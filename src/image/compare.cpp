#include "image/compare.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"

namespace relt {

ImageComparison compareImages(const Image& a, const Image& b, const std::string& nameA, const std::string& nameB) {
  if (a.width != b.width || a.height != b.height)
    throw InputError(nameA, "", "is " + std::to_string(a.width) + "x" + std::to_string(a.height) + " but " + nameB +
                                    " is " + std::to_string(b.width) + "x" + std::to_string(b.height));
  ImageComparison c;
  double se = 0.0, rel = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = double(a.rgb[i]) - double(b.rgb[i]);
    se += d * d;
    rel += d * d / (double(b.rgb[i]) * b.rgb[i] + 0.01);
  }
  const double n = a.rgb.empty() ? 1.0 : double(a.rgb.size());
  c.rmse = std::sqrt(se / n);
  c.relMse = rel / n;
  c.meanA = a.mean();
  c.meanB = b.mean();
  return c;
}

Image signedDifference(const Image& a, const Image& b) {
  Image d(a.width, a.height);
  for (size_t i = 0; i < d.rgb.size(); ++i) d.rgb[i] = a.rgb[i] - b.rgb[i];
  return d;
}

namespace {

// The weights normalised to sum to 1: equal when none are given.
std::vector<double> normalisedWeights(size_t count, const std::vector<double>& weights) {
  if (weights.empty()) return std::vector<double>(count, 1.0 / double(count));
  if (weights.size() != count)
    throw InputError("", "--weights", std::to_string(weights.size()) + " weights for " + std::to_string(count) + " images");
  double total = 0.0;
  for (double w : weights) {
    if (!(w > 0.0) || !std::isfinite(w)) throw InputError("", "--weights", "a weight must be positive and finite");
    total += w;
  }
  std::vector<double> normalised;
  for (double w : weights) normalised.push_back(w / total);
  return normalised;
}

}  // namespace

Image averageImages(const std::vector<Image>& images, const std::vector<std::string>& names,
                    const std::vector<double>& weights) {
  if (images.empty()) throw InputError("", "", "no images to average");
  const std::vector<double> w = normalisedWeights(images.size(), weights);
  const Image& first = images.front();
  std::vector<double> sum(first.rgb.size(), 0.0);
  for (size_t k = 0; k < images.size(); ++k) {
    const Image& im = images[k];
    if (im.width != first.width || im.height != first.height)
      throw InputError(k < names.size() ? names[k] : "", "",
                       "is " + std::to_string(im.width) + "x" + std::to_string(im.height) + " but " +
                           (names.empty() ? std::string("the first image") : names.front()) + " is " +
                           std::to_string(first.width) + "x" + std::to_string(first.height));
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += w[k] * double(im.rgb[i]);
  }
  Image mean(first.width, first.height);
  for (size_t i = 0; i < sum.size(); ++i) mean.rgb[i] = float(sum[i]);
  return mean;
}

}  // namespace relt
