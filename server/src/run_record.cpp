#include "run_record.hpp"

namespace grainlab::server::status {

bool isTerminal(const std::string& s) {
  return s == kCompleted || s == kFailed || s == kCancelled || s == kInterrupted;
}

}  // namespace grainlab::server::status
