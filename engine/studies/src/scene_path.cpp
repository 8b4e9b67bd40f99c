#include "grainlab/studies/scene_path.hpp"

#include <charconv>
#include <stdexcept>
#include <vector>

namespace grainlab::studies {
namespace {

std::vector<std::string> segments(std::string_view path) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t dot = path.find('.', start);
    const std::string_view seg = path.substr(start, dot == std::string_view::npos ? path.size() - start : dot - start);
    if (seg.empty()) throw std::invalid_argument("empty segment in the path \"" + std::string(path) + "\"");
    out.emplace_back(seg);
    if (dot == std::string_view::npos) return out;
    start = dot + 1;
  }
}

bool isIndex(const std::string& seg) { return seg.find_first_not_of("0123456789") == std::string::npos; }

size_t arrayIndex(const nlohmann::json& array, const std::string& seg, const std::string& where) {
  size_t index = 0;
  const auto [end, ec] = std::from_chars(seg.data(), seg.data() + seg.size(), index);
  if (!isIndex(seg) || ec != std::errc() || end != seg.data() + seg.size())
    throw std::invalid_argument(where + " is an array: index it with a number, not \"" + seg + "\"");
  if (index >= array.size())
    throw std::invalid_argument("index " + seg + " is out of range: " + where + " has " + std::to_string(array.size()) +
                                " entries");
  return index;
}

}  // namespace

void setAtPath(nlohmann::json& scene, std::string_view path, const nlohmann::json& value) {
  const std::vector<std::string> segs = segments(path);
  nlohmann::json* node = &scene;
  std::string walked;  // the dotted path up to `node`
  for (size_t k = 0; k < segs.size(); ++k) {
    const std::string& seg = segs[k];
    const bool last = k + 1 == segs.size();
    const std::string where = walked.empty() ? "the scene" : sceneFieldName(walked);
    if (node->is_array()) {
      node = &(*node)[arrayIndex(*node, seg, where)];
    } else if (node->is_object() || node->is_null()) {
      if (!last && !node->contains(seg)) (*node)[seg] = nlohmann::json::object();
      node = &(*node)[seg];
    } else {
      throw std::invalid_argument(where + " is a " + std::string(node->type_name()) + ", not an object or an array");
    }
    if (last) *node = value;
    walked += (k ? "." : "") + seg;
  }
}

std::string sceneFieldName(std::string_view path) {
  std::string out;
  for (const std::string& seg : segments(path)) {
    if (isIndex(seg) && !out.empty()) out += "[" + seg + "]";
    else out += (out.empty() ? "" : ".") + seg;
  }
  return out;
}

}  // namespace grainlab::studies
