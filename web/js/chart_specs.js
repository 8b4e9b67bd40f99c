// What the charts plot, as in the paper: strength (φ_mob, σ1 − σ3), volumetric strain, the
// anisotropy coefficients a_k and directions θ_k (Figs. 7–13), the non-coaxiality ω from the
// stress and from Eqs. 7, 10 and 11 (Fig. 15), and σ12 − σ21 (Fig. 6), against axial strain;
// for the loading paths also θσ, θ_ε̇ and θ_c together, against time or the axes' rotation.

// Each plotted quantity is values(table, rows) → one value per row (null for a gap): whole
// columns at a time, so a 10,000-sample redraw is a few array passes.

/** A column, scaled. */
const column = (name, factor = 1) => (table, rows) => {
  const data = table.column(name);
  if (!data) return rows.map(() => null);
  // Rows ascend without repeats, so first and last tell whether they are one run of rows:
  // then an unscaled column is a plain copy.
  if (factor === 1 && rows.length && rows[rows.length - 1] - rows[0] === rows.length - 1) {
    return data.slice(rows[0], rows[0] + rows.length);
  }
  return rows.map((i) => (data[i] === null ? null : data[i] * factor));
};

/** The a_k an isotropic sample of N_c contacts shows by chance: 1.25·√(2/N_c) (docs/micromechanics.md). */
export const noiseFloor = (contacts) => (contacts > 0 ? 1.25 * Math.sqrt(2 / contacts) : null);
/** A direction θ_k means something only where a_k is at least this many noise floors (as the report). */
export const DIRECTION_NOISE_FACTOR = 2;

/**
 * θ_k where a_k ≥ 2 × noise floor, null (a gap) elsewhere: where a_k is about zero its direction is
 * chance and would jump by tens of degrees from sample to sample.
 */
export const direction = (term) => (table, rows) => {
  const theta = table.column(`theta_${term}_deg`), coef = table.column(`a_${term}`), contacts = table.column('contacts');
  if (!theta || !coef || !contacts) return rows.map(() => null);
  return rows.map((i) => {
    const floor = noiseFloor(contacts[i]);
    if (theta[i] === null || coef[i] === null || floor === null) return null;
    return coef[i] >= DIRECTION_NOISE_FACTOR * floor ? theta[i] : null;
  });
};

/** σ12 − σ21 in kPa. */
const stressAsymmetry = (table, rows) => {
  const s12 = table.column('sigma12'), s21 = table.column('sigma21');
  if (!s12 || !s21) return rows.map(() => null);
  return rows.map((i) => (s12[i] === null || s21[i] === null ? null : (s12[i] - s21[i]) / 1000));
};

/**
 * How far the principal strain-rate axes have turned since the first of the rows (degrees,
 * unwrapped): θ_strain_rate is axial, so each step between samples is taken in [−90°, 90°).
 */
export const rotationAngle = (table, rows) => {
  const theta = table.column('theta_strain_rate_deg');
  if (!theta) return rows.map(() => null);
  let previous = null;
  let turned = 0;
  return rows.map((i) => {
    if (theta[i] === null) return null;
    if (previous !== null) turned += ((((theta[i] - previous) % 180) + 270) % 180) - 90;
    previous = theta[i];
    return turned;
  });
};

export const X_AXES = {
  strain: { label: 'axial strain ε₂₂ (%)', values: column('axial_strain', 100), shearingOnly: true },
  time: { label: 'time (s), all stages', values: column('time'), shearingOnly: false },
  rotation: { label: 'rotation of the strain-rate axes (°), shearing stage', values: rotationAngle, shearingOnly: true },
};

