#include "integrators/render_driver.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "checkpoint/checkpoint.h"
#include "relt_commit.h"
#include "checkpoint/checkpoint_io.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/memory.h"
#include "parallel/workers.h"
#include "render/renderer.h"
#include "integrators/direct/direct_driver.h"
#include "integrators/erpt/erpt_driver.h"
#include "integrators/passes/pass_loop.h"
#include "integrators/pssmlt/pssmlt_driver.h"
#include "integrators/relt/relt_driver.h"
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

// Pixels zeroed by writeImages over the render (snapshots and the final image).
uint64_t nonFinitePixelsZeroed = 0;

// What an EXR says of its render: the integrator, the settings, the commit, and for the final
// image (`stats` given) the samples or mutations taken and the seconds.
ImageAttributes renderAttributes(const RenderSettings& settings, const nlohmann::json& stats) {
  ImageAttributes a = {{"relt:integrator", integratorName(settings.integrator)},
                       {"relt:settings", settings.toJson().dump()},
                       {"relt:commit", RELT_COMMIT}};
  if (stats.is_null()) return a;
  for (const char* key : {"spp", "image_rows_of_the_stopped_pass", "mutations", "render_seconds", "interrupted"})
    if (stats.contains(key)) a.emplace_back(std::string("relt:") + key, stats[key].dump());
  return a;
}

// Images written against a clock are not compressed: snapshots (a save request comes a second
// before mpirun's SIGTERM) and the image of a render stopped by a signal (SIGKILL follows a second
// later); ZIP would take most of that second on a 1024x768 film.
ExrCompression exrCompressionOf(const nlohmann::json& stats) {
  return stats.is_null() || stats.value("interrupted", false) ? ExrCompression::None : ExrCompression::Zip;
}

// The image as -o names it (EXR with optional extra layers and metadata, or PNG) and the optional
// PNG, each written atomically. Root only. Every image goes out through here, so here a NaN or
// infinite pixel is written as 0, counted and reported: a safety net, the integrators must not
// make them. Returns the image as written.
Image writeImages(const RenderSettings& settings, Image image, std::vector<ImageLayer> layers = {},
                  const nlohmann::json& stats = {}) {
  uint64_t zeroed = zeroNonFinitePixels(image);
  for (ImageLayer& layer : layers) zeroed += zeroNonFinitePixels(layer.image);
  if (zeroed > 0)
    std::fprintf(stderr, "relt: warning: %llu non-finite pixels written as 0 to %s (an integrator made them)\n",
                 static_cast<unsigned long long>(zeroed), settings.output.c_str());
  nonFinitePixelsZeroed += zeroed;
  if (imageFormatOf(settings.output) == ImageFormat::Png)
    writePng(settings.output, image, settings.exposure);
  else
    writeExr(settings.output, image, layers, renderAttributes(settings, stats), exrCompressionOf(stats));
  if (!settings.png.empty()) writePng(settings.png, image, settings.exposure);
  return image;
}

// "a.exr, a.png and a.json": every file a render writes, for its closing line.
std::string filesWritten(const RenderSettings& s) {
  std::vector<std::string> files;
  for (const std::string& f : {s.output, s.png, s.stats, s.trace})
    if (!f.empty()) files.push_back(f);
  std::string out;
  for (size_t i = 0; i < files.size(); ++i) out += (i == 0 ? "" : i + 1 == files.size() ? " and " : ", ") + files[i];
  return out;
}

// The passes of pt, bdpt and erpt in stats.json: whole passes, and for a render stopped inside a
// pass the rows it did (in its checkpoint) and those its image shows (render/pass_film.h).
void addPassStats(nlohmann::json& j, PassPoint end, PassPoint shown) {
  j["spp"] = end.passes;
  if (end.rows == 0) return;
  j["rows_of_the_stopped_pass"] = end.rows;
  j["image_rows_of_the_stopped_pass"] = shown.rows;
}

// The closing line's words for a render stopped inside a pass ("" otherwise).
std::string inPassNote(PassPoint end, PassPoint shown) {
  if (end.rows == 0) return "";
  return " and " + std::to_string(end.rows) + " rows of the next" +
         (shown.rows == end.rows ? "" : " (not in the image: its samples reach rows not done)");
}

