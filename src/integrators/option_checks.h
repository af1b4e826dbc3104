#pragma once
// Checks of option values that CLI11 lacks: CLI::Range lets NaN through and CLI::PositiveNumber
// names its range up to the largest double.
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace relt {

// A finite number that `accepts` takes, described as `range` ("> 0").
CLI::Validator finiteNumber(const std::function<bool(double)>& accepts, const std::string& range);
// A finite number > 0.
CLI::Validator positiveNumber();
// A finite number in [lo, hi].
CLI::Validator finiteIn(double lo, double hi);

}  // namespace relt
