#include "sampler.hpp"

#include <cmath>
#include <complex>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/stress_direction.hpp"
#include "sampled_boundary.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

const double kMissing = std::nan("");

// The major (most compressive) principal direction of the strain rate measured from the
// ring's motion, in θσ's convention (docs/micromechanics.md): D = −sym(L), compression
// positive, θ = ½ arg((D11 − D22) + 2i D12). NaN where D has no deviatoric part to speak of
// (a free stage, or compaction's equal rates, where only rounding would pick a direction).
double strainRateDirectionDeg(const Eigen::Matrix2d& l) {
  const double d11 = -l(0, 0), d22 = -l(1, 1), d12 = -0.5 * (l(0, 1) + l(1, 0));
  const std::complex<double> deviator(d11 - d22, 2 * d12);
  const double scale = std::abs(d11) + std::abs(d22) + 2 * std::abs(d12);
  if (!(std::abs(deviator) > 1e-9 * scale)) return kMissing;
  return analysis::axialDirectionDeg(deviator);
}

}  // namespace

Sampler::Sampler(const OutputSpec& output, const World& world, const SampledBoundary* boundary)
    : output_(output), world_(world), boundary_(boundary) {
  histograms_.bins = output.histogramBins;
  if (boundary_) {
    inside_ = boundary_->inside();
  } else {
    inside_.assign(static_cast<size_t>(world.size()), 1);
    for (int k = 0; k < world.size(); ++k) inside_[k] = world.boundaryFlags()[k] ? 0 : 1;
  }
  double sum = 0;
  int count = 0;
  for (int k = 0; k < world.size(); ++k) {
    if (!inside_[k]) continue;
    sum += 2 * std::sqrt(world.area(k) / kPi);
    ++count;
  }
  meanDiameter_ = count ? sum / count : 0;
  resetStrainReference();
}

void Sampler::resetStrainReference() {
  if (!boundary_) return;
  stretch1Ref_ = boundary_->stretch1();
  stretch2Ref_ = boundary_->stretch2();
  areaRef_ = boundary_->area();
}

