#include "integrators/relt/relt_options.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "image/image.h"
#include "integrators/option_checks.h"
#include "integrators/relt/relt_settings.h"
#include "integrators/shared_options.h"
#include "replica/permutation.h"

namespace relt {
namespace {

bool isGiven(const GivenOptions& given, const std::string& option) {
  return std::find(given.begin(), given.end(), option) != given.end();
}

// The ladder: its target family, levels and ladders, and where first states come from.
void addLadderOptions(CLI::App& cmd, ReplicaSettings& r) {
  cmd.add_option_function<std::string>(
         "--family", [&r](const std::string& v) { r.family.kind = *parseFamily(v); }, "relt: target family of the levels")
      ->check(CLI::IsMember({"kitaoka", "relaxed", "tempered"}))
      ->default_str(familyName(r.family.kind));
  cmd.add_option("--levels", r.family.levels, "relt: levels per ladder (relaxed, tempered; kitaoka has 4)")
      ->check(CLI::Range(2, kMaxLevels))
      ->capture_default_str();
  cmd.add_option("--ladders", r.ladders, "relt: number of ladders (chains = ladders x levels)")
      ->check(CLI::Range(1, 1 << 16))
      ->capture_default_str();
  cmd.add_option_function<std::string>(
         "--mis-levels", [&r](const std::string& v) { r.levelHeuristic = *parseMisHeuristic(v); },
         "relt: MIS heuristic over levels")
      ->check(CLI::IsMember({"balance", "power"}))
      ->default_str(misHeuristicName(r.levelHeuristic));
  cmd.add_option_function<std::string>(
         "--init", [&r](const std::string& v) { r.init = v == "annealing" ? InitKind::Annealing : InitKind::Resample; },
         "relt: first states (resample the bootstrap per level, or population annealing)")
      ->check(CLI::IsMember({"resample", "annealing"}))
      ->default_str(r.init == InitKind::Annealing ? "annealing" : "resample");
  cmd.add_flag("--per-level", r.perLevel, "relt: also write each level's contribution as an EXR layer levelK");
}

// The exchanges between levels, the normalisers' lag and where chains run.
void addExchangeOptions(CLI::App& cmd, ReplicaSettings& r) {
  cmd.add_option_function<std::string>(
         "--exchange", [&r](const std::string& v) { r.exchange.move = *parseExchangeMove(v); },
         "relt: exchange move between levels")
      ->check(CLI::IsMember({"deo", "neighbour", "permutation", "swap", "eem"}))
      ->default_str(exchangeMoveName(r.exchange.move));
  cmd.add_option("--exchange-interval", r.exchangeInterval, "relt: steps per chain between exchanges")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd.add_option("--normaliser-lag", r.normaliserLag,
                 "relt: rounds between taking large-step sums and using them in the normalisers (with packed "
                 "placement a rank may run this many rounds ahead of the slowest)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd.add_option("--normaliser-lag-growth", r.normaliserLagGrowth,
                 "relt: the lag grows as rounds / N from --normaliser-lag to 8 times it, so ranks of a long "
                 "render wait less for slow phases of others (0: a fixed lag)")
      ->check(CLI::Range(0, 1 << 20))
      ->capture_default_str();
  cmd.add_option_function<std::string>(
         "--placement", [&r](const std::string& v) { r.placement = *parsePlacement(v); },
         "relt: chains over ranks (spread: chain c on rank c mod P; packed: whole ladders, exchanges decided "
         "locally; auto: packed above 8 ranks when ladders >= 2 x ranks)")
      ->check(CLI::IsMember({"auto", "spread", "packed"}))
      ->default_str(placementName(r.placement));
  cmd.add_option("--balance-window", r.balanceWindow,
                 "relt: seconds of stepping between moves of chains to ranks in proportion to their measured "
                 "speed (0: placement never changes)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--energy-rings", r.exchange.energyRings, "relt eem: number of energy rings (0: one per level)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
}

// Each family's own parameters.
void addFamilyOptions(CLI::App& cmd, FamilySettings& f) {
  cmd.add_option("--relaxed-eps", f.relaxedEps1, "relt relaxed: eps_1 as a multiple of the mean of I")
      ->check(positiveNumber())
      ->capture_default_str();
  cmd.add_option("--relaxed-ratio", f.relaxedRatio, "relt relaxed: eps_{k+1} / eps_k")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--kitaoka-delta", f.kitaokaDelta, "relt kitaoka: weight of L5 in the specific replica")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd.add_option("--temperature-max", f.temperatureMax, "relt tempered: temperature of the top level")
      ->check(CLI::Range(1.0, 1e8))
      ->capture_default_str();
  cmd.add_option("--regularisation", f.regularisation,
                 "relt tempered: rho_0 of the connection roughness floor rho_0 (1 + n)^-gamma (0 = off)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd.add_option("--regularisation-decay", f.regularisationDecay, "relt tempered: gamma of the regularisation schedule")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

}  // namespace

void addReltOptions(CLI::App& cmd, IntegratorSettings& own) {
  ReplicaSettings& r = dynamic_cast<ReltSettings&>(own).replica;
  addLadderOptions(cmd, r);
  addExchangeOptions(cmd, r);
  addFamilyOptions(cmd, r.family);
}

void validateReltOptions(RenderSettings& s, const GivenOptions& given) {
  ReplicaSettings& r = replicaSettings(s);
  const std::pair<const char*, FamilyKind> owner[] = {
      {"--relaxed-eps", FamilyKind::Relaxed},     {"--relaxed-ratio", FamilyKind::Relaxed},
      {"--kitaoka-delta", FamilyKind::Kitaoka},   {"--temperature-max", FamilyKind::Tempered},
      {"--regularisation", FamilyKind::Tempered}, {"--regularisation-decay", FamilyKind::Tempered}};
  for (const auto& [name, kind] : owner)
    if (isGiven(given, name) && kind != r.family.kind)
      throw InputError("", name, std::string("only for --family ") + familyName(kind));
  if (r.family.kind == FamilyKind::Kitaoka) {
    if (isGiven(given, "--levels")) throw InputError("", "--levels", "not for --family kitaoka (its four levels are fixed)");
    r.family.levels = 4;
  }
  if (r.exchange.move == ExchangeMove::Permutation && r.family.levels > kMaxPermutationLevels)
    throw InputError("", "--exchange", "permutation needs at most 12 levels (its cost is M 2^M)");
  if (r.perLevel && imageFormatOf(s.output) != ImageFormat::Exr)
    throw InputError(s.output, "--per-level", "the levels are EXR layers: name the output .exr");
}

void addReltSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  const ReplicaSettings& r = replicaSettings(s);
  j["family"] = familyName(r.family.kind);
  switch (r.family.kind) {
    case FamilyKind::Relaxed:
      j["levels"] = r.family.levels;
      j["relaxed_eps1"] = r.family.relaxedEps1;
      j["relaxed_ratio"] = r.family.relaxedRatio;
      break;
    case FamilyKind::Kitaoka: j["kitaoka_delta"] = r.family.kitaokaDelta; break;
    case FamilyKind::Tempered:
      j["levels"] = r.family.levels;
      j["temperature_max"] = r.family.temperatureMax;
      j["regularisation"] = r.family.regularisation;
      if (r.family.regularisation > 0.0) j["regularisation_decay"] = r.family.regularisationDecay;
      break;
  }
  j["ladders"] = r.ladders;
  j["exchange"] = exchangeMoveName(r.exchange.move);
  j["exchange_interval"] = r.exchangeInterval;
  j["normaliser_lag"] = r.normaliserLag;
  j["normaliser_lag_growth"] = r.normaliserLagGrowth;
  j["placement"] = placementName(r.placement);
  j["balance_window"] = r.balanceWindow;
  j["mis_levels"] = misHeuristicName(r.levelHeuristic);
  j["init"] = r.init == InitKind::Annealing ? "annealing" : "resample";
  if (r.perLevel) j["per_level"] = true;
  addChainSettingsJson(s, j);
}

}  // namespace relt
