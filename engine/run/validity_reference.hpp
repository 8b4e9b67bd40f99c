#pragma once
// The reference scene of the validity envelope: circular-quick's values (grainlab preset
// circular-quick), against which a quantity past its limit is blamed on the field that is
// furthest from its reference (validity_envelope.cpp's drivingField).
namespace grainlab::reference {

inline constexpr double kDensity = 2650;           // kg/m³, material.density
inline constexpr double kNormalStiffness = 3e8;    // N/m, material.normal_stiffness
inline constexpr double kTimestepSafety = 0.2;     // solver.timestep_safety
inline constexpr double kTimestep = 2.4e-6;        // s: what that safety gives circular-quick
inline constexpr double kDiscRadius = 0.002;       // m, assembly.disc_radius
inline constexpr double kLongAxis = 0.007;         // m, the longest of assembly.long_axes
inline constexpr double kSpecimenDiameter = 0.06;  // m, assembly.specimen_diameter
inline constexpr double kStress = 300e3;           // Pa, the stages' pressure, mean_stress, normal_stress
inline constexpr double kRate = 1.0;               // 1/s, the shearing strain rate
inline constexpr double kTotalRotationDeg = 360;   // rotation-circular-quick's stage
inline constexpr double kRotationDuration = 0.3;   // s
inline constexpr double kRotationRateDeg = 1200;   // °/s
inline constexpr double kSimulatedTime = 0.2;      // s: the biaxial stage's 0.2 strain at 1 /s

}  // namespace grainlab::reference
