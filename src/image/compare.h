#pragma once
// Image differences for convergence studies (`relt compare`, benchmarks): root-mean-square error,
// relative MSE and the signed difference image.
#include <string>
#include <vector>

#include "image/image.h"

namespace relt {

struct ImageComparison {
  double rmse = 0.0;    // sqrt(mean over pixels and channels of (a - b)^2)
  double relMse = 0.0;  // mean of (a - b)^2 / (b^2 + 0.01), b the reference (as in many papers)
  double meanA = 0.0, meanB = 0.0;
};

// b is the reference. Throws InputError when the sizes differ (naming both).
ImageComparison compareImages(const Image& a, const Image& b, const std::string& nameA = "A",
                              const std::string& nameB = "B");
// a - b per pixel and channel.
Image signedDifference(const Image& a, const Image& b);
// The pixel-by-pixel mean of independent renders of one scene (`relt average`): their errors
// average out like one render of their total time. With weights (one per image, positive; empty:
// equal) the mean is weighted, e.g. by render time, so renders of unequal work combine as one
// render of their total. Throws InputError naming an image whose size differs from the first's,
// or when the weights do not fit the images.
Image averageImages(const std::vector<Image>& images, const std::vector<std::string>& names,
                    const std::vector<double>& weights = {});

}  // namespace relt
