#include "json_reader.hpp"

#include <cmath>
#include <sstream>

namespace grainlab {
namespace {

thread_local KeyReadSink* keyReadSink = nullptr;

std::string describe(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

KeyReadScope::KeyReadScope(KeyReadSink& sink) : previous_(keyReadSink) { keyReadSink = &sink; }
KeyReadScope::~KeyReadScope() { keyReadSink = previous_; }

void JsonReader::report(const std::string& key, const char* kind, nlohmann::json fallback, double min, double max,
                        bool openMin, bool openMax, bool bounded, const std::set<std::string>& choices) const {
  if (!keyReadSink) return;
  KeyRead read{fieldPath(key), kind, std::move(fallback), min, max, openMin, openMax, bounded, choices,
               has(key) ? object_.at(key) : nlohmann::json()};
  keyReadSink->keyRead(read);
}

JsonReader::JsonReader(const nlohmann::json& object, std::string path) : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) throw SceneError(path_.empty() ? "(scene)" : path_, "must be a JSON object");
}

const nlohmann::json& JsonReader::at(const std::string& key) {
  read_.insert(key);
  return object_.at(key);
}

const nlohmann::json& JsonReader::raw(const std::string& key) {
  static const nlohmann::json null;
  report(key, "raw", nullptr);
  read_.insert(key);
  return has(key) ? object_.at(key) : null;
}

double JsonReader::number(const std::string& key, double fallback, double min, double max, bool openMin, bool openMax) {
  report(key, "number", fallback, min, max, openMin, openMax, true);
  if (!has(key)) { read_.insert(key); return fallback; }
  const nlohmann::json& v = at(key);
  if (!v.is_number()) throw SceneError(fieldPath(key), "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw SceneError(fieldPath(key), "must be finite");
  const bool below = openMin ? x <= min : x < min;
  const bool above = openMax ? x >= max : x > max;
  if (below || above) {
    std::string range = std::string(openMin ? "(" : "[") + describe(min) + ", " + describe(max) + (openMax ? ")" : "]");
    if (std::isinf(max)) range = std::string(openMin ? "> " : ">= ") + describe(min);
    throw SceneError(fieldPath(key), "must be " + range + ", got " + describe(x));
  }
  return x;
}

long long JsonReader::integer(const std::string& key, long long fallback, long long min, long long max) {
  report(key, "integer", fallback, static_cast<double>(min), static_cast<double>(max), false, false, true);
  if (!has(key)) { read_.insert(key); return fallback; }
  const nlohmann::json& v = at(key);
  if (!v.is_number_integer()) throw SceneError(fieldPath(key), "must be an integer");
  const long long x = v.get<long long>();
  if (x < min || x > max) {
    throw SceneError(fieldPath(key), "must be between " + std::to_string(min) + " and " + std::to_string(max) +
                                         ", got " + std::to_string(x));
  }
  return x;
}

bool JsonReader::boolean(const std::string& key, bool fallback) {
  report(key, "boolean", fallback);
  if (!has(key)) { read_.insert(key); return fallback; }
  const nlohmann::json& v = at(key);
  if (!v.is_boolean()) throw SceneError(fieldPath(key), "must be true or false");
  return v.get<bool>();
}

std::string JsonReader::string(const std::string& key, const std::string& fallback) {
  report(key, "string", fallback);
  if (!has(key)) { read_.insert(key); return fallback; }
  const nlohmann::json& v = at(key);
  if (!v.is_string()) throw SceneError(fieldPath(key), "must be a string");
  return v.get<std::string>();
}

std::string JsonReader::choice(const std::string& key, const std::string& fallback, const std::set<std::string>& choices) {
  const std::string s = string(key, fallback);
  report(key, "choice", fallback, 0, 0, false, false, false, choices);
  if (!choices.count(s)) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    throw SceneError(fieldPath(key), "must be one of " + list + ", got \"" + s + "\"");
  }
  return s;
}

Vec2 JsonReader::vec2(const std::string& key, const Vec2& fallback) {
  report(key, "vec2", nlohmann::json::array({fallback.x(), fallback.y()}));
  if (!has(key)) { read_.insert(key); return fallback; }
  return parseVec2(at(key), fieldPath(key));
}

void JsonReader::finish() const {
  for (const auto& item : object_.items()) {
    if (!read_.count(item.key())) throw SceneError(fieldPath(item.key()), "unknown key");
  }
}

Vec2 parseVec2(const nlohmann::json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
    throw SceneError(path, "must be a pair of numbers [x, y]");
  }
  const Vec2 v(value[0].get<double>(), value[1].get<double>());
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) throw SceneError(path, "must be finite");
  return v;
}

}  // namespace grainlab
