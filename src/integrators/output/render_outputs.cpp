#include "integrators/output/render_outputs.h"

#include <cmath>
#include <cstdio>

#include "checkpoint/checkpoint_io.h"
#include "core/memory.h"
#include "relt_commit.h"

namespace relt {
namespace {

// Pixels zeroed by writeImages over the render (snapshots and the final image).
uint64_t nonFinitePixelsZeroed = 0;

// What an EXR says of its render: the integrator, the settings, the commit, and for the final
// image (`stats` given) the samples, mutations or iterations taken and the seconds.
ImageAttributes renderAttributes(const RenderSettings& settings, const nlohmann::json& stats) {
  ImageAttributes a = {{"relt:integrator", settings.integrator.name},
                       {"relt:settings", settings.toJson().dump()},
                       {"relt:commit", RELT_COMMIT}};
  if (stats.is_null()) return a;
  for (const char* key : {"spp", "image_rows_of_the_stopped_pass", "mutations", "iterations", "render_seconds", "interrupted"})
    if (stats.contains(key)) a.emplace_back(std::string("relt:") + key, stats[key].dump());
  return a;
}

// Images written against a clock are not compressed: snapshots (a save request comes a second
// before mpirun's SIGTERM) and the image of a render stopped by a signal (SIGKILL follows a second
// later); ZIP would take most of that second on a 1024x768 film.
ExrCompression exrCompressionOf(const nlohmann::json& stats) {
  return stats.is_null() || stats.value("interrupted", false) ? ExrCompression::None : ExrCompression::Zip;
}

}  // namespace

Image writeImages(const RenderSettings& settings, Image image, std::vector<ImageLayer> layers,
                  const nlohmann::json& stats) {
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

std::string filesWritten(const RenderSettings& s) {
  std::vector<std::string> files;
  for (const std::string& f : {s.output, s.png, s.stats, s.trace})
    if (!f.empty()) files.push_back(f);
  std::string out;
  for (size_t i = 0; i < files.size(); ++i) out += (i == 0 ? "" : i + 1 == files.size() ? " and " : ", ") + files[i];
  return out;
}

void addPassStats(nlohmann::json& j, PassPoint end, PassPoint shown) {
  j["spp"] = end.passes;
  if (end.rows == 0) return;
  j["rows_of_the_stopped_pass"] = end.rows;
  j["image_rows_of_the_stopped_pass"] = shown.rows;
}

std::string inPassNote(PassPoint end, PassPoint shown) {
  if (end.rows == 0) return "";
  return " and " + std::to_string(end.rows) + " rows of the next" +
         (shown.rows == end.rows ? "" : " (not in the image: its samples reach rows not done)");
}

void writeOutputs(const RenderSettings& settings, const Image& image, nlohmann::json stats, Clock::time_point wallStart,
                  const std::vector<ImageLayer>& layers) {
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

Gathered gatherAfterRender(Job& job, Clock::time_point renderStart, const Renderer& renderer, Film& film, bool reduceFilm) {
  Gathered g;
  g.renderSeconds = job.allreduceMax(secondsSince(renderStart));
  if (reduceFilm) job.reduceSumToRoot(film.data());
  g.rays = job.allreduceSum(renderer.rays());
  g.subpathVertices = job.allreduceSum(renderer.subpathVertices());
  g.dropped = job.allreduceSum(film.droppedSamples());
  g.droppedPerRank = job.allgather(double(film.droppedSamples()));
  g.collective = job.allgather(job.collectiveSeconds());
  g.hosts = job.processorNames();
  g.peakResident = job.allgather(double(peakResidentBytes()));
  return g;
}

std::vector<uint64_t> counts(const std::vector<double>& v) { return std::vector<uint64_t>(v.begin(), v.end()); }

nlohmann::json commonStats(const RenderSettings& settings, Job& job, const Gathered& g, const Image& image) {
  nlohmann::json j;
  j["settings"] = settings.toJson();
  j["ranks"] = job.size();
  j["interrupted"] = job.stopAgreed();
  j["hosts"] = g.hosts;
  j["rays"] = g.rays;
  j["render_seconds"] = g.renderSeconds;
  j["rays_per_second"] = g.rays / std::max(g.renderSeconds, 1e-9);
  if (g.subpathVertices > 0) {  // per core: the throughput bidirectional integrators are compared by
    j["subpath_vertices"] = g.subpathVertices;
    j["subpath_vertices_per_second_per_core"] =
        double(g.subpathVertices) / std::max(g.renderSeconds, 1e-9) / double(job.size() * settings.threads);
  }
  j["nan_inf_samples_dropped"] = g.dropped;
  j["nan_inf_samples_dropped_per_rank"] = counts(g.droppedPerRank);
  j["collective_seconds_per_rank"] = g.collective;
  std::vector<double> mib;
  for (double bytes : g.peakResident) mib.push_back(std::round(bytes / double(1 << 20) * 10.0) / 10.0);
  j["peak_resident_mib_per_rank"] = mib;
  j["image_mean"] = image.mean();
  return j;
}

void addMutationRates(nlohmann::json& j, uint64_t mutations, const Gathered& g, int ranks, uint64_t earlier) {
  j["mutations"] = mutations;
  const double now = double(mutations - std::min(mutations, earlier));
  j["mutations_per_second"] = now / std::max(g.renderSeconds, 1e-9);
  j["mutations_per_second_per_rank"] = now / std::max(g.renderSeconds, 1e-9) / ranks;
}

void addResumedFrom(nlohmann::json& j, const std::optional<Resumed>& resumed) {
  if (resumed) j["resumed_from"] = {{"checkpoint", resumed->file}, {"progress", resumed->progress}};
}

}  // namespace relt
