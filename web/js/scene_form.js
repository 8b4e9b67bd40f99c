// The New run form's editable parameters: each field names where it lives in the scene JSON
// (contracts.md), so values read from a preset's scene, edits write back into it, and the
// API's 400 {"error", "field"} is shown beside the field whose path it names.

/** "stages[2].pressure" → ["stages", 2, "pressure"] */
export function parsePath(path) {
  const parts = [];
  for (const piece of path.split('.')) {
    const match = /^([^[\]]+)((?:\[\d+\])*)$/.exec(piece);
    if (!match) return [path];
    parts.push(match[1]);
    for (const index of match[2].matchAll(/\[(\d+)\]/g)) parts.push(Number(index[1]));
  }
  return parts;
}

export function getPath(object, path) {
  let at = object;
  for (const part of parsePath(path)) {
    if (at === null || typeof at !== 'object') return undefined;
    at = at[part];
  }
  return at;
}

/** Sets the value, creating objects on the way; `undefined` removes the key. */
export function setPath(object, path, value) {
  const parts = parsePath(path);
  let at = object;
  for (const [k, part] of parts.slice(0, -1).entries()) {
    if (at[part] === null || typeof at[part] !== 'object') {
      if (value === undefined) return;
      at[part] = typeof parts[k + 1] === 'number' ? [] : {};  // "boundary.size[0]": a list
    }
    at = at[part];
  }
  const last = parts[parts.length - 1];
  if (value === undefined) delete at[last];
  else at[last] = value;
}

const fixed = (path) => () => [path];

/**
 * The fidelity levels of docs/speed-accuracy.md, chosen from the 8-seed `grainlab tradeoff
 * --seeds` ensemble: timestep safety, sampling, and the shearing rate that gives the inertial
 * number I for the paper's particles at 300 kPa (ε̇ = I / (d √(ρ/p))). None shears faster
 * than I = 3e-4: above the servo's bound σ11 is not held.
 */
export const FIDELITY = {
  draft: { timestepSafety: 0.2, sampleStrain: 0.005, strainRate: { disc: 0.798, elongated: 0.762 } },
  standard: { timestepSafety: 0.2, sampleStrain: 0.002, strainRate: { disc: 0.266, elongated: 0.254 } },
  reference: { timestepSafety: 0.05, sampleStrain: 0.001, strainRate: { disc: 0.266, elongated: 0.254 } },
};
const biaxialStages = (scene) => (scene.stages ?? []).filter((stage) => stage.type === 'biaxial');
const particleKind = (scene) => (scene.assembly?.shape === 'elongated' ? 'elongated' : 'disc');

/** The fidelity whose three settings the scene has, or 'custom'. */
export function sceneFidelity(scene) {
  const stages = biaxialStages(scene);
  for (const [name, f] of Object.entries(FIDELITY)) {
    const safety = scene.solver?.timestep_safety ?? 0.2;  // the engine's default
    if (safety === f.timestepSafety && scene.output?.sample_strain === f.sampleStrain &&
        stages.length > 0 && stages.every((stage) => stage.strain_rate === f.strainRate[particleKind(scene)])) {
      return name;
    }
  }
  return 'custom';
}

function applyFidelity(scene, name) {
  const f = FIDELITY[name];
  if (!f) return;  // 'custom' leaves the scene as it is
  setPath(scene, 'solver.timestep_safety', f.timestepSafety);
  setPath(scene, 'output.sample_strain', f.sampleStrain);
  for (const stage of biaxialStages(scene)) stage.strain_rate = f.strainRate[particleKind(scene)];
}
const stagePaths = (types, key) => (scene) =>
  (scene.stages ?? []).flatMap((stage, k) => (types.includes(stage.type) ? [`stages[${k}].${key}`] : []));

/**
 * The loading paths of docs/loading-paths.md, each the stage that replaces the scene's last
 * shearing stage when chosen (the values of the quick presets); `constant_volume` is the
 * biaxial stage with "lateral": "constant_volume".
 */
