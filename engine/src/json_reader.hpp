#pragma once
// Reads one JSON object field by field, naming each field by its path in errors, and
// refusing keys it was never asked about (unknown keys are an error, not silently ignored).
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/math.hpp"

namespace grainlab {

class JsonReader {
 public:
  JsonReader(const nlohmann::json& object, std::string path);

  bool has(const std::string& key) const { return object_.contains(key); }
  std::string fieldPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  /// A finite number in [min, max] (bounds inclusive unless the `open` flags say otherwise).
  double number(const std::string& key, double fallback, double min, double max,
                bool openMin = false, bool openMax = false);
  long long integer(const std::string& key, long long fallback, long long min, long long max);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  /// One of `choices`.
  std::string choice(const std::string& key, const std::string& fallback, const std::set<std::string>& choices);
  Vec2 vec2(const std::string& key, const Vec2& fallback);
  /// The raw value (marks the key as read); null if absent.
  const nlohmann::json& raw(const std::string& key);

  /// Throws for any key that was never read.
  void finish() const;

 private:
  const nlohmann::json& at(const std::string& key);
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
};

/// A JSON [x, y] pair of finite numbers.
Vec2 parseVec2(const nlohmann::json& value, const std::string& path);

}  // namespace grainlab
