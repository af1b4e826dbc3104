#pragma once
// An integrator's own settings (relt's ladder, erpt's chain length), of a type its folder under
// src/integrators/ defines, held in RenderSettings without render/ knowing the type. The options
// several integrators share stay fields of RenderSettings.
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>

namespace relt {

class IntegratorSettings {
 public:
  virtual ~IntegratorSettings() = default;
  virtual std::unique_ptr<IntegratorSettings> clone() const = 0;
};

// Derive an integrator's settings from this: struct ReltSettings final : SettingsOf<ReltSettings>.
template <class Derived>
class SettingsOf : public IntegratorSettings {
 public:
  std::unique_ptr<IntegratorSettings> clone() const override {
    return std::make_unique<Derived>(static_cast<const Derived&>(*this));
  }
};

// One integrator's settings, copied with RenderSettings; empty for an integrator without any.
class OwnSettings {
 public:
  OwnSettings() = default;
  explicit OwnSettings(std::unique_ptr<IntegratorSettings> settings) : settings_(std::move(settings)) {}
  OwnSettings(const OwnSettings& o) : settings_(o.settings_ ? o.settings_->clone() : nullptr) {}
  OwnSettings(OwnSettings&&) noexcept = default;
  OwnSettings& operator=(const OwnSettings& o) { return *this = OwnSettings(o); }
  OwnSettings& operator=(OwnSettings&&) noexcept = default;

  // The settings as the integrator's type; throws std::logic_error when they are of another (the
  // settings name another integrator).
  template <class T>
  T& get() {
    T* t = dynamic_cast<T*>(settings_.get());
    if (!t) throw std::logic_error(std::string("the settings hold no ") + typeid(T).name());
    return *t;
  }
  template <class T>
  const T& get() const {
    return const_cast<OwnSettings*>(this)->get<T>();
  }

 private:
  std::unique_ptr<IntegratorSettings> settings_;
};

}  // namespace relt