const SHEARING_TYPES = ['biaxial', 'rotation', 'cyclic', 'simple_shear'];
export const PATH_STAGES = {
  biaxial: { type: 'biaxial', name: 'shearing', pressure: 300e3, strain_rate: 1.0, target_axial_strain: 0.2 },
  constant_volume: {
    type: 'biaxial', name: 'constant volume', lateral: 'constant_volume', strain_rate: 1.0, target_axial_strain: 0.2,
  },
  rotation: {
    type: 'rotation', name: 'rotation', deviatoric_strain_rate: 1.0, total_rotation_deg: 360, duration: 0.3,
    mean_stress: 300e3, initial_direction_deg: 90,
  },
  cyclic: { type: 'cyclic', name: 'cyclic', pressure: 300e3, strain_rate: 1.0, strain_amplitude: 0.01, cycles: 3 },
  simple_shear: { type: 'simple_shear', name: 'simple shear', shear_rate: 1.0, normal_stress: 300e3, target_shear_strain: 0.3 },
};
const shearingIndex = (scene) => {
  const stages = scene.stages ?? [];
  for (let k = stages.length - 1; k >= 0; k--) if (SHEARING_TYPES.includes(stages[k]?.type)) return k;
  return -1;
};
/** The scene's loading path: its last shearing stage's type (or 'constant_volume'). */
export function scenePath(scene) {
  const k = shearingIndex(scene);
  if (k < 0) return '';
  const stage = scene.stages[k];
  return stage.type === 'biaxial' && stage.lateral === 'constant_volume' ? 'constant_volume' : stage.type;
}
// Where each path keeps the stress it holds and its shearing rate: a new path takes over the
// consolidation pressure and the old path's rate, so switching keeps what was set.
const HELD_STRESS = { biaxial: 'pressure', rotation: 'mean_stress', cyclic: 'pressure', simple_shear: 'normal_stress' };
const RATE = { biaxial: 'strain_rate', rotation: 'deviatoric_strain_rate', cyclic: 'strain_rate', simple_shear: 'shear_rate' };
function applyPath(scene, name) {
  const k = shearingIndex(scene);
  if (k < 0 || !PATH_STAGES[name] || scenePath(scene) === name) return;
  const old = scene.stages[k];
  const stage = structuredClone(PATH_STAGES[name]);
  const confining = scene.stages.find((s) => s.type === 'isotropic')?.pressure ?? old[HELD_STRESS[old.type]];
  if (confining !== undefined && HELD_STRESS[stage.type] && stage.lateral !== 'constant_volume') {
    stage[HELD_STRESS[stage.type]] = confining;
  }
  const rate = old[RATE[old.type]];
  if (rate !== undefined) {
    // A rotation keeps its deviatoric strain per turn (0.3) at the new rate.
    if (stage.type === 'rotation') stage.duration = Number(((stage.duration * stage[RATE.rotation]) / rate).toPrecision(12));
    stage[RATE[stage.type]] = rate;
  }
  scene.stages[k] = stage;
}
const hasAssembly = (scene) => Boolean(scene.assembly);
// A periodic cell (docs/periodic-cell.md): an assembly's cell is the square its particles are
// placed in; explicit particles need the cell's size.
const periodic = (scene) => scene.boundary?.type === 'periodic';
const explicitCell = (scene) => periodic(scene) && !scene.assembly;
// Clumps share the elongated polygons' sizes, aspect ratio and orientation keys.
const elongated = (scene) => scene.assembly?.shape === 'elongated' || scene.assembly?.shape === 'clump';

/**
 * Shape fidelity (docs/shape-fidelity.md): the representations `grainlab shapes` compared with
 * the paper's hexagons, each with its measured cost and bias from web/tables/shape-fidelity.json
 * (generated from the study's table by scripts/shape-fidelity-json). Choosing one rewrites
 * the assembly (keeping its size, and its orientation where the shape has one) and the
 * rolling friction.
 */
