#include "integrators/registry.h"

#include <algorithm>
#include <stdexcept>

#include "core/error.h"
#include "integrators/bdpt/bdpt_integrator.h"
#include "integrators/erpt/erpt_integrator.h"
#include "integrators/meb/meb_integrator.h"
#include "integrators/mmlt/mmlt_integrator.h"
#include "integrators/pssmlt/pssmlt_integrator.h"
#include "integrators/pt/pt_integrator.h"
#include "integrators/relt/relt_integrator.h"
#include "integrators/shared_options.h"
#include "integrators/vcm/vcm_integrator.h"

namespace relt {
namespace {

std::vector<const IntegratorEntry*>& entries() {
  static std::vector<const IntegratorEntry*> all = {
      &ptIntegrator(),
      &bdptIntegrator(),
      &pssmltIntegrator(),
      &mmltIntegrator(),
      &erptIntegrator(),
      &reltIntegrator(),
      &vcmIntegrator(),
      &mebIntegrator(),
  };
  return all;
}

// The long names of what `add` registers on a command of its own.
template <typename Add>
std::vector<std::string> optionNames(const Add& add) {
  CLI::App scratch;
  add(scratch);
  std::vector<std::string> names;
  for (const CLI::Option* option : scratch.get_options())
    if (option->get_name() != "--help") names.push_back(option->get_name());
  return names;
}

// Every option some integrator names or registers, in that order, with the integrators that take
// it; built again when an integrator is registered.
struct OptionTable {
  size_t integrators = 0;
  std::vector<std::pair<std::string, std::vector<const IntegratorEntry*>>> takers;
};

const OptionTable& optionTable() {
  static OptionTable table;
  if (table.integrators == entries().size()) return table;
  table = {entries().size(), {}};
  auto take = [&](const std::string& option, const IntegratorEntry* entry) {
    auto row = std::find_if(table.takers.begin(), table.takers.end(), [&](const auto& r) { return r.first == option; });
    if (row == table.takers.end()) row = table.takers.insert(row, {option, {}});
    if (entry && std::find(row->second.begin(), row->second.end(), entry) == row->second.end())
      row->second.push_back(entry);
  };
  RenderSettings scratchSettings;
  for (const std::string& option : optionNames([&](CLI::App& cmd) { addSharedOptions(cmd, scratchSettings); }))
    take(option, nullptr);
  for (const IntegratorEntry* entry : entries()) {
    for (const std::string& option : entry->sharedOptions) take(option, entry);
    if (!entry->addOptions) continue;
    const std::unique_ptr<IntegratorSettings> own = entry->makeSettings();
    for (const std::string& option : optionNames([&](CLI::App& cmd) { entry->addOptions(cmd, *own); }))
      take(option, entry);
  }
  return table;
}

std::string namesOf(const std::vector<const IntegratorEntry*>& users) {
  std::string names;
  for (size_t i = 0; i < users.size(); ++i) {
    if (i > 0) names += i + 1 == users.size() ? " and " : ", ";
    names += users[i]->kind.name;
  }
  return names;
}

}  // namespace

const std::vector<const IntegratorEntry*>& integrators() { return entries(); }

const IntegratorEntry* findIntegrator(const std::string& name) {
  for (const IntegratorEntry* entry : entries())
    if (entry->kind.name == name) return entry;
  return nullptr;
}

void registerIntegrator(const IntegratorEntry& entry) {
  if (findIntegrator(entry.kind.name)) throw std::invalid_argument("integrator '" + entry.kind.name + "' exists");
  entries().push_back(&entry);
}

void selectIntegrator(RenderSettings& settings, const std::string& name, SettingsDrafts* drafts) {
  const IntegratorEntry* entry = findIntegrator(name);
  if (!entry) throw std::invalid_argument("no integrator named '" + name + "'");
  settings.integrator = entry->kind;
  std::unique_ptr<IntegratorSettings> own;
  if (drafts && drafts->count(name)) own = std::move(drafts->at(name));
  else if (entry->makeSettings) own = entry->makeSettings();
  settings.own = OwnSettings(std::move(own));
}

void addIntegratorOptions(CLI::App& command, RenderSettings& settings, SettingsDrafts& drafts) {
  addSharedOptions(command, settings);
  for (const IntegratorEntry* entry : entries()) {
    if (!entry->makeSettings) continue;
    std::unique_ptr<IntegratorSettings>& own = drafts[entry->kind.name] = entry->makeSettings();
    if (entry->addOptions) entry->addOptions(command, *own);
  }
}

std::vector<std::string> optionsNotForEveryIntegrator() {
  std::vector<std::string> names;
  for (const auto& [option, takers] : optionTable().takers) names.push_back(option);
  return names;
}

std::optional<std::string> unusedOptionReason(const std::string& option, const IntegratorEntry& integrator) {
  for (const auto& [name, takers] : optionTable().takers) {
    if (name != option) continue;
    if (std::find(takers.begin(), takers.end(), &integrator) != takers.end()) return std::nullopt;
    std::string reason = "only for --integrator " + namesOf(takers);
    if (const char* hint = sharedOptionHint(option)) reason += std::string(" (") + hint + ")";
    return reason;
  }
  return std::nullopt;  // every integrator's
}

void validateIntegratorOptions(RenderSettings& settings, const GivenOptions& given) {
  const IntegratorEntry* entry = findIntegrator(settings.integrator.name);
  if (!entry) throw InputError("", "--integrator", "no integrator named '" + settings.integrator.name + "'");
  for (const std::string& option : given)
    if (const auto why = unusedOptionReason(option, *entry)) throw InputError("", option, *why);
  validateSharedOptions(settings);
  if (entry->validate) entry->validate(settings, given);
}

}  // namespace relt
