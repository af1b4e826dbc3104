// relt: the distributed renderer's entry point. Every run initialises MPI; a plain run is one rank.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>

#include "comm.h"
#include "interrupt.h"
#include "mpi_job.h"
#include "core/error.h"
#include "image/compare.h"
#include "image/image.h"
#include "parallel/workers.h"
#include "schedule/schedule.h"
#include "integrators/render_driver.h"
#include "integrators/option_checks.h"
#include "integrators/registry.h"
#include "scene/gltf_loader.h"
#include "scene/scene_summary.h"

namespace {

constexpr int kExitInput = 2;
constexpr int kExitInternal = 1;

const CLI::Validator kPositive = relt::positiveNumber();

// The registry's integrators: their names, and "pt (path tracing ...), bdpt (...)" for --help.
std::vector<std::string> integratorNames() {
  std::vector<std::string> names;
  for (const relt::IntegratorEntry* entry : relt::integrators()) names.push_back(entry->kind.name);
  return names;
}

std::string integratorList() {
  std::string list;
  for (const relt::IntegratorEntry* entry : relt::integrators())
    list += (list.empty() ? "" : ", ") + entry->kind.name + " (" + entry->summary + ")";
  return list;
}

// An unsigned 64-bit integer in decimal (CLI11 takes -1 as 2^64 - 1 and clamps what is larger).
const CLI::Validator kUnsigned64(
    [](std::string& text) {
      const bool digits = !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
      try {
        if (digits) (void)std::stoull(text);
      } catch (const std::exception&) {
        return "must be an integer in [0, 2^64 - 1], got " + text;
      }
      return digits ? std::string() : "must be an integer in [0, 2^64 - 1], got " + text;
    },
    "0 .. 2^64 - 1");

// The word after `relt`, if it is no subcommand (CLI11 would only say one is required).
std::string unknownSubcommand(int argc, char** argv, const CLI::App& app) {
  if (argc < 2 || argv[1][0] == '-') return "";
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == argv[1]) return "";
  return argv[1];
}

struct Options {
  relt::RenderSettings render;
  relt::SettingsDrafts drafts;  // every integrator's own settings until one is chosen
  std::string integrator = relt::kDefaultIntegrator;
  CLI::App* renderCommand = nullptr;
  std::string infoScene;
  std::string compareA, compareB, compareDiff, comparePng;
  std::vector<std::string> averageInputs;
  std::string averageOutput, averagePng;
  std::vector<double> averageWeights;
  double stallTimeout = 120.0;
  CLI::Option* threads = nullptr;
  // The render options given on the command line, by long name.
  relt::GivenOptions given() const {
    relt::GivenOptions names;
    for (const CLI::Option* opt : renderCommand->get_options())
      if (opt->count() > 0) names.push_back(opt->get_name());
    return names;
  }
  relt::CheckpointPlan checkpoint;
};