// The images and the stats (with the wall time added). Root only.
void writeOutputs(const RenderSettings& settings, const Image& image, nlohmann::json stats, Clock::time_point wallStart,
                  const std::vector<ImageLayer>& layers = {}) {
  stats["image_mean"] = writeImages(settings, image, layers, stats).mean();  // of the image as written
  stats["nonfinite_pixels_zeroed"] = nonFinitePixelsZeroed;
  if (checkpointTally().written > 0)
    stats["checkpoints"] = {{"written", checkpointTally().written}, {"seconds", checkpointTally().seconds}};
  if (stats.value("interrupted", false))
    std::fprintf(stderr, "relt: stopped early by a signal (SIGINT/SIGTERM/SIGUSR1): the image holds the work done so far\n");
  if (!settings.stats.empty()) {
    stats["wall_seconds"] = secondsSince(wallStart);
    writeFileAtomically(settings.stats, stats.dump(2) + "\n");
  }
}

// What every rank contributes once rendering ends (collective): the film summed on the root,
// counters summed, timings gathered.
struct Gathered {
  double renderSeconds = 0.0;
  uint64_t rays = 0, dropped = 0;
  std::vector<double> droppedPerRank;  // NaN/Inf samples each rank dropped
  std::vector<double> collective;
  std::vector<std::string> hosts;  // each rank's processor name
  std::vector<double> peakResident;  // each rank's most resident bytes
};

// stats.json: the pass's rays per pixel as taken (0: no emitter in view, the chains did it) and time.
void addDirectStats(nlohmann::json& j, const RenderSettings& settings, const DirectEstimate& direct) {
  if (!directEmissionApart(settings)) return;
  j["direct_emission_spp"] = direct.spp;
  j["direct_emission_seconds"] = direct.seconds;
}

// The chains' settings: a time budget less what the direct estimate took (at least a round runs).
RenderSettings chainSettings(RenderSettings s, const DirectEstimate& direct) {
  if (s.seconds) s.seconds = std::max(1e-3, *s.seconds - direct.seconds);
  return s;
}

// The chains' image plus the separately estimated directly seen emission (if any).
Image withDirect(Image image, const Image& direct) {
  if (!direct.rgb.empty()) image.add(direct);
  return image;
}

Gathered gatherAfterRender(Job& job, Clock::time_point renderStart, const Renderer& renderer, Film& film, bool reduceFilm = true) {
  Gathered g;
  g.renderSeconds = job.allreduceMax(secondsSince(renderStart));
  if (reduceFilm) job.reduceSumToRoot(film.data());
  g.rays = job.allreduceSum(renderer.rays());
  g.dropped = job.allreduceSum(film.droppedSamples());
  g.droppedPerRank = job.allgather(double(film.droppedSamples()));
  g.collective = job.allgather(job.collectiveSeconds());
  g.hosts = job.processorNames();
  g.peakResident = job.allgather(double(peakResidentBytes()));
  return g;
}

// Per-rank counts gathered as doubles, written as integers.
std::vector<uint64_t> counts(const std::vector<double>& v) { return std::vector<uint64_t>(v.begin(), v.end()); }

// The stats every integrator writes.
nlohmann::json commonStats(const RenderSettings& settings, Job& job, const Gathered& g,
                           const Image& image) {
  nlohmann::json j;
  j["settings"] = settings.toJson();
  j["ranks"] = job.size();
  j["interrupted"] = job.stopAgreed();
  j["hosts"] = g.hosts;
  j["rays"] = g.rays;
  j["render_seconds"] = g.renderSeconds;
  j["rays_per_second"] = g.rays / std::max(g.renderSeconds, 1e-9);
  j["nan_inf_samples_dropped"] = g.dropped;
  j["nan_inf_samples_dropped_per_rank"] = counts(g.droppedPerRank);
  j["collective_seconds_per_rank"] = g.collective;
  std::vector<double> mib;
  for (double bytes : g.peakResident) mib.push_back(std::round(bytes / double(1 << 20) * 10.0) / 10.0);
  j["peak_resident_mib_per_rank"] = mib;
  j["image_mean"] = image.mean();
  return j;
}

