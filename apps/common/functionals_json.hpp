#pragma once
/// \file functionals_json.hpp
/// The chapter's functionals as a JSON object, keys as the CSV columns
/// (min_distance_m, bottom_y_m, ..., mass_error), values in SI units.
#include <fsi/state.hpp>
#include <nlohmann/json.hpp>

namespace fsi::app {

nlohmann::ordered_json functionals_json(const Functionals& f);

/// A double as JSON; NaN and infinities (not JSON) become null.
nlohmann::ordered_json number_json(double value);

}  // namespace fsi::app