let shapeFidelity = null;
/** The table the dashboard serves (null: not loaded; the field then shows no figures). */
export function useShapeFidelityTable(table) {
  shapeFidelity = table;
}
const HEXAGON_LENGTH_OVER_WIDTH = Math.sqrt(3);  // the presets' clumps: the hexagons' length over width
export const REPRESENTATIONS = [
  ['hexagons', 'hexagons (the reference)'], ['clumps-2', 'clumps of 2 discs'], ['clumps-3', 'clumps of 3 discs'],
  ['clumps-5', 'clumps of 5 discs'], ['rolling', 'discs with rolling resistance'], ['discs', 'discs'],
];
/** The scene's representation: one of REPRESENTATIONS' keys, or 'custom'. */
export function sceneRepresentation(scene) {
  const a = scene.assembly;
  if (!a) return 'custom';
  if (a.shape === 'elongated') return (a.vertices ?? 6) === 6 && (a.aspect_ratio ?? 1.5) === 1.5 ? 'hexagons' : 'custom';
  if (a.shape === 'clump') {
    const name = `clumps-${a.clump_discs ?? 3}`;
    return REPRESENTATIONS.some(([key]) => key === name) ? name : 'custom';
  }
  return (scene.material?.rolling_friction ?? 0) > 0 ? 'rolling' : 'discs';
}
function applyRepresentation(scene, name) {
  const old = scene.assembly;
  if (!old || !REPRESENTATIONS.some(([key]) => key === name) || sceneRepresentation(scene) === name) return;
  const size = { specimen_diameter: old.specimen_diameter };
  const orientation = old.orientation === 'bedding'
    ? { orientation: 'bedding', bedding_angle_deg: old.bedding_angle_deg }
    : { orientation: 'random' };
  const material = scene.material ?? (scene.material = {});
  delete material.rolling_friction;
  delete material.rolling_damping;
  if (name === 'hexagons') {
    scene.assembly = { shape: 'elongated', aspect_ratio: 1.5, vertices: 6, ...orientation, ...size };
  } else if (name.startsWith('clumps-')) {
    scene.assembly = {
      shape: 'clump', clump_discs: Number(name.slice(7)), aspect_ratio: HEXAGON_LENGTH_OVER_WIDTH, ...orientation, ...size,
    };
  } else {
    scene.assembly = { shape: 'disc', disc_radius: 0.002, ...size };
    if (name === 'rolling') {
      // The measured μ_r nearest the calibrated one (the preset's 0.1 without a table), with the
      // presets' damper.
      const offered = shapeFidelity?.rolling_representation;
      material.rolling_friction = offered ? Number(offered.slice('rolling-'.length)) : 0.1;
      material.rolling_damping = 0.3;
    }
  }
}
// What the dashboard shows of each representation: the quantity, its label, its unit's decimals.
export const SHAPE_FIDELITY_QUANTITIES = [
  ['peak_phi_mob_deg', 'peak φ_mob', 1, '°'], ['void_ratio_consolidated', 'void ratio after consolidation', 3, ''],
  ['a_c_5', 'a_c at 5% strain', 3, ''], ['theta_sigma_5_deg', 'θσ at 5% strain', 1, '°'], ['omega_5_deg', 'ω at 5% strain', 1, '°'],
];
const signed = (value, decimals) => `${value > 0 ? '+' : value < 0 ? '−' : ''}${Math.abs(value).toFixed(decimals)}`;
const plain = (value, decimals) => `${value < 0 ? '−' : ''}${Math.abs(value).toFixed(decimals)}`;
/**
 * The measured cost and bias of the scene's representation, from the loaded table: null when
 * there is no table or no measurement for it (rolling discs at a μ_r the study did not run).
 * The assembly is the bedding-30 one when the scene is bedded, else the random one; discs have
 * no orientation, so theirs are against the random assembly's hexagons.
 */
export function shapeFidelityFigures(scene) {
  const name = sceneRepresentation(scene);
  if (!shapeFidelity || name === 'custom') return null;
  const assembly = scene.assembly?.orientation === 'bedding' ? 'bedding-30' : 'random';
  // Rolling discs: the figures of the ensemble at the scene's own μ_r, if there is one.
  const key = name === 'rolling' ? `rolling-${scene.material.rolling_friction}` : name;
  const measured = shapeFidelity.assemblies?.[assembly]?.[key];
  if (!measured) return null;
  const rows = SHAPE_FIDELITY_QUANTITIES.map(([quantity, label, decimals, unit]) => {
    const q = measured.quantities[quantity];
    if (!q) return null;
    const text = name === 'hexagons' || q.bias === null
      ? `${plain(q.mean, decimals)}${unit} (${plain(q.mean_ci_low, decimals)} to ${plain(q.mean_ci_high, decimals)})`
      : `${signed(q.bias, decimals)}${unit} (${plain(q.bias_ci_low, decimals)} to ${plain(q.bias_ci_high, decimals)})`;
    return { quantity, label, text };
  }).filter(Boolean);
  const rolling = name === 'rolling' ? `, μᵣ = ${measured.rolling_friction}` : '';
  return {
    heading: `Measured by grainlab shapes (${shapeFidelity.size} specimens, ${measured.seeds} seeds, ${assembly} assembly${rolling}): ` +
      (name === 'hexagons'
        ? `${measured.cpu_s.toFixed(1)} CPU s per run; the reference's means, 95% interval:`
        : `cost ${measured.cost_ratio.toFixed(2)}× the hexagons' per run; bias against them, 95% interval:`),
    cost: measured.cost_ratio,
    rows,
  };
}

