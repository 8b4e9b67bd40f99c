// The mean of several runs and its 95 % Student-t interval at each x, for the Compare view's
// ensemble mode: the same statistics as the report's (engine/studies/src/paper/ensemble_stats.cpp).

// t_{0.975} for 1..30 degrees of freedom; beyond, the Cornish-Fisher expansion.
const T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145,
  2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042];

export function studentT975(dof) {
  if (!(dof >= 1)) return NaN;
  if (dof <= 30) return T975[dof - 1];
  const z = 1.959964;
  return z + (z ** 3 + z) / (4 * dof) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * dof * dof);
}

const finite = (v) => v !== null && v !== undefined && Number.isFinite(v);

/** {n, mean, low, high} of the finite values; low/high null with fewer than two (no interval). */
export function meanInterval(values) {
  const xs = values.filter(finite);
  const n = xs.length;
  if (!n) return { n, mean: null, low: null, high: null };
  const mean = xs.reduce((a, b) => a + b, 0) / n;
  if (n < 2) return { n, mean, low: null, high: null };
  const variance = xs.reduce((a, b) => a + (b - mean) ** 2, 0) / (n - 1);
  const half = studentT975(n - 1) * Math.sqrt(variance / n);
  return { n, mean, low: mean - half, high: mean + half };
}

const axial = (deg) => ((deg % 180) + 180) % 180;
const axialOffset = (deg) => axial(deg + 90) - 90;

/** The same for axial directions (degrees): circular mean on 2θ, interval on the offsets from it. */
export function axialMeanInterval(values) {
  const xs = values.filter(finite);
  if (!xs.length) return { n: 0, mean: null, low: null, high: null };
  let c = 0, s = 0;
  for (const t of xs) {
    c += Math.cos((2 * t * Math.PI) / 180);
    s += Math.sin((2 * t * Math.PI) / 180);
  }
  const centre = axial((Math.atan2(s, c) * 90) / Math.PI);
  const m = meanInterval(xs.map((t) => axialOffset(t - centre)));
  const half = m.low === null ? null : (m.high - m.low) / 2;
  return { n: m.n, mean: centre, low: half === null ? null : centre - half, high: half === null ? null : centre + half };
}

/**
 * One run's y at the given xs (both ascending), linear between its samples; null outside its
 * range or beside a gap. `isAxial` interpolates directions along the shorter arc.
 */
export function valuesAt(runX, runY, xs, isAxial = false) {
  const out = [];
  let k = 1;
  for (const x of xs) {
    if (!runX.length) { out.push(null); continue; }
    if (x === runX[0]) { out.push(finite(runY[0]) ? runY[0] : null); continue; }
    if (k >= runX.length || !(runX[k - 1] <= x)) k = 1;
    while (k < runX.length && !(runX[k - 1] <= x && x <= runX[k])) k++;
    if (k >= runX.length) { out.push(null); continue; }
    const y0 = runY[k - 1], y1 = runY[k];
    if (x === runX[k]) out.push(finite(y1) ? y1 : null);
    else if (!finite(y0) || !finite(y1)) out.push(null);
    else {
      const w = (x - runX[k - 1]) / (runX[k] - runX[k - 1]);
      out.push(isAxial ? axial(y0 + w * axialOffset(y1 - y0)) : y0 + w * (y1 - y0));
    }
  }
  return out;
}

/**
 * Several runs' (x, y) on the first run's x: {x, mean, low, high, n}. With `quorum`, a mean of
 * fewer than half the runs is dropped (a direction meaningful in too few of them).
 */
export function ensembleBand(runs, { isAxial = false, quorum = false } = {}) {
  if (!runs.length) return { x: [], mean: [], low: [], high: [], n: [] };
  const x = runs[0][0];
  const columns = runs.map(([rx, ry]) => valuesAt(rx, ry, x, isAxial));
  const need = Math.max(1, Math.ceil(runs.length / 2));
  const band = { x, mean: [], low: [], high: [], n: [] };
  x.forEach((_, i) => {
    const m = (isAxial ? axialMeanInterval : meanInterval)(columns.map((c) => c[i]));
    const drop = quorum && m.n < need;
    band.mean.push(drop ? null : m.mean);
    band.low.push(drop ? null : m.low);
    band.high.push(drop ? null : m.high);
    band.n.push(m.n);
  });
  return band;
}
