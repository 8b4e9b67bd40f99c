#pragma once
// Reads one JSON object field by field, naming each field by its path in errors, and
// refusing keys it was never asked about (unknown keys are an error, not silently ignored).
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/math.hpp"

namespace grainlab {

/// One key a JsonReader was asked about, as the scene-key catalogue records it
/// (engine/src/scene_keys.cpp). `value` is the key's value in the JSON read (null if absent).
struct KeyRead {
  std::string path;  ///< the key's full path, e.g. "stages[2].strain_rate"
  std::string kind;  ///< number, integer, boolean, string, choice, vec2 or raw
  nlohmann::json fallback;
  double min = 0, max = 0;
  bool openMin = false, openMax = false, bounded = false;
  std::set<std::string> choices;
  nlohmann::json value;
};

/// Receives every key every JsonReader on this thread reads while a KeyReadScope is alive.
class KeyReadSink {
 public:
  virtual ~KeyReadSink() = default;
  virtual void keyRead(const KeyRead& read) = 0;
};

/// While alive, reports the keys read on this thread to `sink` (parsing only: no run reads keys).
class KeyReadScope {
 public:
  explicit KeyReadScope(KeyReadSink& sink);
  ~KeyReadScope();
  KeyReadScope(const KeyReadScope&) = delete;
  KeyReadScope& operator=(const KeyReadScope&) = delete;

 private:
  KeyReadSink* previous_;
};

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
  void report(const std::string& key, const char* kind, nlohmann::json fallback, double min = 0, double max = 0,
              bool openMin = false, bool openMax = false, bool bounded = false,
              const std::set<std::string>& choices = {}) const;
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
};

/// A JSON [x, y] pair of finite numbers.
Vec2 parseVec2(const nlohmann::json& value, const std::string& path);

}  // namespace grainlab
