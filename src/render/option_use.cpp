#include "render/option_use.h"

#include <initializer_list>
#include <vector>

namespace relt {
namespace {

using I = Integrator;

struct OptionUse {
  const char* option;
  std::vector<Integrator> users;
  const char* hint;  // added to the others' refusal, or nullptr
};

const std::vector<OptionUse>& optionUses() {
  static const std::vector<OptionUse> uses = [] {
    const std::vector<Integrator> passes = {I::PathTracing, I::Bdpt, I::Erpt}, chains = {I::Pssmlt, I::Mmlt, I::Relt};
    const std::vector<Integrator> kelemen = {I::Pssmlt, I::Mmlt, I::Erpt, I::Relt};
    std::vector<OptionUse> u = {
        {"--spp", passes, "the Markov-chain integrators take --mutations-per-pixel"},
        {"--mutations-per-pixel", chains, "the others take --spp"},
        {"--chains", {I::Pssmlt, I::Mmlt}, "relt's chains are ladders x levels: --ladders, --levels"},
        {"--large-step-probability", chains, nullptr},
        {"--small-step-min", kelemen, nullptr},
        {"--small-step-max", kelemen, nullptr},
        {"--direct-emission-spp", {I::Pssmlt, I::Relt}, nullptr},
        {"--chain-length", {I::Erpt}, nullptr},
        {"--erpt-max-consecutive", {I::Erpt}, nullptr},
        {"--erpt-proposal-filter", {I::Erpt}, nullptr},
    };
    for (const char* relt : {"--family", "--levels", "--ladders", "--exchange", "--exchange-interval",
                             "--normaliser-lag", "--normaliser-lag-growth", "--placement", "--balance-window",
                             "--mis-levels", "--init", "--per-level", "--trace", "--relaxed-eps", "--relaxed-ratio",
                             "--kitaoka-delta", "--temperature-max", "--regularisation", "--regularisation-decay",
                             "--energy-rings"})
      u.push_back({relt, {I::Relt}, nullptr});
    return u;
  }();
  return uses;
}

std::string namesOf(const std::vector<Integrator>& users) {
  std::string names;
  for (size_t i = 0; i < users.size(); ++i) {
    if (i > 0) names += i + 1 == users.size() ? " and " : ", ";
    names += integratorName(users[i]);
  }
  return names;
}

}  // namespace

std::vector<std::string> optionsNotForEveryIntegrator() {
  std::vector<std::string> names;
  for (const OptionUse& use : optionUses()) names.push_back(use.option);
  return names;
}

std::optional<std::string> unusedOptionReason(const std::string& option, Integrator integrator) {
  for (const OptionUse& use : optionUses()) {
    if (option != use.option) continue;
    for (Integrator user : use.users)
      if (user == integrator) return std::nullopt;
    std::string reason = "only for --integrator " + namesOf(use.users);
    if (use.hint) reason += std::string(" (") + use.hint + ")";
    return reason;
  }
  return std::nullopt;
}

}  // namespace relt
