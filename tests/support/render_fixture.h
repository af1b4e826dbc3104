#pragma once
// One in-process fixture through which every integrator test renders: load a scene, render it
// with given settings on this process alone through the executable's own code (the registry's
// integrator, runRender's outputs, a LocalJob), return the image (pixel values).
#include <string>
#include <vector>

#include "image/image.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace relt::test {

Image renderInProcess(const std::string& scene, RenderSettings settings);
// The same for a scene already loaded (and possibly edited by the test).
Image renderInProcess(Scene scene, RenderSettings settings);

// scenes/ring.gltf with glossy metals (alpha 0.04 instead of mirrors): there tempering changes the
// targets a lot (alpha up to 2 at T = 2500), and connections at metal vertices exist untempered.
Scene glossyRing();

// Mean of a rectangular region [x0, x1) x [y0, y1) over all channels (luminance is not needed
// for agreement tests: every channel must agree).
double regionMean(const Image& image, int x0, int y0, int x1, int y1);

// Mean and standard error of the mean of independent estimates.
struct Estimate {
  double mean = 0.0, stderror = 0.0;
};
Estimate meanAndStandardError(const std::vector<double>& values);

}  // namespace relt::test
