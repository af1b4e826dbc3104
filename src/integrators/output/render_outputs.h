#pragma once
// What every integrator's render writes and how: the images as -o and --png name them (with the
// EXR's metadata), the stats every integrator has, and the closing line's list of files.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "checkpoint/checkpoint_io.h"
#include "core/clock.h"
#include "film/film.h"
#include "image/image.h"
#include "parallel/job.h"
#include "render/renderer.h"
#include "render/settings.h"
#include "schedule/schedule.h"

namespace relt {

// The image as -o names it (EXR with optional extra layers and metadata, or PNG) and the optional
// PNG, each written atomically. Root only. Every image goes out through here, so here a NaN or
// infinite pixel is written as 0, counted and reported: a safety net, the integrators must not
// make them. `stats` given: the final image (its metadata names the samples and the time).
// Returns the image as written.
Image writeImages(const RenderSettings& settings, Image image, std::vector<ImageLayer> layers = {},
                  const nlohmann::json& stats = {});

// The images and the stats (with the wall time added). Root only.
void writeOutputs(const RenderSettings& settings, const Image& image, nlohmann::json stats, Clock::time_point wallStart,
                  const std::vector<ImageLayer>& layers = {});

// "a.exr, a.png and a.json": every file a render writes, for its closing line.
std::string filesWritten(const RenderSettings& settings);

// What every rank contributes once rendering ends (collective): the film summed on the root,
// counters summed, timings gathered.
struct Gathered {
  double renderSeconds = 0.0;
  uint64_t rays = 0, dropped = 0;
  uint64_t subpathVertices = 0;  // bidirectional integrators' (0: none counted)
  std::vector<double> droppedPerRank;  // NaN/Inf samples each rank dropped
  std::vector<double> collective;
  std::vector<std::string> hosts;    // each rank's processor name
  std::vector<double> peakResident;  // each rank's most resident bytes
};
Gathered gatherAfterRender(Job& job, Clock::time_point renderStart, const Renderer& renderer, Film& film,
                           bool reduceFilm = true);

// The stats every integrator writes.
nlohmann::json commonStats(const RenderSettings& settings, Job& job, const Gathered& g, const Image& image);
// Per-rank counts gathered as doubles, written as integers.
std::vector<uint64_t> counts(const std::vector<double>& v);
// `earlier`: mutations of the render this one resumed (in the total, not in the rates).
void addMutationRates(nlohmann::json& j, uint64_t mutations, const Gathered& g, int ranks, uint64_t earlier = 0);
// The checkpoint a render continued, if it did.
void addResumedFrom(nlohmann::json& j, const std::optional<Resumed>& resumed);

// The passes of pt, bdpt and erpt in stats.json: whole passes, and for a render stopped inside a
// pass the rows it did (in its checkpoint) and those its image shows (render/pass_film.h).
void addPassStats(nlohmann::json& j, PassPoint end, PassPoint shown);
// The closing line's words for a render stopped inside a pass ("" otherwise).
std::string inPassNote(PassPoint end, PassPoint shown);

}  // namespace relt