// `earlier`: mutations of the render this one resumed (in the total, not in the rates).
void addMutationRates(nlohmann::json& j, uint64_t mutations, const Gathered& g, int ranks, uint64_t earlier = 0) {
  j["mutations"] = mutations;
  const double now = double(mutations - std::min(mutations, earlier));
  j["mutations_per_second"] = now / std::max(g.renderSeconds, 1e-9);
  j["mutations_per_second_per_rank"] = now / std::max(g.renderSeconds, 1e-9) / ranks;
}

double ratio(uint64_t a, uint64_t b) { return b ? double(a) / double(b) : 0.0; }

// Replica exchange: the ladder's diagnostics go to stats.json (DESIGN §3.5).
nlohmann::json reltStats(const ReltOutcome& o) {
  nlohmann::json j;
  j["rounds"] = o.rounds;
  j["steps_per_chain"] = o.stepsPerChain;
  j["round_trips"] = o.roundTrips;
  j["round_trips_per_chain"] = double(o.roundTrips) / std::max(1, o.ladders * o.levels);
  j["bootstrap_samples"] = o.bootstrapSamples;
  j["loop_seconds"] = o.loopSeconds;
  j["round_collective_seconds_per_rank"] = o.roundCollectiveSeconds;
  j["placement"] = placementName(o.placement);
  j["chain_moves"] = o.chainMoves;
  j["chains_per_rank"] = o.chainsPerRank;
  j["groups"] = roundGroups(o.ladders);
  j["group_round_step_seconds_mean_per_rank"] = o.stepMean;
  j["group_round_step_seconds_deviation_per_rank"] = o.stepDeviation;
  j["group_round_finish_seconds_mean_per_rank"] = o.finishMean;
  nlohmann::json levels = nlohmann::json::array();
  for (int k = 0; k < o.levels; ++k) {
    const LevelCounters& c = o.perLevel[size_t(k)];
    nlohmann::json l;
    l["level"] = k;
    l["name"] = o.levelNames[size_t(k)];
    l["normaliser"] = o.normalisers[size_t(k)];
    l["mutations"] = c.smallProposed + c.largeProposed;
    l["acceptance_small"] = ratio(c.smallAccepted, c.smallProposed);
    l["acceptance_large"] = ratio(c.largeAccepted, c.largeProposed);
    l["invalid_proposals"] = c.invalidProposals;
    l["seconds"] = c.seconds;
    l["state_change_rate"] = o.tally.changeRate(k);
    if (k + 1 < o.levels) {
      const double a = o.tally.adjacentAcceptance(k);
      l["swap_acceptance_with_next"] = std::isnan(a) ? nlohmann::json(nullptr) : nlohmann::json(a);
    }
    levels.push_back(l);
  }
  j["levels"] = levels;
  return j;
}

