// libFuzzer harness for the scene loader: the input is a .glb (when it starts with "glTF") or a
// .gltf file. It is loaded and, when the loader accepts it, turned into a renderable scene (ray
// tracer, light sampler, camera) at a small resolution and one row is rendered with bdpt, the
// integrator that touches every part of the scene. Anything but a clean InputError (a crash, a
// sanitizer report, another exception, a non-finite sample being splatted) is a finding.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "film/film.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

namespace {

std::filesystem::path workDir() {
  static const std::filesystem::path dir = [] {
    const char* shm = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp";
    auto d = std::filesystem::path(shm) / ("relt-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool glb = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  const std::filesystem::path file = workDir() / (glb ? "input.glb" : "input.gltf");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    relt::Scene scene = relt::loadGltf(file.string());
    relt::RenderSettings settings;
    settings.width = 8;
    settings.height = 8;
    settings.maxDepth = 4;
    relt::Renderer renderer(std::move(scene), settings);
    relt::Film film(settings.width, settings.height);
    renderer.renderRow(relt::RowEstimator::Bidirectional, 0, 3, film);
    for (double v : film.data())
      if (!std::isfinite(v)) std::abort();  // non-finite samples must be dropped, never splatted
  } catch (const relt::InputError&) {
    // The expected outcome for a bad file.
  }
  return 0;
}
