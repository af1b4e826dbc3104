#include "integrators/option_checks.h"

#include <cmath>

namespace relt {

CLI::Validator finiteNumber(const std::function<bool(double)>& accepts, const std::string& range) {
  return CLI::Validator(
      [accepts, range](std::string& text) {
        double v = std::nan("");
        try {
          v = std::stod(text);
        } catch (const std::exception&) {
        }
        return std::isfinite(v) && accepts(v) ? std::string() : "must be a number " + range + ", got " + text;
      },
      range);
}

CLI::Validator positiveNumber() { return finiteNumber([](double v) { return v > 0.0; }, "> 0"); }

CLI::Validator finiteIn(double lo, double hi) {
  return finiteNumber([lo, hi](double v) { return v >= lo && v <= hi; },
                      "in [" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]");
}

}  // namespace relt
