#pragma once
// An enum's names as they appear in JSON, files and the API: one table of (value, name)
// pairs per enum, looked up both ways.
#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace grainlab {

template <class Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, std::string_view>, N>;

/// The value's name, or "unknown" for a value the table does not list.
template <class Enum, std::size_t N>
constexpr std::string_view nameIn(const NameTable<Enum, N>& table, Enum value) {
  for (const auto& [v, name] : table) {
    if (v == value) return name;
  }
  return "unknown";
}

/// The value a name gives; nothing for any other string.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> valueIn(const NameTable<Enum, N>& table, std::string_view name) {
  for (const auto& [v, n] : table) {
    if (n == name) return v;
  }
  return std::nullopt;
}

}  // namespace grainlab
