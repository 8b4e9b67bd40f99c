// The Studies view's launch form as a sweep spec (docs/sweeps.md): the same JSON `grainlab
// sweep` reads and POST /api/studies takes. Kept apart from the view so it can be tested
// without a page.

/** "0.3, 0.5, dense" -> [0.3, 0.5, "dense"]: each piece as JSON where it reads as JSON, else a string. */
export function parseValues(text) {
  const pieces = [];
  // Commas inside brackets or quotes belong to the value ([0, -9.81], "a, b").
  let depth = 0, start = 0, quoted = false;
  for (let i = 0; i <= text.length; i++) {
    const c = text[i];
    if (quoted && i < text.length) {
      if (c === '\\') i++;
      else if (c === '"') quoted = false;
      continue;
    }
    if (c === '"') quoted = true;
    else if (c === '[' || c === '{') depth++;
    else if (c === ']' || c === '}') depth--;
    if (i === text.length || (c === ',' && depth === 0)) {
      const piece = text.slice(start, i).trim();
      if (piece) pieces.push(piece);
      start = i + 1;
    }
  }
  return pieces.map((piece) => {
    try {
      return JSON.parse(piece);
    } catch {
      return piece;
    }
  });
}

function refuse(field, message) {
  const error = new Error(message);
  error.field = field;
  throw error;
}

/**
 * {name, preset, mode, seeds: "1, 2", rows: [{path, values: "0.3, 0.5"}]} as a spec; throws an
 * Error with .field for what the form cannot send (an empty path, a row without values).
 */
export function sweepSpec({ name, preset, mode, seeds, rows }) {
  const vary = {};
  for (const row of rows) {
    if (!row.path && !row.values.trim()) continue;  // an empty row is no row
    if (!row.path) refuse('vary', 'a row has values but no scene path');
    const values = parseValues(row.values);
    if (!values.length) refuse(`vary.${row.path}`, 'give at least one value');
    if (row.path in vary) refuse(`vary.${row.path}`, 'this path is in two rows');
    vary[row.path] = values;
  }
  const seedValues = parseValues(seeds ?? '');
  if (seedValues.length) {
    if ('seed' in vary) refuse('vary.seed', 'seed is both a row and the seeds box');
    vary.seed = seedValues;
  }
  if (!Object.keys(vary).length) refuse('vary', 'give at least one scene path with values, or seeds');
  const spec = { name, base: { preset }, vary };
  if (mode && mode !== 'grid') spec.mode = mode;
  return spec;
}

/** How many runs the spec makes: the product of the lists (grid) or their length (zip). */
export function runCount(spec) {
  const lengths = Object.values(spec.vary).map((v) => v.length);
  if (spec.mode === 'zip') {
    if (new Set(lengths).size > 1) refuse('vary', `zip takes lists of one length, not ${lengths.join(', ')}`);
    return lengths[0];
  }
  return lengths.reduce((a, b) => a * b, 1);
}
