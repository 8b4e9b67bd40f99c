// What the charts plot, as in the paper: strength (φ_mob, σ1 − σ3), volumetric strain, the
// anisotropy coefficients a_k and directions θ_k (Figs. 7–13), the non-coaxiality ω from the
// stress and from Eqs. 7, 10 and 11 (Fig. 15), and σ12 − σ21 (Fig. 6), against axial strain.

/** A column, scaled, as a per-row accessor. */
const column = (name, factor = 1) => (table, i) => {
  const v = table.value(name, i);
  return v === null ? null : v * factor;
};

export const X_AXES = {
  strain: { label: 'axial strain ε₂₂ (%)', value: column('axial_strain', 100), shearingOnly: true },
  time: { label: 'time (s), all stages', value: column('time'), shearingOnly: false },
};

export const RUN_CHARTS = [
  {
    key: 'strength',
    title: 'Mobilised friction angle and deviator stress',
    series: [
      { label: 'φ_mob (°)', value: column('phi_mob_deg'), scale: 'deg' },
      // q is the Mohr circle's radius (σ1 − σ3)/2 (engine/src/stress.cpp).
      { label: 'σ1 − σ3 (kPa)', value: column('q', 2e-3), scale: 'kPa' },
    ],
    axes: [{ scale: 'deg', label: 'φ_mob (°)' }, { scale: 'kPa', label: 'σ1 − σ3 (kPa)', side: 1 }],
  },
  {
    key: 'volumetric',
    title: 'Volumetric strain (compression positive)',
    series: [{ label: 'ε_v (%)', value: column('volumetric_strain', 100) }],
    axes: [{ label: 'ε_v (%)' }],
  },
  {
    key: 'coefficients',
    title: 'Anisotropy coefficients',
    series: [
      { label: 'a_c', value: column('a_c') },
      { label: 'a_n', value: column('a_n') },
      { label: 'a_t', value: column('a_t') },
      { label: 'a_ln', value: column('a_ln') },
      { label: 'a_lt', value: column('a_lt') },
    ],
    axes: [{ label: 'a_k' }],
  },
  {
    key: 'directions',
    title: 'Principal directions of anisotropy',
    series: [
      { label: 'θ_c (°)', value: column('theta_c_deg') },
      { label: 'θ_n (°)', value: column('theta_n_deg') },
      { label: 'θ_t (°)', value: column('theta_t_deg') },
      { label: 'θ_ln (°)', value: column('theta_ln_deg') },
      { label: 'θ_lt (°)', value: column('theta_lt_deg') },
    ],
    axes: [{ label: 'θ_k (°)' }],
  },
  {
    key: 'omega',
    title: 'Non-coaxiality ω: from the stress and from Eqs. 7, 10, 11',
    series: [
      { label: 'ω stress (°)', value: column('omega_macro_deg') },
      { label: 'ω Eq. 7 (°)', value: column('omega_micro_deg') },
      { label: 'ω Eq. 10 (°)', value: column('omega_eq10_deg'), dash: [6, 3] },
      { label: 'ω Eq. 11 (°)', value: column('omega_eq11_deg'), dash: [2, 3] },
    ],
    axes: [{ label: 'ω (°)' }],
  },
  {
    key: 'asymmetry',
    title: 'σ12 − σ21 (symmetry of the stress tensor)',
    series: [{
      label: 'σ12 − σ21 (kPa)',
      value: (table, i) => {
        const a = table.value('sigma12', i), b = table.value('sigma21', i);
        return a === null || b === null ? null : (a - b) / 1000;
      },
    }],
    axes: [{ label: 'σ12 − σ21 (kPa)' }],
  },
];

/** The compare view: one quantity per chart, one line per run. */
export const COMPARE_CHARTS = [
  { key: 'phi', title: 'φ_mob (°)', value: column('phi_mob_deg') },
  { key: 'deviator', title: 'σ1 − σ3 (kPa)', value: column('q', 2e-3) },
  { key: 'volumetric', title: 'ε_v (%)', value: column('volumetric_strain', 100) },
  { key: 'omega', title: 'ω from the stress (°)', value: column('omega_macro_deg') },
  { key: 'omega7', title: 'ω from Eq. 7 (°)', value: column('omega_micro_deg') },
  { key: 'a_c', title: 'a_c', value: column('a_c') },
  { key: 'theta_c', title: 'θ_c (°)', value: column('theta_c_deg') },
  { key: 'a_n', title: 'a_n', value: column('a_n') },
  { key: 'theta_n', title: 'θ_n (°)', value: column('theta_n_deg') },
  { key: 'a_t', title: 'a_t', value: column('a_t') },
  { key: 'theta_t', title: 'θ_t (°)', value: column('theta_t_deg') },
  { key: 'a_ln', title: 'a_ln', value: column('a_ln') },
  { key: 'theta_ln', title: 'θ_ln (°)', value: column('theta_ln_deg') },
  { key: 'a_lt', title: 'a_lt', value: column('a_lt') },
  { key: 'theta_lt', title: 'θ_lt (°)', value: column('theta_lt_deg') },
  { key: 'asymmetry', title: 'σ12 − σ21 (kPa)', value: (t, i) => {
    const a = t.value('sigma12', i), b = t.value('sigma21', i);
    return a === null || b === null ? null : (a - b) / 1000;
  } },
];

/**
 * The rows a chart shows and their x values: the shearing stage against axial strain, or every
 * row against time. Returns {rows: [row index], x: [value]}.
 */
export function chartDomain(table, xAxis, shearing) {
  const rows = [];
  const x = [];
  const stages = table.column('stage');
  for (let i = 0; i < table.length; i++) {
    if (xAxis.shearingOnly && !(stages && shearing.has(stages[i]))) continue;
    const v = xAxis.value(table, i);
    if (v === null) continue;
    rows.push(i);
    x.push(v);
  }
  return { rows, x };
}