/**
 * kind: number | integer | text | select. factor: scene value = shown value × factor.
 * visible(scene): whether the scene has the part the field edits. fallback: what a select
 * shows when the key is absent (the engine's default).
 */
export const SCENE_FIELDS = [
  { section: 'Run' },
  { key: 'name', label: 'Name', kind: 'text', paths: fixed('name') },
  { key: 'seed', label: 'Random seed', kind: 'integer', paths: fixed('seed') },
  { section: 'Material' },
  { key: 'friction', label: 'Friction coefficient μ', kind: 'number', paths: fixed('material.friction') },
  { key: 'normal_stiffness', label: 'Normal stiffness kₙ', unit: 'N/m', kind: 'number', paths: fixed('material.normal_stiffness') },
  { key: 'tangential_stiffness', label: 'Tangential stiffness kₜ', unit: 'N/m', kind: 'number', paths: fixed('material.tangential_stiffness') },
  {
    key: 'rolling_friction', label: 'Rolling friction μᵣ', kind: 'number', paths: fixed('material.rolling_friction'),
    visible: (scene) => !elongated(scene), hint: 'discs only: a couple up to μᵣ R* fₙ resists rolling; empty: none (docs/shape-fidelity.md)',
  },
  { section: 'Loading' },
  {
    key: 'confining', label: 'Confining stress', unit: 'kPa', kind: 'number', factor: 1e3,
    paths: stagePaths(['isotropic', 'biaxial', 'cyclic'], 'pressure'),
    hint: 'the consolidation pressure and the shearing stage\'s constant σ₁₁',
  },
  {
    key: 'path', label: 'Loading path', kind: 'select',
    paths: (scene) => (shearingIndex(scene) >= 0 ? [`stages[${shearingIndex(scene)}].type`] : []),
    options: [['biaxial', 'biaxial, constant σ₁₁ (the paper)'], ['constant_volume', 'biaxial, constant volume'],
      ['rotation', 'rotation of principal axes'], ['cyclic', 'cyclic biaxial'], ['simple_shear', 'simple shear']],
    display: scenePath, apply: applyPath,
    hint: 'replaces the shearing stage (docs/loading-paths.md)',
  },
  {
    key: 'lateral', label: 'Lateral boundary', kind: 'select', paths: stagePaths(['biaxial', 'cyclic'], 'lateral'),
    options: [['constant_stress', 'constant σ₁₁'], ['constant_volume', 'constant volume (area)']], fallback: 'constant_stress',
  },
  { key: 'strain_rate', label: 'Axial strain rate', unit: '1/s', kind: 'number', paths: stagePaths(['biaxial', 'cyclic'], 'strain_rate') },
  { key: 'target_axial_strain', label: 'Final axial strain', unit: '%', kind: 'number', factor: 0.01, paths: stagePaths(['biaxial'], 'target_axial_strain') },
  {
    key: 'deviatoric_strain_rate', label: 'Deviatoric strain rate ε̇₁ − ε̇₃', unit: '1/s', kind: 'number',
    paths: stagePaths(['rotation'], 'deviatoric_strain_rate'),
  },
  {
    key: 'total_rotation_deg', label: 'Total rotation', unit: '°', kind: 'number', paths: stagePaths(['rotation'], 'total_rotation_deg'),
    hint: 'counter-clockwise positive; with the duration it sets the rotation rate',
  },
  { key: 'rotation_duration', label: 'Duration', unit: 's', kind: 'number', paths: stagePaths(['rotation'], 'duration') },
  { key: 'mean_stress', label: 'Mean stress held', unit: 'kPa', kind: 'number', factor: 1e3, paths: stagePaths(['rotation'], 'mean_stress') },
  {
    key: 'initial_direction_deg', label: 'Initial strain-rate direction', unit: '°', kind: 'number',
    paths: stagePaths(['rotation'], 'initial_direction_deg'), hint: '90° = vertical compression, as the biaxial test',
  },
  { key: 'strain_amplitude', label: 'Axial strain amplitude', unit: '%', kind: 'number', factor: 0.01, paths: stagePaths(['cyclic'], 'strain_amplitude') },
  // Shown for a cyclic stage that reverses at stress ratios (set in the JSON instead of the
  // amplitude): the two limits of (σ22 − σ11)/(σ22 + σ11).
  ...[0, 1].map((end) => ({
    key: `q_over_p_${end ? 'upper' : 'lower'}`, label: `${end ? 'Upper' : 'Lower'} q/p limit`, kind: 'number',
    paths: (scene) => stagePaths(['cyclic'], 'q_over_p_limits')(scene)
      .filter((path) => Array.isArray(getPath(scene, path))).map((path) => `${path}[${end}]`),
  })),
  { key: 'cycles', label: 'Cycles', kind: 'integer', paths: stagePaths(['cyclic'], 'cycles') },
  { key: 'shear_rate', label: 'Shear rate γ̇', unit: '1/s', kind: 'number', paths: stagePaths(['simple_shear'], 'shear_rate') },
  { key: 'normal_stress', label: 'Normal stress σ₂₂ held', unit: 'kPa', kind: 'number', factor: 1e3, paths: stagePaths(['simple_shear'], 'normal_stress') },
  { key: 'target_shear_strain', label: 'Final shear strain γ', unit: '%', kind: 'number', factor: 0.01, paths: stagePaths(['simple_shear'], 'target_shear_strain') },
  { section: 'Specimen' },
  {
    key: 'boundary', label: 'Boundary', kind: 'select', paths: fixed('boundary.type'),
    options: [['membrane', 'membrane ring (the paper)'], ['periodic', 'periodic cell'], ['none', 'none']], fallback: 'none',
    hint: 'periodic: no boundary, the particles fill a cell that tiles the plane; its own stages are isotropic, biaxial, simple shear (docs/periodic-cell.md)',
  },
  ...[0, 1].map((k) => ({
    key: `cell_${k ? 'height' : 'width'}`, label: `Cell ${k ? 'height' : 'width'}`, unit: 'mm', kind: 'number', factor: 1e-3,
    paths: fixed(`boundary.size[${k}]`), visible: explicitCell,
    hint: 'explicit particles only: an assembly\'s cell is the square its particles are placed in',
  })),
  {
    key: 'rate_cap', label: 'Strain-rate cap', unit: '1/s', kind: 'number', paths: fixed('boundary.rate_cap'), visible: periodic,
    hint: 'the fastest strain rate the biaxial and simple-shear servos may command; empty: 3',
  },
  {
    key: 'representation', label: 'Shape fidelity', kind: 'select', paths: (scene) => (scene.assembly ? ['assembly'] : []),
    options: [['custom', 'custom'], ...REPRESENTATIONS], display: sceneRepresentation, apply: applyRepresentation,
    figures: shapeFidelityFigures, hint: 'particle shape by what it costs and how far it moves the results from the hexagons\' (docs/shape-fidelity.md)',
  },
  {
    key: 'shape', label: 'Particle shape', kind: 'select', paths: fixed('assembly.shape'), visible: hasAssembly,
    options: [['disc', 'circular discs'], ['elongated', 'elongated polygons'], ['clump', 'clumps of discs in a line']], fallback: 'disc',
  },
  { key: 'aspect_ratio', label: 'Aspect ratio', kind: 'number', paths: fixed('assembly.aspect_ratio'), visible: elongated },
  { key: 'clump_discs', label: 'Discs per clump', kind: 'integer', paths: fixed('assembly.clump_discs'), visible: (scene) => scene.assembly?.shape === 'clump' },
  {
    key: 'orientation', label: 'Orientation', kind: 'select', paths: fixed('assembly.orientation'), visible: elongated,
    options: [['random', 'random'], ['bedding', 'bedding plane']], fallback: 'random',
  },
  {
    key: 'bedding_angle', label: 'Bedding angle α', unit: '°', kind: 'number', paths: fixed('assembly.bedding_angle_deg'),
    visible: (scene) => elongated(scene) && scene.assembly?.orientation === 'bedding',
  },
  { key: 'specimen_diameter', label: 'Specimen diameter', unit: 'mm', kind: 'number', factor: 1e-3, paths: fixed('assembly.specimen_diameter'), visible: hasAssembly },
  { section: 'Solver' },
  {
    key: 'engine', label: 'Engine', kind: 'select', paths: fixed('solver.engine'),
    options: [['dem', 'DEM (contact springs)'], ['box2d', 'Box2D rigid bodies']], fallback: 'dem',
    hint: 'box2d: Box2D\'s rigid-body solver (docs/speed-accuracy.md)',
  },
  {
    key: 'timestep_safety', label: 'Timestep safety', kind: 'number', paths: fixed('solver.timestep_safety'),
    hint: 'fraction of the critical timestep',
  },
  {
    // Sets three fields at once; shown as 'custom' when the scene matches none of them.
    key: 'fidelity', label: 'Fidelity', kind: 'select',
    paths: (scene) => (biaxialStages(scene).length > 0 ? ['solver.timestep_safety'] : []),
    options: [['custom', 'custom'], ['draft', 'draft (I = 3e-4)'], ['standard', 'standard (I = 1e-4)'],
      ['reference', 'reference (I = 1e-4, safety 0.05)']],
    display: sceneFidelity, apply: applyFidelity,
    hint: 'timestep safety, sampling and shearing rate, measured by grainlab tradeoff',
  },
];