export const RUN_CHARTS = [
  {
    key: 'strength',
    title: 'Mobilised friction angle and deviator stress',
    series: [
      { label: 'φ_mob (°)', values: column('phi_mob_deg'), scale: 'deg' },
      // q is the Mohr circle's radius (σ1 − σ3)/2 (engine/src/stress.cpp).
      { label: 'σ1 − σ3 (kPa)', values: column('q', 2e-3), scale: 'kPa' },
    ],
    axes: [{ scale: 'deg', label: 'φ_mob (°)' }, { scale: 'kPa', label: 'σ1 − σ3 (kPa)', side: 1 }],
  },
  {
    key: 'volumetric',
    title: 'Volumetric strain (compression positive)',
    series: [{ label: 'ε_v (%)', values: column('volumetric_strain', 100) }],
    axes: [{ label: 'ε_v (%)' }],
  },
  {
    key: 'coefficients',
    title: 'Anisotropy coefficients',
    series: [
      { label: 'a_c', values: column('a_c') },
      { label: 'a_n', values: column('a_n') },
      { label: 'a_t', values: column('a_t') },
      { label: 'a_ln', values: column('a_ln') },
      { label: 'a_lt', values: column('a_lt') },
    ],
    axes: [{ label: 'a_k' }],
  },
  {
    key: 'directions',
    title: 'Principal directions of anisotropy (drawn where a_k ≥ 2× noise floor)',
    series: [
      { label: 'θ_c (°)', values: direction('c') },
      { label: 'θ_n (°)', values: direction('n') },
      { label: 'θ_t (°)', values: direction('t') },
      { label: 'θ_ln (°)', values: direction('ln') },
      { label: 'θ_lt (°)', values: direction('lt') },
    ],
    axes: [{ label: 'θ_k (°)' }],
  },
  {
    // The loading paths' chart (docs/loading-paths.md): stress, strain rate and fabric turning
    // together, or not, through a rotation of the principal axes.
    key: 'principal-axes',
    title: 'Principal directions: stress θσ, strain rate θ_ε̇ and fabric θ_c',
    series: [
      { label: 'θσ (°)', values: column('theta_sigma_macro_deg') },
      { label: 'θ_ε̇ (°)', values: column('theta_strain_rate_deg'), dash: [6, 3] },
      { label: 'θ_c (°)', values: direction('c'), dash: [2, 3] },
    ],
    axes: [{ label: 'direction (°)' }],
  },
  {
    key: 'omega',
    title: 'Non-coaxiality ω: from the stress and from Eqs. 7, 10, 11',
    series: [
      { label: 'ω stress (°)', values: column('omega_macro_deg') },
      { label: 'ω Eq. 7 (°)', values: column('omega_micro_deg') },
      { label: 'ω Eq. 10 (°)', values: column('omega_eq10_deg'), dash: [6, 3] },
      { label: 'ω Eq. 11 (°)', values: column('omega_eq11_deg'), dash: [2, 3] },
      { label: 'θσ − θ_ε̇ (°)', values: column('omega_strain_rate_deg'), dash: [1, 2] },
    ],
    axes: [{ label: 'ω (°)' }],
  },
  {
    key: 'asymmetry',
    title: 'σ12 − σ21 (symmetry of the stress tensor)',
    series: [{ label: 'σ12 − σ21 (kPa)', values: stressAsymmetry }],
    axes: [{ label: 'σ12 − σ21 (kPa)' }],
  },
];

/**
 * The compare view: one quantity per chart, one line per run. `gaps`: a missing value is a gap
 * to keep (a direction below its noise floor), not a sample another run has and this one lacks.
 */
export const COMPARE_CHARTS = [
  { key: 'phi', title: 'φ_mob (°)', values: column('phi_mob_deg') },
  { key: 'deviator', title: 'σ1 − σ3 (kPa)', values: column('q', 2e-3) },
  { key: 'volumetric', title: 'ε_v (%)', values: column('volumetric_strain', 100) },
  { key: 'omega', title: 'ω from the stress (°)', values: column('omega_macro_deg') },
  { key: 'omega7', title: 'ω from Eq. 7 (°)', values: column('omega_micro_deg') },
  { key: 'a_c', title: 'a_c', values: column('a_c') },
  { key: 'theta_c', title: 'θ_c (°), where a_c ≥ 2× noise floor', values: direction('c'), gaps: true },
  { key: 'a_n', title: 'a_n', values: column('a_n') },
  { key: 'theta_n', title: 'θ_n (°), where a_n ≥ 2× noise floor', values: direction('n'), gaps: true },
  { key: 'a_t', title: 'a_t', values: column('a_t') },
  { key: 'theta_t', title: 'θ_t (°), where a_t ≥ 2× noise floor', values: direction('t'), gaps: true },
  { key: 'a_ln', title: 'a_ln', values: column('a_ln') },
  { key: 'theta_ln', title: 'θ_ln (°), where a_ln ≥ 2× noise floor', values: direction('ln'), gaps: true },
  { key: 'a_lt', title: 'a_lt', values: column('a_lt') },
  { key: 'theta_lt', title: 'θ_lt (°), where a_lt ≥ 2× noise floor', values: direction('lt'), gaps: true },
  { key: 'asymmetry', title: 'σ12 − σ21 (kPa)', values: stressAsymmetry },
];

/**
 * The rows a chart shows and their x values: the shearing stage against axial strain, or every
 * row against time. Returns {rows: [row index], x: [value]}.
 */
export function chartDomain(table, xAxis, shearing) {
  const all = [];
  const stages = table.column('stage');
  for (let i = 0; i < table.length; i++) {
    if (!xAxis.shearingOnly || (stages && shearing.has(stages[i]))) all.push(i);
  }
  const values = xAxis.values(table, all);
  const rows = [];
  const x = [];
  all.forEach((row, k) => {
    if (values[k] === null) return;
    rows.push(row);
    x.push(values[k]);
  });
  return { rows, x };
}
