#include "grainlab/lammps/import.hpp"

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/histogram.hpp"
#include "grainlab/analysis/stress_direction.hpp"
#include "grainlab/histogram_writer.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "grainlab/series_column.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab::lammps {
namespace fs = std::filesystem;
namespace {

const double kMissing = std::nan("");

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The frames of one kind, from files read one after the other.
class FrameStream {
 public:
  void add(const std::string& path) { paths_.push_back(path); }
  bool empty() const { return paths_.empty(); }
  const std::string& firstPath() const { return paths_.front(); }
  bool next(DumpFrame& f) {
    for (;;) {
      if (!reader_) {
        if (at_ == paths_.size()) return false;
        reader_ = std::make_unique<DumpReader>(paths_[at_++]);
      }
      if (reader_->next(f)) return true;
      reader_.reset();
    }
  }

 private:
  std::vector<std::string> paths_;
  std::size_t at_ = 0;
  std::unique_ptr<DumpReader> reader_;
};

// The cell's edge matrix h = [a b] with a = (lx, 0), b = (xy, ly).
Eigen::Matrix2d cellMatrix(const DumpBox& b) {
  Eigen::Matrix2d h;
  h << b.lx(), b.xy, 0, b.ly();
  return h;
}

// The major (most compressive) principal direction of the cell's strain rate, as grainlab's
// sampler measures the ring's (engine/run/sampler.cpp): L = ḣ h⁻¹ (here Δh h⁻¹, the scale does
// not matter), D = −sym(L), θ = ½ arg((D11 − D22) + 2i D12). NaN without a deviatoric part.
double strainRateDirectionDeg(const DumpBox& before, const DumpBox& now) {
  const Eigen::Matrix2d h1 = cellMatrix(now);
  Eigen::Matrix2d inverse;  // of the upper-triangular h1
  inverse << 1 / now.lx(), -now.xy / (now.lx() * now.ly()), 0, 1 / now.ly();
  const Eigen::Matrix2d l = (h1 - cellMatrix(before)) * inverse;
  const double d11 = -l(0, 0), d22 = -l(1, 1), d12 = -0.5 * (l(0, 1) + l(1, 0));
  const std::complex<double> deviator(d11 - d22, 2 * d12);
  const double scale = std::abs(d11) + std::abs(d22) + 2 * std::abs(d12);
  if (!(std::abs(deviator) > 1e-9 * scale)) return kMissing;
  return analysis::axialDirectionDeg(deviator);
}

// contacts_final.csv's columns, as grainlab's runs write them: i and j are particle indices
// (ascending atom id), l_i and l_j the branch vectors from each centroid (j's image across a
// periodic boundary) to the contact point.
std::string contactRows(const FrameContacts& c) {
  std::string text = "i,j,px,py,nx,ny,fn,ft,lix,liy,ljx,ljy\n";
  for (const ContactRecord& k : c.contacts) {
    const Vec2 li = k.point - c.centroids[static_cast<std::size_t>(k.i)];
    const Vec2 lj = k.point - c.centroids[static_cast<std::size_t>(k.j)];
    // An image's index stands for its atom: the atom j whose image it is.
    int j = k.j;
    if (j >= c.particles) j = c.imageOf[static_cast<std::size_t>(j - c.particles)];
    text += std::to_string(k.i) + "," + std::to_string(j) + "," + num(k.point.x()) + "," + num(k.point.y()) + "," +
            num(k.normal.x()) + "," + num(k.normal.y()) + "," + num(k.fn) + "," + num(k.ft) + "," + num(li.x()) + "," +
            num(li.y()) + "," + num(lj.x()) + "," + num(lj.y()) + "\n";
  }
  return text;
}

std::string particleRows(const FrameContacts& c) {
  std::string text = "id,shape,x,y,angle,vx,vy,spin,radius,boundary\n";
  for (int k = 0; k < c.particles; ++k) {
    const auto u = static_cast<std::size_t>(k);
    text += std::to_string(c.ids[u]) + ",disc," + num(c.centroids[u].x()) + "," + num(c.centroids[u].y()) + ",0," +
            num(c.velocities[u].x()) + "," + num(c.velocities[u].y()) + "," + num(c.spins[u]) + "," + num(c.radii[u]) +
            ",0\n";
  }
  return text;
}

}  // namespace