Sample Sampler::measure(int stageIndex, const StageSpec& stage, double strainRate) {
  using Id = SeriesColumnId;
  constexpr auto at = columnIndex;
  constexpr size_t cStep = at(Id::Step), cTime = at(Id::Time), cStage = at(Id::Stage),
                   cAxial = at(Id::AxialStrain), cLateral = at(Id::LateralStrain),
                   cVol = at(Id::VolumetricStrain), c11 = at(Id::Sigma11), c22 = at(Id::Sigma22),
                   c12 = at(Id::Sigma12), c21 = at(Id::Sigma21), cP = at(Id::P), cQ = at(Id::Q),
                   cPhi = at(Id::PhiMobDeg), cVoid = at(Id::VoidRatio),
                   cCoord = at(Id::Coordination), cContacts = at(Id::Contacts),
                   cAc = at(Id::AC), cThc = at(Id::ThetaCDeg), cAn = at(Id::AN),
                   cThn = at(Id::ThetaNDeg), cAt = at(Id::AT), cTht = at(Id::ThetaTDeg),
                   cAw = at(Id::AW), cAln = at(Id::ALn), cThln = at(Id::ThetaLnDeg),
                   cAlt = at(Id::ALt), cThlt = at(Id::ThetaLtDeg),
                   cTsMacro = at(Id::ThetaSigmaMacroDeg), cTsMicro = at(Id::ThetaSigmaMicroDeg),
                   cTs10 = at(Id::ThetaSigmaEq10Deg), cTs11 = at(Id::ThetaSigmaEq11Deg),
                   cOmMacro = at(Id::OmegaMacroDeg), cOmMicro = at(Id::OmegaMicroDeg),
                   cKin = at(Id::KineticEnergy), cOm10 = at(Id::OmegaEq10Deg),
                   cOm11 = at(Id::OmegaEq11Deg), cF0 = at(Id::F0), cL0 = at(Id::L0),
                   cInertial = at(Id::InertialNumber), cElastic = at(Id::ElasticEnergy),
                   cArea = at(Id::Area), cThEps = at(Id::ThetaStrainRateDeg),
                   cOmEps = at(Id::OmegaStrainRateDeg);
  Sample s;
  s.step = world_.stepCount();
  s.time = world_.time();
  s.stage = stage.name;
  std::vector<double>& v = s.values;
  v.assign(seriesColumns().size(), kMissing);
  v[cStep] = static_cast<double>(s.step);
  v[cTime] = s.time;
  v[cStage] = stageIndex;
  v[cKin] = world_.kineticEnergy();
  v[cElastic] = world_.elasticEnergy();

  world_.contacts(contacts_);
  // Coordination: contact ends on specimen particles per specimen particle.
  long long ends = 0, specimen = 0, contacts = 0;
  for (const ContactRecord& c : contacts_) {
    const bool a = inside_[c.i], b = !c.isWall() && inside_[c.j];
    ends += a + b;
    contacts += (a || b);
  }
  for (unsigned char f : inside_) specimen += f;
  v[cContacts] = static_cast<double>(contacts);
  if (specimen) v[cCoord] = static_cast<double>(ends) / specimen;

  if (boundary_) {
    const PeriodicCell* cell = boundary_->cell();
    const double area = boundary_->area();
    v[cArea] = area;
    v[cAxial] = 1 - boundary_->stretch2() / stretch2Ref_;
    v[cLateral] = 1 - boundary_->stretch1() / stretch1Ref_;
    v[cVol] = 1 - area / areaRef_;
    lastVoidRatio_ = (area - boundary_->solidArea()) / boundary_->solidArea();
    v[cVoid] = lastVoidRatio_;
    v[cThEps] = strainRateDirectionDeg(boundary_->velocityGradient());
    const StressTensor stress = contactStress(contacts_, world_.positions(), inside_, area, cell);
    v[c11] = stress.s11;
    v[c22] = stress.s22;
    v[c12] = stress.s12;
    v[c21] = stress.s21;
    v[cP] = stress.p();
    v[cQ] = stress.q();
    if (stress.p() > 0) {
      const double phi = analysis::phiMobDeg(stress);
      v[cPhi] = phi;
      if (isShearing(stage.type)) peakPhiMob_ = std::max(peakPhiMob_, phi);
      // I = ε̇ d √(ρ/p): below ~1e-3 the shearing is quasi-static.
      v[cInertial] = std::abs(strainRate) * meanDiameter_ * std::sqrt(world_.material().density / stress.p());
    }
    if (output_.fabric && contacts > 0) {
      const analysis::FabricState f = analysis::measureFabric(contacts_, world_.positions(), inside_, cell);
      v[cAc] = f.a_c;
      v[cThc] = f.theta_c_deg;
      v[cAn] = f.a_n;
      v[cThn] = f.theta_n_deg;
      v[cAt] = f.a_t;
      v[cTht] = f.theta_t_deg;
      v[cAw] = f.a_w;
      v[cAln] = f.a_ln;
      v[cThln] = f.theta_ln_deg;
      v[cAlt] = f.a_lt;
      v[cThlt] = f.theta_lt_deg;
      v[cF0] = f.f0;
      v[cL0] = f.l0;
      if (stress.p() > 0) {
        const analysis::StressDirections d = analysis::stressDirections(stress, f);
        v[cTsMacro] = d.theta_sigma_macro_deg;
        v[cTsMicro] = d.theta_sigma_micro_deg;
        v[cTs10] = d.theta_sigma_eq10_deg;
        v[cTs11] = d.theta_sigma_eq11_deg;
        v[cOmMacro] = d.omega_macro_deg;
        v[cOmMicro] = d.omega_micro_deg;
        v[cOm10] = d.omega_eq10_deg;
        v[cOm11] = d.omega_eq11_deg;
        if (!std::isnan(v[cThEps])) v[cOmEps] = analysis::omegaDeg(d.theta_sigma_macro_deg, v[cThEps]);
      }
    }
    if (output_.histograms && contacts > 0) {
      analysis::measureHistograms(contacts_, world_.positions(), inside_, histograms_, cell);
      s.histograms = &histograms_;
    }
  }
  return s;
}

}  // namespace grainlab
