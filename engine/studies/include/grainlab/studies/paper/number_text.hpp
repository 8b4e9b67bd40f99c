#pragma once
// Numbers as text, for the CSV cells, the findings' notes and the charts' labels alike.
#include <string>

namespace grainlab::report {

/// `value` with `decimals` digits after the point ("-" for NaN or infinity, "-0" never).
std::string fixed(double value, int decimals);

/// `value` with `digits` significant digits, shortest form (%g); "" for NaN or infinity, so a
/// CSV cell is empty rather than "nan".
std::string general(double value, int digits = 10);

}  // namespace grainlab::report