ImportReport importLammps(const std::vector<std::string>& dumps, const std::string& outDir, const ImportOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  if (dumps.empty()) throw std::invalid_argument("give the dumps: a dump custom file and a dump local file");
  // The import replaces outDir at the end: only an empty folder or an earlier import's.
  const fs::path out(outDir);
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out))) {
    bool earlier = false;
    try {
      earlier = nlohmann::json::parse(std::ifstream(out / "summary.json")).value("origin", "") == "lammps";
    } catch (const std::exception&) {
    }
    if (!earlier)
      throw std::runtime_error(outDir + " exists and is not an earlier LAMMPS import: give a new or empty folder");
  }
  // Sort the files by the kind of their first frame.
  FrameStream atomStream, entryStream;
  for (const std::string& path : dumps)
    (dumpKind(path) == DumpFrame::Kind::Atoms ? atomStream : entryStream).add(path);
  if (atomStream.empty()) throw DumpError(dumps.front() + ":1: no dump custom (ITEM: ATOMS) file among the dumps");
  if (entryStream.empty()) throw DumpError(dumps.front() + ":1: no dump local (ITEM: ENTRIES) file among the dumps");

  // export.json beside the particles' dump: the timestep and the density, unless given.
  std::optional<double> timestep = options.timestep, density = options.density;
  double startTime = 0;  // s: the clock of a specimen exported --from a prepared run
  const fs::path exportJson = fs::path(atomStream.firstPath()).parent_path() / "export.json";
  if (fs::exists(exportJson)) {
    try {
      const nlohmann::json meta = nlohmann::json::parse(std::ifstream(exportJson));
      if (!timestep && meta.contains("timestep_s")) timestep = meta["timestep_s"].get<double>();
      if (!density && meta.contains("material")) density = meta["material"]["density"].get<double>();
      if (!options.timestep) startTime = meta.value("start_time_s", 0.0);
    } catch (const std::exception& e) {
      throw std::runtime_error(exportJson.string() + ": " + e.what());
    }
  }

  // Everything goes to a temporary folder, renamed over outDir at the end.
  const fs::path work = out.string() + ".importing";
  fs::remove_all(work);
  fs::create_directories(work);
  if (options.framesEvery > 0) fs::create_directories(work / "frames");
  ImportReport report;
  try {
    std::ofstream series(work / "series.csv", std::ios::binary);
    series << seriesHeader() << '\n';
    Scene noScene;
    World noWorld(Material{});  // HistogramWriter reads only the samples
    HistogramWriter histogramWriter(work.string());
    histogramWriter.onStart(noScene, noWorld);

    DumpFrame atoms, entries;
    FrameContacts contacts, last;  // this frame's, and the one before (the last at the end)
    analysis::PolarHistograms histograms;
    histograms.bins = options.histogramBins;
    std::vector<unsigned char> inside;
    DumpBox firstBox, previousBox;
    using Id = SeriesColumnId;
    constexpr auto at = columnIndex;
    for (;;) {
      bool haveAtoms = false, haveEntries = false;
      try {
        haveAtoms = atomStream.next(atoms);
        haveEntries = entryStream.next(entries);
      } catch (const DumpError& e) {
        if (!e.truncated()) throw;
        report.warning = std::string(e.what()) + "; the " + std::to_string(report.frames) + " frames before it are imported";
        break;
      }
      if (!haveAtoms && !haveEntries) break;
      if (haveAtoms != haveEntries) {
        const DumpFrame& more = haveAtoms ? atoms : entries;
        throw DumpError(more.file + ":" + std::to_string(more.line) + ": a frame of timestep " +
                        std::to_string(more.timestep) + " has no partner: the " + (haveAtoms ? "local" : "atom") +
                        " dump ends at timestep " + std::to_string(report.lastTimestep));
      }
      frameContacts(atoms, entries, options.columns, contacts);
      const DumpBox& box = atoms.box;
      if (report.frames == 0) firstBox = box;
      const double area = box.area();

      Sample s;
      s.step = atoms.timestep;
      s.time = timestep ? startTime + static_cast<double>(atoms.timestep) * *timestep : kMissing;
      s.stage = "lammps";
      std::vector<double>& v = s.values;
      v.assign(seriesColumns().size(), kMissing);
      v[at(Id::Step)] = static_cast<double>(s.step);
      v[at(Id::Time)] = s.time;
      v[at(Id::Stage)] = 0;
      v[at(Id::Area)] = area;
      v[at(Id::AxialStrain)] = 1 - box.ly() / firstBox.ly();
      v[at(Id::LateralStrain)] = 1 - box.lx() / firstBox.lx();
      v[at(Id::VolumetricStrain)] = 1 - area / firstBox.area();
      v[at(Id::VoidRatio)] = (area - contacts.solidArea) / contacts.solidArea;
      const auto n = static_cast<std::size_t>(contacts.particles);
      v[at(Id::Contacts)] = static_cast<double>(contacts.contacts.size());
      if (n) v[at(Id::Coordination)] = 2.0 * static_cast<double>(contacts.contacts.size()) / static_cast<double>(n);
      if (density) {
        double ke = 0;
        for (std::size_t k = 0; k < n; ++k) {
          const double r = contacts.radii[k], m = *density * kPi * r * r;
          ke += 0.5 * m * contacts.velocities[k].squaredNorm() + 0.25 * m * r * r * contacts.spins[k] * contacts.spins[k];
        }
        v[at(Id::KineticEnergy)] = ke;
      }
      const double thetaRate = report.frames > 0 ? strainRateDirectionDeg(previousBox, box) : kMissing;
      v[at(Id::ThetaStrainRateDeg)] = thetaRate;

      inside.assign(contacts.centroids.size(), 1);
      const StressTensor stress = contactStress(contacts.contacts, contacts.centroids, inside, area);
      v[at(Id::Sigma11)] = stress.s11;
      v[at(Id::Sigma22)] = stress.s22;
      v[at(Id::Sigma12)] = stress.s12;
      v[at(Id::Sigma21)] = stress.s21;
      v[at(Id::P)] = stress.p();
      v[at(Id::Q)] = stress.q();
      if (stress.p() > 0) v[at(Id::PhiMobDeg)] = analysis::phiMobDeg(stress);
      if (!contacts.contacts.empty()) {
        const analysis::FabricState f = analysis::measureFabric(contacts.contacts, contacts.centroids, inside);
        v[at(Id::AC)] = f.a_c;
        v[at(Id::ThetaCDeg)] = f.theta_c_deg;
        v[at(Id::AN)] = f.a_n;
        v[at(Id::ThetaNDeg)] = f.theta_n_deg;
        v[at(Id::AT)] = f.a_t;
        v[at(Id::ThetaTDeg)] = f.theta_t_deg;
        v[at(Id::AW)] = f.a_w;
        v[at(Id::ALn)] = f.a_ln;
        v[at(Id::ThetaLnDeg)] = f.theta_ln_deg;
        v[at(Id::ALt)] = f.a_lt;
        v[at(Id::ThetaLtDeg)] = f.theta_lt_deg;
        v[at(Id::F0)] = f.f0;
        v[at(Id::L0)] = f.l0;
        if (stress.p() > 0) {
          const analysis::StressDirections d = analysis::stressDirections(stress, f);
          v[at(Id::ThetaSigmaMacroDeg)] = d.theta_sigma_macro_deg;
          v[at(Id::ThetaSigmaMicroDeg)] = d.theta_sigma_micro_deg;
          v[at(Id::ThetaSigmaEq10Deg)] = d.theta_sigma_eq10_deg;
          v[at(Id::ThetaSigmaEq11Deg)] = d.theta_sigma_eq11_deg;
          v[at(Id::OmegaMacroDeg)] = d.omega_macro_deg;
          v[at(Id::OmegaMicroDeg)] = d.omega_micro_deg;
          v[at(Id::OmegaEq10Deg)] = d.omega_eq10_deg;
          v[at(Id::OmegaEq11Deg)] = d.omega_eq11_deg;
          if (!std::isnan(thetaRate)) v[at(Id::OmegaStrainRateDeg)] = analysis::omegaDeg(d.theta_sigma_macro_deg, thetaRate);
        }
        analysis::measureHistograms(contacts.contacts, contacts.centroids, inside, histograms);
        s.histograms = &histograms;
      }
      series << formatSeriesRow(s) << '\n';
      histogramWriter.onSample(s, noWorld);
      if (options.observer) options.observer->onFrame(s, contacts);
      if (options.framesEvery > 0 && report.frames % options.framesEvery == 0)
        writeFileAtomically((work / "frames" / (std::to_string(s.step) + ".csv")).string(), particleRows(contacts));
      if (report.frames == 0) report.firstTimestep = s.step;
      report.lastTimestep = s.step;
      report.particles = contacts.particles;
      previousBox = box;
      ++report.frames;
      std::swap(contacts, last);
    }
    if (report.frames == 0) throw DumpError(atomStream.firstPath() + ":1: no whole frame to import");
    series.close();
    if (!series) throw std::runtime_error("cannot write " + (work / "series.csv").string());
    histogramWriter.onFinish(RunSummary{}, noWorld);
    writeFileAtomically((work / "particles_final.csv").string(), particleRows(last));
    writeFileAtomically((work / "contacts_final.csv").string(), contactRows(last));
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    nlohmann::json summary = {{"origin", "lammps"},
                              {"status", "completed"},
                              {"dumps", dumps},
                              {"frames", report.frames},
                              {"first_timestep", report.firstTimestep},
                              {"last_timestep", report.lastTimestep},
                              {"steps", report.lastTimestep},  // LAMMPS's step count at the last frame
                              {"particles", report.particles},
                              {"import_seconds", report.seconds},
                              {"notes", report.warning.empty() ? nlohmann::json::array()
                                                               : nlohmann::json::array({report.warning})}};
    if (timestep) summary["timestep_s"] = *timestep;
    writeFileAtomically((work / "summary.json").string(), summary.dump(2) + "\n");
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(work, ignored);
    throw;
  }
  fs::remove_all(out);
  fs::rename(work, out);
  return report;
}

}  // namespace grainlab::lammps