void renderRelt(Job& job, Renderer& renderer, const RenderSettings& settings, Clock::time_point wallStart,
                Clock::time_point renderStart, const DirectEstimate& direct, const CheckpointPlan& plan,
                const Resumed* resumed) {
  const bool layers = settings.replica.perLevel;
  std::vector<Film> films;
  int snapshots = 0;
  const ReltOutcome o = runRelt(job, renderer, chainSettings(settings, direct), films,
                                          [&](const std::vector<double>& sums, double d) {
    writeImages(settings, withDirect(Renderer::resolve(films[0], sums, d), direct.image));
    ++snapshots;
  }, plan, resumed);
  // The first film takes the sum of all levels; the others are reduced as layers.
  std::vector<std::vector<double>> layerSums;
  if (layers)
    for (Film& f : films) {
      layerSums.push_back(f.data());
      job.reduceSumToRoot(layerSums.back());
    }
  for (size_t k = 1; k < films.size(); ++k)
    for (size_t i = 0; i < films[0].data().size(); ++i) films[0].data()[i] += films[k].data()[i];
  const Gathered g = gatherAfterRender(job, renderStart, renderer, films[0]);
  if (!job.isRoot()) return;
  const Image image = withDirect(Renderer::resolve(films[0], films[0].data(), o.resolveDivisor), direct.image);
  std::vector<ImageLayer> out;
  for (size_t k = 0; k < layerSums.size(); ++k)
    out.push_back({"level" + std::to_string(k), Renderer::resolve(films[k], layerSums[k], o.resolveDivisor)});
  if (layers && !direct.image.rgb.empty()) out.push_back({"direct", direct.image});  // the layers still sum to the image
  uint64_t mutations = 0, invalid = 0, nonFinite = 0;
  for (const LevelCounters& c : o.perLevel) {
    mutations += c.smallProposed + c.largeProposed;
    invalid += c.invalidProposals;
    nonFinite += c.nonFinite;
  }
  nlohmann::json j = commonStats(settings, job, g, image);
  j["nan_inf_samples_dropped"] = nonFinite + direct.dropped;
  addDirectStats(j, settings, direct);
  j["nan_inf_samples_dropped_per_rank"] = counts(o.nonFinitePerRank);
  const uint64_t earlier =
      resumed ? resumed->progress.at("steps_per_chain").get<uint64_t>() * uint64_t(o.ladders * o.levels) : 0;
  addMutationRates(j, mutations, g, job.size(), earlier);
  j["snapshots"] = snapshots;
  j["invalid_proposals"] = invalid;
  j["relt"] = reltStats(o);
  if (resumed) j["resumed_from"] = {{"checkpoint", resumed->file}, {"progress", resumed->progress}};
  writeOutputs(settings, image, j, wallStart, out);
  if (!settings.trace.empty())  // the scaling model's input; large, so apart from stats.json
    writeFileAtomically(settings.trace, nlohmann::json{{"group_round_step_seconds_per_rank", o.stepTrace}}.dump() + "\n");
  std::fprintf(stderr, "relt: %llu mutations in %llu rounds, %.2f s, %.3f M mutations/s, %llu round trips; wrote %s\n",
               static_cast<unsigned long long>(mutations), static_cast<unsigned long long>(o.rounds), g.renderSeconds,
               j["mutations_per_second"].get<double>() * 1e-6, static_cast<unsigned long long>(o.roundTrips),
               filesWritten(settings).c_str());
}

// pssmlt and mmlt: the chains' image (plus the direct emission apart), their counters in stats.json.
void renderChains(Job& job, Renderer& renderer, const RenderSettings& settings, Clock::time_point wallStart,
                  Clock::time_point renderStart, const DirectEstimate& direct, const CheckpointPlan& plan,
                  const Resumed* resumed) {
  Film film(settings.width, settings.height);
  int snapshots = 0;
  const PssmltOutcome o = runPssmlt(job, renderer, chainSettings(settings, direct), film,
                                    [&](const std::vector<double>& sums, double d) {
    writeImages(settings, withDirect(Renderer::resolve(film, sums, d), direct.image));
    ++snapshots;
  }, plan, resumed);
  const Gathered g = gatherAfterRender(job, renderStart, renderer, film);
  if (!job.isRoot()) return;
  const double area = double(settings.width) * settings.height;
  const Image image =
      withDirect(Renderer::resolve(film, film.data(), pssmltResolveDivisor(o.totalMutations, o.normaliser, area)), direct.image);
  const uint64_t mutations = o.counters.smallProposed + o.counters.largeProposed;
  nlohmann::json j = commonStats(settings, job, g, image);
  j["nan_inf_samples_dropped"] = g.dropped + direct.dropped;
  addDirectStats(j, settings, direct);
  addMutationRates(j, mutations, g, job.size(), resumed ? resumed->progress.at("mutations").get<uint64_t>() : 0);
  j["rounds"] = o.rounds;
  j["snapshots"] = snapshots;
  j["bootstrap_samples"] = o.bootstrapSamples;
  j["normaliser"] = o.normaliser;
  j["acceptance_small"] = o.counters.smallProposed ? double(o.counters.smallAccepted) / o.counters.smallProposed : 0.0;
  j["acceptance_large"] = o.counters.largeProposed ? double(o.counters.largeAccepted) / o.counters.largeProposed : 0.0;
  j["invalid_proposals"] = o.counters.invalidProposals;
  if (!o.perDepth.empty()) {
    nlohmann::json depths = nlohmann::json::array();
    for (size_t d = 0; d < o.perDepth.size(); ++d) {
      const ChainCounters& c = o.perDepth[d];
      const uint64_t proposed = c.smallProposed + c.largeProposed;
      depths.push_back({{"depth", d + 1},
                        {"mutations", proposed},
                        {"acceptance", proposed ? double(c.smallAccepted + c.largeAccepted) / proposed : 0.0}});
    }
    j["per_depth"] = depths;
  }
  if (resumed) j["resumed_from"] = {{"checkpoint", resumed->file}, {"progress", resumed->progress}};
  writeOutputs(settings, image, j, wallStart);
  std::fprintf(stderr, "relt: %llu mutations, %.2f s, %.3f M mutations/s; wrote %s\n",
               static_cast<unsigned long long>(mutations), g.renderSeconds,
               mutations / std::max(g.renderSeconds, 1e-9) * 1e-6, filesWritten(settings).c_str());
}

