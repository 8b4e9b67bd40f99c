#pragma once
// Where the server's tokens come from (docs/security.md): a file (--token-file,
// --read-only-token-file) or the environment (GRAINLAB_TOKEN, GRAINLAB_READ_ONLY_TOKEN),
// never the command line, where `ps` shows it to every user of the machine. Bound to an
// address other machines can reach with no token given, the server makes one.
#include <functional>
#include <string>

#include "grainlab/server/serve.hpp"

namespace grainlab::server {

struct AccessTokens {
  std::string full;      ///< empty: no token asked (loopback only)
  std::string readOnly;  ///< empty: none
  bool generated = false;
};

/// Reads `environment("GRAINLAB_TOKEN")` and the like; std::getenv in the server.
using Environment = std::function<const char*(const char*)>;

/// Throws std::invalid_argument naming the option and the reason (an unreadable or empty
/// file, a token with characters a cookie cannot carry, a read-only token equal to the full
/// one).
AccessTokens loadAccessTokens(const ServeOptions& options, const Environment& environment);

/// 32 random bytes from the kernel, as 64 hex digits.
std::string randomToken();

}  // namespace grainlab::server
