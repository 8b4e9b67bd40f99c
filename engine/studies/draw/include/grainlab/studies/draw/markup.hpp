#pragma once
// Escaping for the SVG and HTML writers.
#include <string>
#include <string_view>

namespace grainlab::report {

/// `text` with &, <, >, " and ' replaced by entities: safe inside XML/HTML text and attributes.
std::string escapeMarkup(std::string_view text);

}  // namespace grainlab::report