// pssmlt and relt stopped during the direct-emission pass: the image of the pass so far (the chains
// have not started; its checkpoint is written), and the stats.
void finishInThePass(Job& job, const Renderer& renderer, const RenderSettings& settings,
                     Clock::time_point wallStart, Clock::time_point renderStart, const DirectEstimate& direct) {
  Film none(settings.width, settings.height);
  const Gathered g = gatherAfterRender(job, renderStart, renderer, none);
  if (!job.isRoot()) return;
  const Image image = direct.spp > 0 ? direct.image : Renderer::resolve(none, none.data(), 1.0);
  nlohmann::json j = commonStats(settings, job, g, image);
  j["nan_inf_samples_dropped"] = direct.dropped;
  addDirectStats(j, settings, direct);
  writeOutputs(settings, image, j, wallStart);
  std::fprintf(stderr, "relt: stopped in the direct-emission pass (%d rays per pixel), %.2f s; wrote %s\n", direct.spp,
               g.renderSeconds, filesWritten(settings).c_str());
}

// erpt: its image (with the proposal filter, if asked) and counters in stats.json.
void renderErpt(Job& job, Renderer& renderer, const RenderSettings& settings, Clock::time_point wallStart,
                const CheckpointPlan& plan, const Resumed* resumed) {
  PassFilm film = erptFilm(settings);
  const auto renderStart = Clock::now();
  int snapshots = 0;
  const ErptOutcome o = runErpt(job, renderer, settings, film, [&](const Image& image) {
    writeImages(settings, image);
    ++snapshots;
  }, plan, resumed);
  const Gathered g = gatherAfterRender(job, renderStart, renderer, film.live(), false);
  if (!job.isRoot()) return;
  const Image& image = o.image;
  nlohmann::json j = commonStats(settings, job, g, image);
  addMutationRates(j, o.counters.mutations, g, job.size(),
                   resumed ? resumed->progress.at("mutations").get<uint64_t>() : 0);
  addPassStats(j, o.end, film.shown(o.end));
  j["snapshots"] = snapshots;
  j["seeds"] = o.counters.seeds;
  j["chains"] = o.counters.chains;
  j["acceptance"] = o.counters.mutations ? double(o.counters.accepted) / o.counters.mutations : 0.0;
  j["invalid_proposals"] = o.counters.invalidProposals;
  j["normaliser"] = o.normaliser;
  if (resumed) j["resumed_from"] = {{"checkpoint", resumed->file}, {"progress", resumed->progress}};
  writeOutputs(settings, image, j, wallStart);
  std::fprintf(stderr, "relt: %d seeds per pixel%s, %llu seeds, %llu chains, %llu mutations, %.2f s; wrote %s\n",
               o.end.passes, inPassNote(o.end, film.shown(o.end)).c_str(),
               static_cast<unsigned long long>(o.counters.seeds), static_cast<unsigned long long>(o.counters.chains),
               static_cast<unsigned long long>(o.counters.mutations), g.renderSeconds, filesWritten(settings).c_str());
}

