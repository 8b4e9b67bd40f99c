// Colour palettes as precomputed CSS strings: the renderer batches particles by palette
// entry, so a palette is also the number of fill calls per frame.

/** Interpolates `stops` ([r, g, b] 0..255) into `size` CSS colours. */
function ramp(stops, size) {
  const out = [];
  for (let k = 0; k < size; k++) {
    const t = (k / (size - 1)) * (stops.length - 1);
    const lo = Math.min(Math.floor(t), stops.length - 2);
    const f = t - lo;
    const c = stops[lo].map((a, i) => Math.round(a + (stops[lo + 1][i] - a) * f));
    out.push(`rgb(${c[0]},${c[1]},${c[2]})`);
  }
  return out;
}

/** Mean contact force: pale yellow (no force) through orange and red to dark purple. */
export const FORCE_PALETTE = ramp(
  [[255, 250, 215], [254, 217, 118], [253, 141, 60], [227, 26, 28], [128, 0, 38], [60, 10, 60]], 32);

/** Orientation over 0..180°: a cyclic hue ring, since 0° and 180° are the same axis. */
export const ORIENTATION_PALETTE = Array.from({ length: 36 }, (_, k) => `hsl(${(k * 360) / 36}, 62%, 62%)`);

export const BOUNDARY_FILL = '#9aa5b1';
export const BOUNDARY_STROKE = '#3d4a57';
export const CHAIN_COLOUR = '#1c2430';  // opaque: blending would cost raster time

/** CSS linear-gradient of a palette, for legends. */
export function gradientCss(palette) {
  return `linear-gradient(to right, ${palette.join(', ')})`;
}

/** Distinct line colours for chart series (one per quantity or per run). */
export const SERIES_COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b',
  '#e377c2', '#17becf', '#7f7f7f', '#bcbd22'];
