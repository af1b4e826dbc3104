// A toy integrator written the way every integrator is (integrators/integrator.h): an entry with a
// name, one option of its own, a validation and a render; one line registers it. It renders
// through the executable's own runRender (scene loading, option checks, outputs, stats) on a job
// of one process, so nothing but this file and that line is needed to add an integrator.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "image/image.h"
#include "integrators/output/render_outputs.h"
#include "integrators/registry.h"
#include "integrators/render_driver.h"
#include "parallel/local_job.h"
#include "test_support.h"

namespace relt {
namespace {

// Every pixel the same grey, set by --grey.
struct ToySettings final : SettingsOf<ToySettings> {
  double grey = 0.5;
};

void addToyOptions(CLI::App& cmd, IntegratorSettings& own) {
  cmd.add_option("--grey", dynamic_cast<ToySettings&>(own).grey, "constant: the grey of every pixel")
      ->check(CLI::Range(0.0, 1e6));
}

void validateToy(RenderSettings& settings, const GivenOptions& given) {
  if (settings.maxDepth > 1) throw InputError("", "--max-depth", "constant: only 1 (it traces nothing)");
}

void renderToy(RenderContext& c) {
  const auto start = Clock::now();
  Film none(c.settings.width, c.settings.height);
  const Gathered g = gatherAfterRender(c.job, start, c.renderer, none);
  if (!c.job.isRoot()) return;
  Image image(c.settings.width, c.settings.height);
  for (float& v : image.rgb) v = float(c.settings.own.get<ToySettings>().grey);
  writeOutputs(c.settings, image, commonStats(c.settings, c.job, g, image), c.wallStart);
}

const IntegratorEntry& constantIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "constant";
    e.kind.settingsJson = [](const RenderSettings& s, nlohmann::json& j) { j["grey"] = s.own.get<ToySettings>().grey; };
    e.summary = "a constant grey (a test's toy)";
    e.makeSettings = makeSettingsOf<ToySettings>;
    e.addOptions = addToyOptions;
    e.validate = validateToy;
    e.render = renderToy;
    return e;
  }();
  return entry;
}

// The command line of `relt render` as the executable builds it, parsed from `args`.
RenderSettings parsed(std::vector<std::string> args) {
  CLI::App command;
  RenderSettings settings;
  SettingsDrafts drafts;
  std::string integrator;
  command.add_option("--integrator", integrator);
  addIntegratorOptions(command, settings, drafts);
  std::reverse(args.begin(), args.end());
  command.parse(args);
  selectIntegrator(settings, integrator, &drafts);
  GivenOptions given;
  for (const CLI::Option* option : command.get_options())
    if (option->count() > 0 && option->get_name() != "--integrator") given.push_back(option->get_name());
  validateIntegratorOptions(settings, given);
  return settings;
}

TEST(ToyIntegrator, OneRegistryLineAddsItWithItsOptionsAndItRendersThroughRunRender) {
  registerIntegrator(constantIntegrator());
  EXPECT_THROW(registerIntegrator(constantIntegrator()), std::invalid_argument);

  // Its option is its own: refused for the others, and theirs for it.
  EXPECT_EQ(*unusedOptionReason("--grey", *findIntegrator("pt")), "only for --integrator constant");
  EXPECT_TRUE(unusedOptionReason("--chains", constantIntegrator()));
  EXPECT_FALSE(unusedOptionReason("--seed", constantIntegrator()));
  EXPECT_THROW(parsed({"--integrator", "pt", "--grey", "1"}), InputError);
  EXPECT_THROW(parsed({"--integrator", "constant", "--spp", "4"}), InputError);

  RenderSettings settings = parsed({"--integrator", "constant", "--grey", "0.25"});
  EXPECT_EQ(settings.own.get<ToySettings>().grey, 0.25);
  const std::string dir = test::makeTempDir("toy-integrator");
  settings.scenePath = test::sourcePath("scenes/furnace.gltf");
  settings.output = dir + "/constant.exr";
  settings.stats = dir + "/constant.json";
  settings.width = 8;
  settings.height = 4;
  LocalJob job;
  runRender(job, settings);

  const Image image = readExr(settings.output);
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 4);
  for (float v : image.rgb) EXPECT_EQ(v, 0.25f);
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(settings.stats));
  EXPECT_EQ(stats.at("settings").at("integrator"), "constant");
  EXPECT_EQ(stats.at("settings").at("grey"), 0.25);
  const ImageAttributes attributes = readExrAttributes(settings.output);
  EXPECT_NE(std::find(attributes.begin(), attributes.end(), std::pair<std::string, std::string>("relt:integrator", "constant")),
            attributes.end());

  settings.maxDepth = 3;  // its own validation runs too
  EXPECT_THROW(validateIntegratorOptions(settings, {}), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace relt
