#include "grainlab/analysis/histogram.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/contact_ends.hpp"

namespace grainlab::analysis {

namespace {

void checkBins(int bins) {
  if (bins < kMinHistogramBins || bins > kMaxHistogramBins)
    throw std::invalid_argument("histogram bins must be in [" + std::to_string(kMinHistogramBins) +
                                ", " + std::to_string(kMaxHistogramBins) + "], got " +
                                std::to_string(bins));
}

// Least squares of c0 + c1 cos 2θ + c2 sin 2θ through the bin centres, one equal weight per
// used bin. With every bin used the normal matrix is diagonal (equally spaced 2θ), and this
// is the discrete Fourier projection; empty bins of a mean have no value and are left out.
template <class Value>
FourierFit fitBins(const PolarHistograms& h, bool skipEmpty, Value&& value) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  int used = 0;
  double sum = 0;
  for (int b = 0; b < h.bins; ++b) {
    if (skipEmpty && h.count[static_cast<size_t>(b)] == 0) continue;
    const double twoTheta = 2.0 * radians(h.binCentreDeg(b));
    const Eigen::Vector3d row(1.0, std::cos(twoTheta), std::sin(twoTheta));
    const double v = value(static_cast<size_t>(b));
    normal += row * row.transpose();
    rhs += row * v;
    sum += v;
    ++used;
  }
  FourierFit fit;
  if (used == 0) return fit;
  // Three distinct directions determine the three coefficients; fewer give only a mean.
  if (used < 3) {
    fit.c0 = sum / used;
    return fit;
  }
  const Eigen::Vector3d c = normal.ldlt().solve(rhs);
  fit.c0 = c[0];
  fit.c1 = c[1];
  fit.c2 = c[2];
  return fit;
}

void setTerm(std::complex<double> A, double& a, double& thetaDeg) {
  a = std::abs(A);
  thetaDeg = axialDirectionDeg(A);
}

}  // namespace

double FourierFit::value(double thetaDeg) const {
  const double x = 2.0 * radians(thetaDeg);
  return c0 + c1 * std::cos(x) + c2 * std::sin(x);
}

double FourierFit::amplitude() const { return std::hypot(c1, c2); }

double FourierFit::cosDirectionDeg() const { return axialDirectionDeg({c1, c2}); }

// −a sin 2(θ − θ_k) = a sin 2θ_k cos 2θ − a cos 2θ_k sin 2θ, so c1 + i c2 = −i a e^{2iθ_k}.
double FourierFit::sinDirectionDeg() const { return axialDirectionDeg({-c2, c1}); }

int PolarHistograms::binOf(double thetaDeg) const {
  const int b = static_cast<int>(axialDeg(thetaDeg) / binWidthDeg());
  // Rounding can put 179.9999… into bin `bins`; it belongs to the last bin.
  return b < bins ? b : bins - 1;
}

double PolarHistograms::smoothing() const {
  const double delta = kPi / bins;
  return std::sin(delta) / delta;
}

FabricState PolarHistograms::anisotropy() const {
  using cplx = std::complex<double>;
  const double s = smoothing();
  const cplx I(0, 1);
  FabricState f;
  f.ends = ends;
  f.contacts = contacts;
  if (density.c0 != 0) setTerm(cplx(density.c1, density.c2) / (density.c0 * s), f.a_c, f.theta_c_deg);
  f.f0 = fnFit.c0;
  if (f.f0 != 0) {
    setTerm(cplx(fnFit.c1, fnFit.c2) / (f.f0 * s), f.a_n, f.theta_n_deg);
    setTerm(I * cplx(ftFit.c1, ftFit.c2) / (f.f0 * s), f.a_t, f.theta_t_deg);
    f.a_w_direct = ftFit.c0 / f.f0;
  }
  f.l0 = lnFit.c0;
  if (f.l0 != 0) {
    setTerm(cplx(lnFit.c1, lnFit.c2) / (f.l0 * s), f.a_ln, f.theta_ln_deg);
    setTerm(I * cplx(ltFit.c1, ltFit.c2) / (f.l0 * s), f.a_lt, f.theta_lt_deg);
    f.lt0_ratio = ltFit.c0 / f.l0;
  }
  f.a_w = momentEquilibriumAw(f);
  return f;
}

