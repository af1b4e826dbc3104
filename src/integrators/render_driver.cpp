#include "integrators/render_driver.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <optional>

#include "checkpoint/checkpoint.h"
#include "core/error.h"
#include "integrators/registry.h"
#include "scene/gltf_loader.h"
#include "scene/scene_summary.h"

namespace relt {
namespace {

// Fails before any work if an output cannot be created (checked on the root, shared with all).
void checkOutputsWritable(Job& job, const RenderSettings& s) {
  std::string problem;
  if (job.isRoot()) {
    for (const std::string& path : {s.output, s.png, s.stats, s.trace}) {
      if (path.empty()) continue;
      const std::filesystem::path dir = std::filesystem::path(path).parent_path();
      const std::string d = dir.empty() ? "." : dir.string();
      if (!std::filesystem::is_directory(d)) {
        problem = path + ": output directory '" + d + "' does not exist";
        break;
      }
      if (::access(d.c_str(), W_OK) != 0) {
        problem = path + ": output directory '" + d + "' is not writable";
        break;
      }
    }
  }
  job.shareRootProblem(problem);
}

// The checkpoint folder is made if missing and must be writable; the one to resume from must
// hold a checkpoint (read and checked later). Before any work, on the root, shared with all.
void checkCheckpointFolders(Job& job, const CheckpointPlan& plan) {
  std::string problem;
  if (job.isRoot()) {
    std::error_code error;
    if (!plan.dir.empty()) {
      std::filesystem::create_directories(plan.dir, error);
      if (error || !std::filesystem::is_directory(plan.dir))
        problem = plan.dir + ": cannot make the checkpoint folder" + (error ? ": " + error.message() : "");
      else if (::access(plan.dir.c_str(), W_OK) != 0)
        problem = plan.dir + ": the checkpoint folder is not writable";
    }
    if (problem.empty() && !plan.resume.empty() && !std::filesystem::exists(checkpointFile(plan.resume)))
      problem = plan.resume + ": no checkpoint to resume (" + checkpointFile(plan.resume) + " does not exist)";
  }
  job.shareRootProblem(problem);
}

}  // namespace

void runRender(Job& job, const RenderSettings& settings, const CheckpointPlan& plan) {
  const auto wallStart = Clock::now();
  renderScene(job, loadGltf(settings.scenePath), settings, plan, wallStart);
}

void renderScene(Job& job, Scene scene, RenderSettings settings, CheckpointPlan plan, Clock::time_point wallStart) {
  const IntegratorEntry* integrator = findIntegrator(settings.integrator.name);
  if (!integrator) throw InputError("", "--integrator", "no integrator named '" + settings.integrator.name + "'");
  Renderer renderer(std::move(scene), settings);
  settings = renderer.settings();
  if (job.isRoot())
    for (const std::string& w : renderer.scene().warnings) std::fprintf(stderr, "relt: warning: %s\n", w.c_str());
  checkOutputsWritable(job, settings);
  checkCheckpointFolders(job, plan);
  // Only the root reads and writes checkpoints; the digest reads the scene file again.
  if (job.isRoot() && (!plan.dir.empty() || !plan.resume.empty())) {
    plan.identity = imageIdentity(settings, sceneDigest(settings.scenePath, summarizeScene(renderer.scene())));
    plan.settings = settings.toJson();
  }
  std::optional<Resumed> resumed;
  if (!plan.resume.empty()) resumed = loadCheckpoint(job, plan, settings.integrator.name.c_str());
  RenderContext context{job, renderer, settings, plan, resumed, wallStart};
  integrator->render(context);
}

}  // namespace relt