// pt and bdpt: a checkpoint is the film and where the passes got to (pass k's samples depend on k
// only), and inside a pass for bdpt also the film of the whole passes (render/pass_film.h).
void renderPasses(Job& job, Renderer& renderer, const RenderSettings& settings,
                  Clock::time_point wallStart, const CheckpointPlan& plan, const Resumed* resumed) {
  PassFilm film(settings.width, settings.height, samplesStayInTheirRow(settings.integrator), 0, settings.threads);
  PassStart start;
  uint64_t earlierSamples = 0;
  if (resumed) {
    start = passStartOf(resumed->progress);
    resumed->restoreFilms(film.checkpointFilms(start.at));
    film.restored(start.at);
    earlierSamples = resumed->progress.at("samples").get<uint64_t>();
  }
  const auto renderStart = Clock::now();
  int snapshots = 0;
  PassHooks hooks;
  hooks.renderUnit = [&](uint64_t pass, int row) { renderer.renderRow(pass, row, film.workerFilm(currentWorker())); };
  hooks.rate = [&](double elapsed) { return double(renderer.samples()) * job.size() / std::max(elapsed, 1e-9); };
  hooks.snapshot = [&](PassPoint at) {
    const Image image = reducedPassImage(job, film, at);
    if (job.isRoot()) writeImages(settings, image);
    ++snapshots;
  };
  hooks.chunkDone = [&, lastCheckpoint = start.elapsed](PassPoint at, double elapsed, bool more, bool save) mutable {
    if (!checkpointNow(plan, elapsed, lastCheckpoint, more, save)) return;
    film.gatherWorkers();
    nlohmann::json progress = passProgress(at, elapsed);
    progress["samples"] = earlierSamples + job.allreduceSum(renderer.samples());
    saveCheckpoint(job, plan, integratorName(settings.integrator), progress, film.checkpointFilms(at), {});
  };
  const PassPoint end = runPasses(job, settings, film, hooks, start);
  const uint64_t samplesNow = job.allreduceSum(renderer.samples()), samples = earlierSamples + samplesNow;
  const Image image = reducedPassImage(job, film, end);
  const Gathered g = gatherAfterRender(job, renderStart, renderer, film.live(), false);
  if (!job.isRoot()) return;

  nlohmann::json j = commonStats(settings, job, g, image);
  addPassStats(j, end, film.shown(end));
  j["snapshots"] = snapshots;
  j["samples"] = samples;
  j["samples_per_second"] = samplesNow / std::max(g.renderSeconds, 1e-9);
  j["samples_per_second_per_rank"] = samplesNow / std::max(g.renderSeconds, 1e-9) / job.size();
  if (resumed) j["resumed_from"] = {{"checkpoint", resumed->file}, {"progress", resumed->progress}};
  writeOutputs(settings, image, j, wallStart);
  std::fprintf(stderr, "relt: %d spp%s, %.2f s, %.3f M samples/s, %.2f M rays/s; wrote %s\n", end.passes,
               inPassNote(end, film.shown(end)).c_str(), g.renderSeconds,
               samplesNow / std::max(g.renderSeconds, 1e-9) * 1e-6, g.rays / std::max(g.renderSeconds, 1e-9) * 1e-6,
               filesWritten(settings).c_str());
}

}  // namespace

void runRender(Job& job, RenderSettings settings, CheckpointPlan plan) {
  const auto wallStart = Clock::now();
  Renderer renderer(loadGltf(settings.scenePath), settings);
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
  if (!plan.resume.empty()) resumed = loadCheckpoint(job, plan, integratorName(settings.integrator));

  if (settings.integrator == Integrator::Relt || isMarkovChain(settings.integrator)) {
    const auto renderStart = Clock::now();
    const DirectEstimate direct = directEmission(job, renderer, settings, plan, resumed, [&](const Image& image) {
      writeImages(settings, image);
    });
    if (direct.stopped) {
      finishInThePass(job, renderer, settings, wallStart, renderStart, direct);
      return;
    }
    if (directEmissionApart(settings)) {
      plan.direct = direct.progress();
      if (direct.spp > 0) plan.directFilm = &direct.film;
    }
    const Resumed* chains = resumed ? &*resumed : nullptr;
    if (settings.integrator == Integrator::Relt)
      renderRelt(job, renderer, settings, wallStart, renderStart, direct, plan, chains);
    else
      renderChains(job, renderer, settings, wallStart, renderStart, direct, plan, chains);
    return;
  }
  if (settings.integrator == Integrator::Erpt) {
    renderErpt(job, renderer, settings, wallStart, plan, resumed ? &*resumed : nullptr);
    return;
  }
  renderPasses(job, renderer, settings, wallStart, plan, resumed ? &*resumed : nullptr);
}

}  // namespace relt
