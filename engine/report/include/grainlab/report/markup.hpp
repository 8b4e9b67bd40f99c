#pragma once
// Text helpers shared by the SVG, HTML and CSV writers: escaping and number formatting.
#include <string>
#include <string_view>

namespace grainlab::report {

/// `text` with &, <, >, " and ' replaced by entities: safe inside XML/HTML text and attributes.
std::string escapeMarkup(std::string_view text);

/// `value` with `decimals` digits after the point ("-" for NaN or infinity, "-0" never).
std::string fixed(double value, int decimals);

/// `value` with `digits` significant digits, shortest form (%g); "" for NaN or infinity, so a
/// CSV cell is empty rather than "nan".
std::string general(double value, int digits = 10);

}  // namespace grainlab::report
