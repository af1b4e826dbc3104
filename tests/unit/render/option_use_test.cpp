// Which integrators use which render options (render/option_use.h).
#include "render/option_use.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace relt {
namespace {

const Integrator kAll[] = {Integrator::PathTracing, Integrator::Bdpt, Integrator::Pssmlt,
                           Integrator::Mmlt,        Integrator::Erpt, Integrator::Relt};

TEST(OptionUse, AnOptionIsRefusedOnlyWhereItIsUnused) {
  EXPECT_FALSE(unusedOptionReason("--chains", Integrator::Pssmlt));
  EXPECT_FALSE(unusedOptionReason("--chains", Integrator::Mmlt));
  ASSERT_TRUE(unusedOptionReason("--chains", Integrator::PathTracing));
  EXPECT_EQ(*unusedOptionReason("--chains", Integrator::PathTracing),
            "only for --integrator pssmlt and mmlt (relt's chains are ladders x levels: --ladders, --levels)");
  EXPECT_FALSE(unusedOptionReason("--small-step-min", Integrator::Erpt));
  EXPECT_TRUE(unusedOptionReason("--small-step-min", Integrator::Bdpt));
  EXPECT_EQ(*unusedOptionReason("--ladders", Integrator::Pssmlt), "only for --integrator relt");
}

TEST(OptionUse, OptionsOutsideTheTableAreEveryIntegrators) {
  for (Integrator i : kAll) {
    EXPECT_FALSE(unusedOptionReason("--seed", i));
    EXPECT_FALSE(unusedOptionReason("--max-depth", i));
    EXPECT_FALSE(unusedOptionReason("--checkpoint", i));
  }
}

TEST(OptionUse, EveryOptionOfTheTableHasUsersAndNonUsers) {
  for (const std::string& option : optionsNotForEveryIntegrator()) {
    int users = 0;
    for (Integrator i : kAll) users += unusedOptionReason(option, i) ? 0 : 1;
    EXPECT_GT(users, 0) << option;
    EXPECT_LT(users, 6) << option;
  }
}

// A name in the table that the command line does not have would refuse nothing.
TEST(OptionUse, EveryOptionOfTheTableIsARenderOption) {
  const test::CommandResult help = test::runCommand(test::reltBinary() + " render --help");
  ASSERT_EQ(help.exitCode, 0) << help.output;
  for (const std::string& option : optionsNotForEveryIntegrator())
    EXPECT_NE(help.output.find("  " + option + " "), std::string::npos) << option;
}

}  // namespace
}  // namespace relt
