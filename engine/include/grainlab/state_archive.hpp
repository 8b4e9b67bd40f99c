#pragma once
// The binary image of a run's state, for checkpoints. One `persist(StateArchive&)` per class
// lists its state once; the same function saves it and loads it back, so the two directions
// cannot drift apart. Values are copied bit for bit (doubles included): a run resumed from
// an archive continues exactly as if it had never stopped.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "grainlab/math.hpp"

namespace grainlab {

/// A checkpoint that cannot be read: truncated, corrupt, or from another format version.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateArchive {
 public:
  /// An empty archive to save into.
  StateArchive() = default;
  /// An archive to load from `bytes` (which must outlive it).
  explicit StateArchive(std::string_view bytes) : loading_(true), in_(bytes) {}

  bool loading() const { return loading_; }
  /// What has been saved so far.
  const std::string& bytes() const { return out_; }

  /// A plain value (number, enum, bool, or a struct of them), bit for bit.
  template <class T>
    requires std::is_trivially_copyable_v<T>
  void operator()(T& value) {
    raw(&value, sizeof(T));
  }
  /// A flag: one byte, 0 or 1 (any other byte would load as a bool that is neither).
  void operator()(bool& b) {
    unsigned char byte = b ? 1 : 0;
    raw(&byte, 1);
    if (loading_ && byte > 1) throw CheckpointError("checkpoint: a flag is " + std::to_string(byte) + ", neither 0 nor 1");
    b = byte == 1;
  }
  void operator()(Vec2& v) {
    (*this)(v.x());
    (*this)(v.y());
  }
  void operator()(std::string& s) {
    std::uint64_t n = s.size();
    (*this)(n);
    if (loading_) {
      need(n);
      s.assign(in_.data() + at_, n);
      at_ += n;
    } else {
      out_.append(s);
    }
  }
  /// A vector of plain values, or of anything with an overload above.
  template <class T>
  void operator()(std::vector<T>& v) {
    std::uint64_t n = v.size();
    (*this)(n);
    if (loading_) {
      need(n);  // each element takes at least a byte: a corrupt count cannot allocate wildly
      v.resize(n);
    }
    if constexpr (std::is_trivially_copyable_v<T>) {
      if (n) raw(v.data(), n * sizeof(T));
    } else {
      for (T& x : v) (*this)(x);
    }
  }
  /// A plain struct that holds Eigen fixed-size vectors: they are arrays of doubles, but
  /// Eigen declares their copy operations, so the language does not call them trivially
  /// copyable. Copied bit for bit like the plain values above.
  template <class T>
    requires(std::is_standard_layout_v<T> && std::is_trivially_destructible_v<T>)
  void bitwise(T& value) {
    raw(&value, sizeof(T));
  }
  template <class T>
    requires(std::is_standard_layout_v<T> && std::is_trivially_destructible_v<T>)
  void bitwise(std::vector<T>& v) {
    std::uint64_t n = v.size();
    (*this)(n);
    if (loading_) {
      need(n);
      v.resize(n);
    }
    if (n) raw(v.data(), n * sizeof(T));
  }
  /// Any class with a `persist(StateArchive&)` member.
  template <class T>
    requires requires(T& t, StateArchive& a) { t.persist(a); }
  void operator()(T& value) {
    value.persist(*this);
  }

  /// A named mark between sections: loading checks it, so a layout that differs (a
  /// different build, a scene that is not the one the checkpoint came from) is reported at
  /// the section where it starts rather than read as garbage.
  void section(std::string_view name) {
    std::string mark(name);
    if (!loading_) return (*this)(mark);
    std::string found;
    (*this)(found);
    if (found != mark) throw CheckpointError("checkpoint: expected section '" + mark + "', found '" + found.substr(0, 40) + "'");
  }
  /// A value the run already has, rebuilt from its scene (a particle count, a scale): saved,
  /// and on loading checked to be the same, so a checkpoint is never applied to another scene.
  template <class T>
    requires std::is_trivially_copyable_v<T>
  void same(const T& value, const std::string& what) {
    T stored = value;
    (*this)(stored);
    require(std::memcmp(&stored, &value, sizeof(T)) == 0, what + " differs from the scene's: the checkpoint belongs to another run");
  }
  /// Loading: throws unless every byte was read.
  void expectEnd() const {
    if (loading_ && at_ != in_.size()) throw CheckpointError("checkpoint: " + std::to_string(in_.size() - at_) + " bytes left over");
  }
  /// Loading: throws with `what` unless `ok` (a loaded value that contradicts the run).
  void require(bool ok, const std::string& what) const {
    if (loading_ && !ok) throw CheckpointError("checkpoint: " + what);
  }

 private:
  void need(std::uint64_t n) const {
    if (n > in_.size() - at_) throw CheckpointError("checkpoint: truncated");
  }
  void raw(void* p, std::size_t n) {
    if (loading_) {
      need(n);
      std::memcpy(p, in_.data() + at_, n);
      at_ += n;
    } else {
      out_.append(static_cast<const char*>(p), n);
    }
  }

  bool loading_ = false;
  std::string out_;
  std::string_view in_;
  std::size_t at_ = 0;
};

}  // namespace grainlab