void addRenderOptions(CLI::App& cmd, Options& o) {
  relt::RenderSettings& r = o.render;
  cmd.add_option("scene", r.scenePath, "glTF 2.0 scene (.gltf or .glb)")->required();
  cmd.add_option("-o,--output", r.output, "output image: .exr (OpenEXR, float RGB, with metadata) or .png (sRGB)")->required();
  cmd.add_option("--png", r.png, "also write an sRGB PNG preview");
  cmd.add_option("--stats", r.stats, "write settings and statistics as JSON");
  cmd.add_option("--integrator", o.integrator, "light transport algorithm: " + integratorList())
      ->check(CLI::IsMember(integratorNames()))
      ->capture_default_str();
  CLI::Option* time = cmd.add_option("--time", r.seconds, "render for this many seconds (decided collectively)")
                          ->check(kPositive);
  relt::addIntegratorOptions(cmd, r, o.drafts);
  CLI::Option* spp = cmd.get_option("--spp");
  CLI::Option* mpp = cmd.get_option("--mutations-per-pixel");
  spp->excludes(time);
  mpp->excludes(spp);
  mpp->excludes(time);
  cmd.add_option("--snapshot-every", r.snapshotEvery,
                 "write the image so far (atomically) every this many seconds")
      ->check(kPositive);
  cmd.add_option("--width", r.width, "image width (default: scene extras, else 256)")->check(CLI::Range(1, relt::kMaxImageSide));
  cmd.add_option("--height", r.height, "image height (default: scene extras, else 256)")->check(CLI::Range(1, relt::kMaxImageSide));
  cmd.add_option("--max-depth", r.maxDepth, "maximum path segments (default: scene extras, else 8)")
      ->check(CLI::Range(1, relt::kMaxDepth));
  cmd.add_option("--seed", r.seed, "random seed; with the other settings it fixes the image (not the rank or thread count)")
      ->check(kUnsigned64)
      ->capture_default_str();
  o.threads = cmd.add_option("--threads", r.threads,
                             "worker threads per rank (default: the cores the rank may use, shared "
                             "with the node's other ranks unless mpirun binds them); the image does not depend on it")
                  ->check(CLI::Range(1, relt::kMaxWorkers));
  cmd.add_option("--camera", r.camera, "camera name (default: the first perspective camera)");
  cmd.add_option("--exposure", r.exposure, "PNG exposure in stops")->check(relt::finiteIn(-64.0, 64.0))->capture_default_str();
  cmd.add_option("--stall-timeout", o.stallTimeout,
                 "end the job with an error when a rank waits this many seconds for the others (0: never)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  auto* checkpoint = cmd.add_option("--checkpoint", o.checkpoint.dir,
                                    "write a checkpoint into this folder (made if missing) when the "
                                    "render ends or is stopped, and every --checkpoint-every seconds");
  cmd.add_option("--checkpoint-every", o.checkpoint.every, "seconds between checkpoints (0: only at the end)")
      ->check(CLI::Range(0.0, 1e9))
      ->needs(checkpoint)
      ->capture_default_str();
  cmd.add_option("--resume", o.checkpoint.resume,
                 "continue the render of this checkpoint folder (same scene and settings; the budget is the total)");
  cmd.add_option_function<std::string>(
         "--mis", [&r](const std::string& v) { r.heuristic = *relt::parseMisHeuristic(v); }, "MIS heuristic")
      ->check(CLI::IsMember({"power", "balance"}))
      ->default_str(relt::misHeuristicName(r.heuristic));
}

// The image format follows -o's extension; --png is a PNG.
void checkOutputNames(const relt::RenderSettings& r) {
  const std::optional<relt::ImageFormat> format = relt::imageFormatOf(r.output);
  if (!format) throw relt::InputError(r.output, "", "unknown image format: name the output .exr or .png");
  if (!r.png.empty() && relt::imageFormatOf(r.png) != relt::ImageFormat::Png)
    throw relt::InputError(r.png, "--png", "a PNG preview's name ends in .png");
}

// An output of compare or average must be named for the one format it is written in.
void checkNamedAs(const std::string& path, const char* option, relt::ImageFormat format) {
  if (path.empty() || relt::imageFormatOf(path) == format) return;
  throw relt::InputError(path, option, format == relt::ImageFormat::Exr ? "written as OpenEXR: name it .exr"
                                                                         : "written as PNG: name it .png");
}

// relt compare: the figures as JSON on stdout, the signed difference and its magnitude if asked.
int runCompare(const Options& o, bool root) {
  checkNamedAs(o.compareDiff, "--diff", relt::ImageFormat::Exr);
  checkNamedAs(o.comparePng, "--png", relt::ImageFormat::Png);
  const relt::Image a = relt::readExr(o.compareA), b = relt::readExr(o.compareB);
  const relt::ImageComparison c = relt::compareImages(a, b, o.compareA, o.compareB);
  if (!root) return 0;
  std::printf("{\"rmse\": %.9g, \"rel_mse\": %.9g, \"mean\": %.9g, \"reference_mean\": %.9g}\n", c.rmse, c.relMse,
              c.meanA, c.meanB);
  const relt::Image d = relt::signedDifference(a, b);
  if (!o.compareDiff.empty()) relt::writeExr(o.compareDiff, d);
  if (!o.comparePng.empty()) {
    relt::Image magnitude = d;
    for (float& v : magnitude.rgb) v = std::abs(v);
    relt::writePng(o.comparePng, magnitude, 3.0f);
  }
  return 0;
}

// relt average: the pixel-by-pixel mean of the inputs, weighted if asked.
int runAverage(const Options& o, bool root) {
  checkNamedAs(o.averageOutput, "--output", relt::ImageFormat::Exr);
  checkNamedAs(o.averagePng, "--png", relt::ImageFormat::Png);
  std::vector<relt::Image> images;
  for (const std::string& path : o.averageInputs) images.push_back(relt::readExr(path));
  const relt::Image mean = relt::averageImages(images, o.averageInputs, o.averageWeights);
  if (root) {
    relt::writeExr(o.averageOutput, mean);
    if (!o.averagePng.empty()) relt::writePng(o.averagePng, mean, 0.0f);
  }
  return 0;
}

