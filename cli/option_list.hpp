#pragma once
// A command-line option's comma-separated list ("a,b,c"), empty items dropped.
#include <sstream>
#include <string>
#include <vector>

namespace grainlab {

inline std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

}  // namespace grainlab
