#include "static_files.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace grainlab::server {
namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

ApiResponse plain(int status, const std::string& text) {
  ApiResponse r;
  r.status = status;
  r.contentType = "text/plain; charset=utf-8";
  r.body = text + "\n";
  return r;
}

}  // namespace

std::string_view mimeType(std::string_view path) {
  const auto dot = path.rfind('.');
  if (dot == std::string_view::npos) return "application/octet-stream";
  const auto ext = lower(path.substr(dot + 1));
  if (ext == "html" || ext == "htm") return "text/html; charset=utf-8";
  if (ext == "js" || ext == "mjs") return "text/javascript; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "json" || ext == "map") return "application/json";
  if (ext == "txt" || ext == "md") return "text/plain; charset=utf-8";
  if (ext == "csv") return "text/csv; charset=utf-8";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "png") return "image/png";
  if (ext == "jpg" || ext == "jpeg") return "image/jpeg";
  if (ext == "gif") return "image/gif";
  if (ext == "ico") return "image/vnd.microsoft.icon";
  if (ext == "webp") return "image/webp";
  if (ext == "woff") return "font/woff";
  if (ext == "woff2") return "font/woff2";
  if (ext == "wasm") return "application/wasm";
  return "application/octet-stream";
}

std::optional<std::string> percentDecode(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '%') {
      if (i + 2 >= text.size()) return std::nullopt;
      const int hi = hexValue(text[i + 1]), lo = hexValue(text[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    }
    if (c == '\0') return std::nullopt;
    out += c;
  }
  return out;
}

ApiResponse StaticFiles::get(const std::string& path, bool head) const {
  if (path.empty() || path.front() != '/' || path.find('\\') != std::string::npos)
    return plain(400, "illegal path");
  // Refuse ".." as a segment anywhere (after decoding, which the caller has done).
  std::string_view rest(path);
  while (!rest.empty()) {
    rest.remove_prefix(1);
    const auto slash = rest.find('/');
    const auto segment = rest.substr(0, slash);
    if (segment == "..") return plain(400, "illegal path: it leaves the web root");
    if (slash == std::string_view::npos) break;
    rest.remove_prefix(slash);
  }
  std::filesystem::path file = std::filesystem::path(root_) / path.substr(1);
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) file /= "index.html";
  if (!std::filesystem::is_regular_file(file, ec)) return plain(404, "not found: " + path);

  std::ifstream in(file, std::ios::binary);
  if (!in) return plain(404, "not found: " + path);
  std::ostringstream content;
  content << in.rdbuf();
  ApiResponse r;
  r.status = 200;
  r.contentType = std::string(mimeType(file.filename().string()));
  r.body = std::move(content).str();
  r.headOnly = head;
  // The dashboard changes while developers work on it: revalidate rather than cache stale code.
  r.headers.emplace_back("Cache-Control", "no-cache");
  return r;
}

}  // namespace grainlab::server