export function fieldVisible(field, scene) {
  if (field.visible && !field.visible(scene)) return false;
  return field.paths(scene).length > 0;
}

/** The scene's value as the form shows it ('' when the key is absent: the default applies). */
export function displayValue(field, scene) {
  if (field.display) return field.display(scene);
  const value = getPath(scene, field.paths(scene)[0]);
  if (value === undefined || value === null) return field.fallback ?? '';
  if (field.kind === 'number' && typeof value === 'number') {
    const shown = Number((value / (field.factor ?? 1)).toPrecision(12));
    // Stiffnesses read better as 3e+8 than as 300000000.
    return Math.abs(shown) >= 1e6 ? shown.toExponential() : String(shown);
  }
  return String(value);
}

/**
 * Writes the text typed into the field into the scene. Returns an error message for text that
 * is not a value of the field's kind (the scene is then left as it was), else null.
 */
export function applyValue(field, scene, text) {
  const trimmed = text.trim();
  if (field.apply) {
    field.apply(scene, trimmed);
    return null;
  }
  let value;
  if (trimmed === '') {
    value = undefined;  // omitted: the engine's documented default
  } else if (field.kind === 'number' || field.kind === 'integer') {
    const number = Number(trimmed);
    if (!Number.isFinite(number)) return 'must be a number';
    if (field.kind === 'integer' && !Number.isInteger(number)) return 'must be a whole number';
    value = field.kind === 'number' ? number * (field.factor ?? 1) : number;
  } else {
    value = trimmed;
  }
  for (const path of field.paths(scene)) setPath(scene, path, value);
  return null;
}