void measureHistograms(std::span<const ContactRecord> contacts, std::span<const Vec2> centroids,
                       std::span<const unsigned char> inside, PolarHistograms& out, const PeriodicCell* cell) {
  checkBins(out.bins);
  const auto bins = static_cast<size_t>(out.bins);
  // assign keeps the capacity, so a histogram measured at every sample allocates once.
  out.count.assign(bins, 0);
  out.fn.assign(bins, 0.0);
  out.ft.assign(bins, 0.0);
  out.ln.assign(bins, 0.0);
  out.lt.assign(bins, 0.0);
  out.ends = 0;
  out.contacts = 0;

  std::size_t lastContact = std::numeric_limits<std::size_t>::max();
  size_t b = 0;
  forEachInsideEnd(contacts, centroids, inside, [&](const ContactEnd& e) {
    if (e.contact != lastContact) {
      // The folded direction from e^{2iθ}, which both ends of a contact share bit for bit:
      // computed once per contact, and the two ends always land in the same bin.
      b = static_cast<size_t>(out.binOf(0.5 * degrees(std::atan2(e.sin2, e.cos2))));
      ++out.contacts;
      lastContact = e.contact;
    }
    ++out.count[b];
    out.fn[b] += e.fn;
    out.ft[b] += e.ft;
    out.ln[b] += e.ln;
    out.lt[b] += e.lt;
    ++out.ends;
  }, cell);

  for (size_t k = 0; k < bins; ++k) {
    if (out.count[k] == 0) continue;
    const double inv = 1.0 / static_cast<double>(out.count[k]);
    out.fn[k] *= inv;
    out.ft[k] *= inv;
    out.ln[k] *= inv;
    out.lt[k] *= inv;
  }
  if (out.ends > 0) {
    const double scale = static_cast<double>(bins) / static_cast<double>(out.ends);
    out.density = fitBins(out, false, [&](size_t b) { return scale * static_cast<double>(out.count[b]); });
  } else {
    out.density = FourierFit{};
  }
  out.fnFit = fitBins(out, true, [&](size_t b) { return out.fn[b]; });
  out.ftFit = fitBins(out, true, [&](size_t b) { return out.ft[b]; });
  out.lnFit = fitBins(out, true, [&](size_t b) { return out.ln[b]; });
  out.ltFit = fitBins(out, true, [&](size_t b) { return out.lt[b]; });
}

namespace {

nlohmann::json fitJson(const FourierFit& f) { return {{"c0", f.c0}, {"c1", f.c1}, {"c2", f.c2}}; }

FourierFit fitFromJson(const nlohmann::json& j) {
  return {j.at("c0").get<double>(), j.at("c1").get<double>(), j.at("c2").get<double>()};
}

// Means of empty bins are written as null: they have no value, and 0 would plot as one.
nlohmann::json meansJson(const PolarHistograms& h, const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (size_t b = 0; b < v.size(); ++b) {
    if (h.count[b] == 0)
      a.push_back(nullptr);
    else
      a.push_back(v[b]);
  }
  return a;
}

void meansFromJson(const nlohmann::json& a, const char* name, size_t bins, std::vector<double>& v) {
  if (!a.is_array() || a.size() != bins)
    throw std::invalid_argument(std::string("histogram JSON: \"") + name + "\" must have " +
                                std::to_string(bins) + " entries");
  v.assign(bins, 0.0);
  for (size_t b = 0; b < bins; ++b)
    if (!a[b].is_null()) v[b] = a[b].get<double>();
}

}  // namespace

void to_json(nlohmann::json& j, const PolarHistograms& h) {
  nlohmann::json centres = nlohmann::json::array();
  for (int b = 0; b < h.bins; ++b) centres.push_back(h.binCentreDeg(b));
  j = nlohmann::json{{"bins", h.bins},
                     {"bin_width_deg", h.binWidthDeg()},
                     {"smoothing", h.smoothing()},
                     {"ends", h.ends},
                     {"contacts", h.contacts},
                     {"centres_deg", std::move(centres)},
                     {"count", h.count},
                     {"fn", meansJson(h, h.fn)},
                     {"ft", meansJson(h, h.ft)},
                     {"ln", meansJson(h, h.ln)},
                     {"lt", meansJson(h, h.lt)},
                     {"fits",
                      {{"density", fitJson(h.density)},
                       {"fn", fitJson(h.fnFit)},
                       {"ft", fitJson(h.ftFit)},
                       {"ln", fitJson(h.lnFit)},
                       {"lt", fitJson(h.ltFit)}}}};
}

void from_json(const nlohmann::json& j, PolarHistograms& h) {
  const int bins = j.at("bins").get<int>();
  checkBins(bins);
  const auto n = static_cast<size_t>(bins);
  h.bins = bins;
  h.ends = j.at("ends").get<std::int64_t>();
  h.contacts = j.at("contacts").get<std::int64_t>();
  const nlohmann::json& count = j.at("count");
  if (!count.is_array() || count.size() != n)
    throw std::invalid_argument("histogram JSON: \"count\" must have " + std::to_string(bins) +
                                " entries");
  h.count = count.get<std::vector<std::int64_t>>();
  meansFromJson(j.at("fn"), "fn", n, h.fn);
  meansFromJson(j.at("ft"), "ft", n, h.ft);
  meansFromJson(j.at("ln"), "ln", n, h.ln);
  meansFromJson(j.at("lt"), "lt", n, h.lt);
  const nlohmann::json& fits = j.at("fits");
  h.density = fitFromJson(fits.at("density"));
  h.fnFit = fitFromJson(fits.at("fn"));
  h.ftFit = fitFromJson(fits.at("ft"));
  h.lnFit = fitFromJson(fits.at("ln"));
  h.ltFit = fitFromJson(fits.at("lt"));
}

}  // namespace grainlab::analysis