// relt info: the summary; a valid file that cannot be rendered is still exit 2.
int runInfo(const Options& o, bool root) {
  const relt::Scene scene = relt::loadGltf(o.infoScene);
  if (root) std::cout << relt::summarizeScene(scene) << std::flush;
  relt::checkRenderable(scene);
  return 0;
}

// The integrator named by --integrator; an option it does not use is refused.
void checkRenderOptions(Options& o) {
  relt::selectIntegrator(o.render, o.integrator, &o.drafts);
  relt::validateIntegratorOptions(o.render, o.given());
}

// --threads on auto; collective, as ranks on a node are counted.
int threadsOnAuto() {
  const int ranksOnNode = relt::mpi::ranksOnThisNode();
  return relt::defaultThreads(relt::coresAvailable(), relt::coresOnline(), ranksOnNode);
}

}  // namespace

int main(int argc, char** argv) {
  relt::mpi::Session session(&argc, &argv);
  relt::mpi::installStopHandlers();
  const bool root = session.isRoot();

  CLI::App app{"relt: replica-exchange light transport renderer (glTF 2.0 in, OpenEXR or PNG out), distributed with MPI.\n"
               "Run under mpirun for several ranks; a plain run is one rank with a thread per core it may use."};
  app.require_subcommand(1);
  Options o;
  CLI::App* render = app.add_subcommand("render", "render a scene");
  o.renderCommand = render;
  addRenderOptions(*render, o);
  CLI::App* info = app.add_subcommand("info", "validate and summarise a scene");
  info->add_option("scene", o.infoScene, "glTF 2.0 scene")->required();
  CLI::App* compare = app.add_subcommand("compare", "compare an image with a reference: RMSE, relative MSE, means");
  compare->add_option("image", o.compareA, "image to assess (OpenEXR)")->required();
  compare->add_option("reference", o.compareB, "reference image (OpenEXR)")->required();
  compare->add_option("--diff", o.compareDiff, "write the signed difference image - reference (OpenEXR)");
  compare->add_option("--png", o.comparePng, "write |difference| as a PNG (exposure +3)");
  CLI::App* average =
      app.add_subcommand("average", "pixel-by-pixel mean of independent renders of one scene (e.g. from separate jobs)");
  average->add_option("images", o.averageInputs, "renders to average (OpenEXR, same size)")->required();
  average->add_option("-o,--output", o.averageOutput, "the mean (OpenEXR)")->required();
  average->add_option("--png", o.averagePng, "also write an sRGB PNG preview");
  average->add_option("--weights", o.averageWeights,
                      "one positive weight per image, e.g. its render time (default: equal)")
      ->delimiter(',');

  if (const std::string word = unknownSubcommand(argc, argv, app); !word.empty()) {
    if (root) std::fprintf(stderr, "relt: error: unknown command '%s': expected render, info, compare or average (see relt --help)\n", word.c_str());
    return kExitInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    if (root) std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp& e) {
    if (root) std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    if (root) std::fprintf(stderr, "relt: error: %s (see relt --help)\n", e.what());
    return kExitInput;
  }

  try {
    if (*compare) return runCompare(o, root);
    if (*average) return runAverage(o, root);
    if (*info) return runInfo(o, root);
    checkRenderOptions(o);
    checkOutputNames(o.render);
    if (o.threads->count() == 0) o.render.threads = threadsOnAuto();
    relt::mpi::startStallWatchdog(o.stallTimeout);
    relt::mpi::MpiJob job(session);
    relt::runRender(job, o.render, o.checkpoint);
    return 0;
  } catch (const relt::InputError& e) {
    if (root) std::fprintf(stderr, "relt: error: %s\n", e.what());
    return kExitInput;
  } catch (const std::exception& e) {
    // A broken invariant on one rank must not leave the others waiting in a collective.
    std::fprintf(stderr, "relt: internal error (rank %d): %s\n", session.rank(), e.what());
    MPI_Abort(MPI_COMM_WORLD, kExitInternal);
    return kExitInternal;
  }
}
