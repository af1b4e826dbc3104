#include "render_fixture.h"

#include <cmath>
#include <filesystem>

#include "integrators/render_driver.h"
#include "parallel/local_job.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

namespace relt::test {

Image renderInProcess(const std::string& scene, RenderSettings settings) {
  settings.scenePath = scene;
  return renderInProcess(loadGltf(scene), settings);
}

// Through the executable's own render (integrators/render_driver.h) on a job of one process: the
// image goes out as the executable writes it (an EXR of floats, exact) and is read back.
Image renderInProcess(Scene scene, RenderSettings settings) {
  const std::string dir = makeTempDir("render-in-process");
  settings.output = dir + "/image.exr";
  settings.png = settings.stats = settings.trace = "";
  LocalJob job;
  renderScene(job, std::move(scene), settings);
  Image image = readExr(settings.output);
  std::filesystem::remove_all(dir);
  return image;
}

Scene glossyRing() {
  Scene scene = loadGltf(sourcePath("scenes/ring.gltf"));
  for (Material& m : scene.materials)
    if (m.kind == MaterialKind::Conductor) m.alpha = 0.04f;
  return scene;
}

double regionMean(const Image& image, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) sum += image.rgb[3 * (static_cast<size_t>(y) * image.width + x) + c];
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

Estimate meanAndStandardError(const std::vector<double>& v) {
  Estimate e;
  for (double x : v) e.mean += x;
  e.mean /= static_cast<double>(v.size());
  double var = 0.0;
  for (double x : v) var += (x - e.mean) * (x - e.mean);
  var /= static_cast<double>(v.size() - 1);
  e.stderror = std::sqrt(var / static_cast<double>(v.size()));
  return e;
}

}  // namespace relt::test
