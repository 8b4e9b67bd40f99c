#include "grainlab/histogram_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "grainlab/analysis/histogram.hpp"
#include "grainlab/state_archive.hpp"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

// Round-trip precision, as series.csv writes its numbers.
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

std::string histogramsHeader() { return "stage,sample,quantity,bin,value"; }

HistogramWriter::HistogramWriter(std::string directory)
    : path_((fs::path(std::move(directory)) / "histograms.csv").string()) {}

void HistogramWriter::append(const std::string& text) {
  file_ << text;
  file_.flush();
  if (!file_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

void HistogramWriter::onStart(const Scene&, const World&) {
  fs::create_directories(fs::path(path_).parent_path());
  file_.open(path_, std::ios::binary | std::ios::trunc);
  if (!file_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
  samples_ = 0;
  append(histogramsHeader() + '\n');
}

void HistogramWriter::onSample(const Sample& sample, const World&) {
  const std::int64_t index = samples_++;
  const analysis::PolarHistograms* h = sample.histograms;
  if (h == nullptr || h->ends == 0) return;
  const std::string prefix = sample.stage + "," + std::to_string(index) + ",";
  std::string text;
  auto row = [&](const char* quantity, int bin, const std::string& value) {
    text += prefix + quantity + "," + std::to_string(bin) + "," + value + "\n";
  };
  const double scale = static_cast<double>(h->bins) / static_cast<double>(h->ends);
  const struct {
    const char* name;
    const char* fitName;
    const std::vector<double>* means;  // null: the density, from the counts
    const analysis::FourierFit* fit;
  } quantities[] = {{"density", "density_fit", nullptr, &h->density}, {"fn", "fn_fit", &h->fn, &h->fnFit},
                    {"ft", "ft_fit", &h->ft, &h->ftFit},              {"ln", "ln_fit", &h->ln, &h->lnFit},
                    {"lt", "lt_fit", &h->lt, &h->ltFit}};
  for (int b = 0; b < h->bins; ++b) row("count", b, std::to_string(h->count[static_cast<size_t>(b)]));
  for (const auto& q : quantities) {
    for (int b = 0; b < h->bins; ++b) {
      const auto k = static_cast<size_t>(b);
      if (q.means == nullptr)
        row(q.name, b, num(scale * static_cast<double>(h->count[k])));
      else
        row(q.name, b, h->count[k] == 0 ? std::string() : num((*q.means)[k]));
    }
    for (int b = 0; b < h->bins; ++b) row(q.fitName, b, num(q.fit->value(h->binCentreDeg(b))));
  }
  append(text);
}

void HistogramWriter::persistOutput(StateArchive& a) {
  a.section("histograms.csv");
  if (!a.loading()) {
    file_.flush();
    if (!file_) throw std::runtime_error("cannot write " + path_);
    bytes_ = static_cast<std::uint64_t>(file_.tellp());
    // The rows up to here must outlive a crash as surely as the checkpoint that counts them.
    const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
      const std::string why = std::strerror(errno);
      if (fd >= 0) ::close(fd);
      throw std::runtime_error("cannot flush " + path_ + " to disk: " + why);
    }
    ::close(fd);
  }
  a(bytes_);
  a(samples_);
}

void HistogramWriter::onResume(const Scene&, const World&) {
  std::error_code ec;
  const auto size = fs::file_size(path_, ec);
  if (ec || size < bytes_) {
    throw std::runtime_error(path_ + " is shorter than when the checkpoint was written (" +
                             std::to_string(ec ? 0 : size) + " of " + std::to_string(bytes_) +
                             " bytes): it cannot be continued");
  }
  fs::resize_file(path_, bytes_);
  file_.open(path_, std::ios::binary | std::ios::app);
  if (!file_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

void HistogramWriter::onFinish(const RunSummary&, const World&) { file_.close(); }

}  // namespace grainlab
