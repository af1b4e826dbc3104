// The integrator registry: which options each integrator takes follows from the entries
// (integrators/registry.h), and the executable's command line has every one of them.
#include "integrators/registry.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "integrators/erpt/erpt_settings.h"
#include "integrators/relt/relt_settings.h"

#include "test_support.h"

namespace relt {
namespace {

const IntegratorEntry& entry(const std::string& name) {
  const IntegratorEntry* e = findIntegrator(name);
  EXPECT_NE(e, nullptr) << name;
  return *e;
}

TEST(Registry, HasTheEightIntegratorsInHelpOrder) {
  std::vector<std::string> names;
  for (const IntegratorEntry* e : integrators()) names.push_back(e->kind.name);
  EXPECT_EQ(names, (std::vector<std::string>{"pt", "bdpt", "pssmlt", "mmlt", "erpt", "relt", "vcm", "meb"}));
  EXPECT_EQ(findIntegrator("melt"), nullptr);
  RenderSettings s;
  EXPECT_THROW(selectIntegrator(s, "melt"), std::invalid_argument);
  EXPECT_EQ(s.integrator.name, kDefaultIntegrator);
}

TEST(Registry, SelectingAnIntegratorSetsItsKind) {
  RenderSettings s;
  selectIntegrator(s, "relt");
  EXPECT_EQ(s.integrator.name, "relt");
  EXPECT_TRUE(s.integrator.directEmissionApart);
  EXPECT_TRUE(directEmissionApart(s));
  s.directSpp = 0;
  EXPECT_FALSE(directEmissionApart(s));
  selectIntegrator(s, "mmlt");
  s.directSpp = kDirectSppAuto;
  EXPECT_FALSE(directEmissionApart(s));
  EXPECT_EQ(s.toJson().at("chains"), s.chains);
}

// Each option writes into its own integrator's draft; the chosen integrator keeps its draft, and
// without drafts its own settings' defaults.
TEST(Registry, TheChosenIntegratorKeepsItsOwnSettingsFromTheCommandLine) {
  CLI::App command;
  RenderSettings s;
  SettingsDrafts drafts;
  addIntegratorOptions(command, s, drafts);
  command.parse(std::vector<std::string>{"3", "--levels", "50", "--chain-length"});  // reversed
  selectIntegrator(s, "erpt", &drafts);
  EXPECT_EQ(s.own.get<ErptIntegratorSettings>().chainLength, 50);
  EXPECT_THROW(replicaSettings(s), std::logic_error);
  selectIntegrator(s, "relt", &drafts);
  EXPECT_EQ(replicaSettings(s).family.levels, 3);
  selectIntegrator(s, "relt");
  EXPECT_EQ(replicaSettings(s).family.levels, ReplicaSettings{}.family.levels);
}

TEST(Registry, AnOptionIsRefusedOnlyWhereItIsUnused) {
  EXPECT_FALSE(unusedOptionReason("--chains", entry("pssmlt")));
  EXPECT_FALSE(unusedOptionReason("--chains", entry("mmlt")));
  ASSERT_TRUE(unusedOptionReason("--chains", entry("pt")));
  EXPECT_EQ(*unusedOptionReason("--chains", entry("pt")),
            "only for --integrator pssmlt and mmlt (relt's chains are ladders x levels: --ladders, --levels)");
  EXPECT_FALSE(unusedOptionReason("--small-step-min", entry("erpt")));
  EXPECT_TRUE(unusedOptionReason("--small-step-min", entry("bdpt")));
  EXPECT_EQ(*unusedOptionReason("--ladders", entry("pssmlt")), "only for --integrator relt");
  EXPECT_EQ(*unusedOptionReason("--chain-length", entry("relt")), "only for --integrator erpt");
  EXPECT_EQ(*unusedOptionReason("--spp", entry("relt")),
            "only for --integrator pt, bdpt, erpt, vcm and meb (pssmlt, mmlt and relt take --mutations-per-pixel)");
}

TEST(Registry, OptionsOutsideTheTableAreEveryIntegrators) {
  for (const IntegratorEntry* e : integrators()) {
    EXPECT_FALSE(unusedOptionReason("--seed", *e));
    EXPECT_FALSE(unusedOptionReason("--max-depth", *e));
    EXPECT_FALSE(unusedOptionReason("--checkpoint", *e));
  }
}

TEST(Registry, EveryOptionOfTheTableHasUsersAndNonUsers) {
  const std::vector<std::string> options = optionsNotForEveryIntegrator();
  EXPECT_GE(options.size(), 25u);
  for (const std::string& option : options) {
    size_t users = 0;
    for (const IntegratorEntry* e : integrators()) users += unusedOptionReason(option, *e) ? 0 : 1;
    EXPECT_GT(users, 0u) << option;
    EXPECT_LT(users, integrators().size()) << option;
  }
}

// A shared option an entry names but nobody registers would refuse nothing and take nothing.
TEST(Registry, EverySharedOptionAnEntryNamesIsRegistered) {
  const std::vector<std::string> options = optionsNotForEveryIntegrator();
  for (const IntegratorEntry* e : integrators())
    for (const std::string& option : e->sharedOptions)
      EXPECT_NE(std::find(options.begin(), options.end(), option), options.end()) << e->kind.name << " " << option;
}

// The validation refuses an option the integrator does not take, and checks the shared ones.
TEST(Registry, ValidationRefusesUnusedOptionsAndCrossedStepSizes) {
  RenderSettings s;
  selectIntegrator(s, "pt");
  EXPECT_THROW(validateIntegratorOptions(s, {"--chains"}), InputError);
  EXPECT_NO_THROW(validateIntegratorOptions(s, {"--spp", "--seed"}));
  selectIntegrator(s, "pssmlt");
  s.smallStepMin = 0.1f;
  s.smallStepMax = 0.01f;
  EXPECT_THROW(validateIntegratorOptions(s, {"--small-step-min"}), InputError);
}

// A name in the table that the command line does not have would refuse nothing.
TEST(Registry, EveryOptionOfTheTableIsARenderOption) {
  const test::CommandResult help = test::runCommand(test::reltBinary() + " render --help");
  ASSERT_EQ(help.exitCode, 0) << help.output;
  for (const std::string& option : optionsNotForEveryIntegrator())
    EXPECT_NE(help.output.find("  " + option + " "), std::string::npos) << option;
  for (const IntegratorEntry* e : integrators())
    EXPECT_NE(help.output.find(e->kind.name + " (" + e->summary + ")"), std::string::npos) << e->kind.name;
}

}  // namespace
}  // namespace relt
