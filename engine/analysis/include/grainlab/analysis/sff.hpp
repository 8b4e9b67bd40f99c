#pragma once
// The stress-force-fabric relation in closed form (docs/micromechanics.md, "Exact closed
// form"): the stress that paper Eq. (1) gives for the Fourier distributions of a FabricState,
// with every order of the coefficients kept. With K = m_v f0 l0:
//   σ11 + σ22 = K T,   (σ11 − σ22) + i(σ12 + σ21) = K Z,   σ12 − σ21 = −K M.
#include <complex>

#include "grainlab/analysis/fabric.hpp"
#include "grainlab/stress.hpp"

namespace grainlab::analysis {

/// T, Z and M, dimensionless (in units of K = m_v f0 l0).
struct SffForm {
  double T = 0;
  std::complex<double> Z{};
  double M = 0;
};

/// The closed form for the coefficients and directions of `s` (its a_w included as stored).
SffForm sffClosedForm(const FabricState& s);

/// The stress tensor (Pa) the closed form predicts, with endDensity = m_v in contact ends
/// per m² (ends / area) and f0 (N/m), l0 (m) taken from `s`.
StressTensor sffStress(const FabricState& s, double endDensity);

}  // namespace grainlab::analysis