/** The field whose paths include the API's error field ("material.friction"), or null. */
export function fieldForPath(scene, path) {
  if (!path) return null;
  // An error about a list ("boundary.size") belongs to the field of its first element.
  return SCENE_FIELDS.find((field) => field.paths && field.paths(scene).includes(path)) ??
    SCENE_FIELDS.find((field) => field.paths && field.paths(scene).some((p) => p.startsWith(`${path}[`))) ?? null;
}

/** One line about a preset's scene: particles, specimen, stages. */
export function describeScene(scene) {
  const parts = [];
  const a = scene.assembly;
  if (a) {
    const orientation = a.orientation === 'bedding' ? `bedding α = ${a.bedding_angle_deg}°` : 'random orientation';
    const shape = a.shape === 'clump'
      ? `clumps of ${a.clump_discs ?? 3} discs (aspect ${a.aspect_ratio ?? 'default'}, ${orientation})`
      : a.shape === 'elongated'
      ? `elongated polygons (aspect ${a.aspect_ratio ?? 'default'}, ${a.orientation === 'bedding' ? `bedding α = ${a.bedding_angle_deg}°` : 'random orientation'})`
      : `discs of radius ${(a.disc_radius ?? 0.002) * 1e3} mm`;
    parts.push(`${shape} in a ${(a.specimen_diameter ?? 0) * 1e3} mm specimen`);
  } else if (scene.particles) {
    parts.push(`${scene.particles.length} explicit particles`);
  }
  if (scene.stages?.length) parts.push(`stages: ${scene.stages.map((s) => s.name ?? s.type).join(' → ')}`);
  return parts.join('; ');
}
