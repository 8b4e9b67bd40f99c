#include "access_tokens.hpp"

#include <sys/random.h>
#include <sys/stat.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "access_policy.hpp"

namespace grainlab::server {
namespace {

// Printable ASCII a cookie value and a URL query carry as they are.
void checkCharacters(const std::string& token, const std::string& source) {
  if (token.size() < 16) throw std::invalid_argument(source + ": the token is shorter than 16 characters");
  for (const char c : token) {
    const bool ok = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '-' ||
                    c == '_' || c == '.' || c == '~';
    if (!ok) throw std::invalid_argument(source + ": a token may hold only letters, digits and - _ . ~");
  }
}

std::string readTokenFile(const std::string& path, const std::string& option) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(option + " " + path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  std::string token = text.str();
  while (!token.empty() && (token.back() == '\n' || token.back() == '\r' || token.back() == ' ')) token.pop_back();
  if (token.empty()) throw std::invalid_argument(option + " " + path + ": the file is empty");
  checkCharacters(token, option + " " + path);
  // Said, not refused: a shared machine's other users could read it.
  if (struct stat st{}; ::stat(path.c_str(), &st) == 0 && (st.st_mode & (S_IRWXG | S_IRWXO)))
    std::cerr << "grainlab serve: warning: " << path << " is readable by other users (chmod 600 it)\n";
  return token;
}

std::string fromFileOrEnvironment(const std::string& file, const std::string& option, const char* variable,
                                  const Environment& environment) {
  if (!file.empty()) return readTokenFile(file, option);
  const char* value = environment ? environment(variable) : nullptr;
  if (value == nullptr || *value == '\0') return {};
  checkCharacters(value, variable);
  return value;
}

}  // namespace

std::string randomToken() {
  unsigned char bytes[32];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const auto n = ::getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0) throw std::runtime_error("no random bytes from the kernel for a token");
    got += static_cast<std::size_t>(n);
  }
  static constexpr char hex[] = "0123456789abcdef";
  std::string token;
  for (const unsigned char b : bytes) {
    token += hex[b >> 4];
    token += hex[b & 15];
  }
  return token;
}

AccessTokens loadAccessTokens(const ServeOptions& options, const Environment& environment) {
  AccessTokens tokens;
  tokens.full = fromFileOrEnvironment(options.tokenFile, "--token-file", "GRAINLAB_TOKEN", environment);
  tokens.readOnly =
      fromFileOrEnvironment(options.readOnlyTokenFile, "--read-only-token-file", "GRAINLAB_READ_ONLY_TOKEN", environment);
  if (!tokens.readOnly.empty() && tokens.readOnly == tokens.full)
    throw std::invalid_argument("--read-only-token-file: the read-only token is the full token");
  // Reachable from other machines, or a read-only token to tell apart from full access:
  // a full token there must be, made now if none was given.
  if (tokens.full.empty() && (!isLoopbackAddress(options.host) || !tokens.readOnly.empty())) {
    tokens.full = randomToken();
    tokens.generated = true;
  }
  return tokens;
}

}  // namespace grainlab::server
