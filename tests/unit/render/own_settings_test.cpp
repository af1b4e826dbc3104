// An integrator's own settings held type-erased in RenderSettings: copies are deep, and reading them
// as another integrator's type is refused.
#include <gtest/gtest.h>

#include "render/settings.h"

using namespace relt;

namespace {

struct Ladder final : SettingsOf<Ladder> {
  int levels = 8;
};
struct Chains final : SettingsOf<Chains> {
  int length = 100;
};

}  // namespace

TEST(OwnSettings, ACopyOfTheSettingsHasItsOwnIntegratorSettings) {
  RenderSettings a;
  a.own = OwnSettings(std::make_unique<Ladder>());
  RenderSettings b = a;
  b.own.get<Ladder>().levels = 4;
  EXPECT_EQ(a.own.get<Ladder>().levels, 8);
  EXPECT_EQ(b.own.get<Ladder>().levels, 4);
  a = b;
  EXPECT_EQ(a.own.get<Ladder>().levels, 4);
}

TEST(OwnSettings, ReadingThemAsAnotherIntegratorsTypeThrows) {
  RenderSettings s;
  EXPECT_THROW(s.own.get<Ladder>(), std::logic_error);  // none held
  s.own = OwnSettings(std::make_unique<Chains>());
  EXPECT_THROW(s.own.get<Ladder>(), std::logic_error);
  EXPECT_EQ(s.own.get<Chains>().length, 100);
}
