// Rose diagrams of the polar histograms (engine/analysis/histogram.hpp's JSON): per-bin bars
// over the full circle (a direction θ and θ + 180° are the same contact normal) and the
// fitted c0 + c1 cos 2θ + c2 sin 2θ curve on top. θ is measured from the horizontal (1-axis),
// counter-clockwise, as in the paper's Fig. 1.
import { forcePerMetre, millimetres, sig } from './format.js';

/** The five diagrams: which per-bin values and which fit each one draws. */
export const ROSES = [
  {
    key: 'density', title: 'Contact normals E(θ)', fit: 'density',
    values: (h) => h.count.map((c) => (h.ends > 0 ? (c * h.bins) / h.ends : null)),
    format: (v) => sig(v, 2), coefficient: 'a_c', direction: 'theta_c_deg',
  },
  {
    key: 'fn', title: 'Normal force f̄ₙ(θ)', fit: 'fn', values: (h) => h.fn,
    format: forcePerMetre, coefficient: 'a_n', direction: 'theta_n_deg',
  },
  {
    key: 'ft', title: 'Tangential force f̄ₜ(θ)', fit: 'ft', values: (h) => h.ft, reference: 'fn',
    format: forcePerMetre, coefficient: 'a_t', direction: 'theta_t_deg',
  },
  {
    key: 'ln', title: 'Normal branch l̄ₙ(θ)', fit: 'ln', values: (h) => h.ln,
    format: millimetres, coefficient: 'a_ln', direction: 'theta_ln_deg',
  },
  {
    key: 'lt', title: 'Tangential branch l̄ₜ(θ)', fit: 'lt', values: (h) => h.lt, reference: 'ln',
    format: millimetres, coefficient: 'a_lt', direction: 'theta_lt_deg',
  },
];

const POSITIVE = 'rgba(36, 99, 166, 0.55)';
const NEGATIVE = 'rgba(230, 126, 34, 0.6)';
const FIT = '#b3261e';

function fitValue(fit, thetaRad) {
  return fit.c0 + fit.c1 * Math.cos(2 * thetaRad) + fit.c2 * Math.sin(2 * thetaRad);
}

/** Draws one diagram; `histogram` is the "histograms" object of a histogram message (or null). */
export function drawRose(canvas, rose, histogram) {
  const ratio = window.devicePixelRatio || 1;
  const size = Math.max(1, Math.round(canvas.clientWidth * ratio));
  if (canvas.width !== size || canvas.height !== size) {
    canvas.width = size;
    canvas.height = size;
  }
  const ctx = canvas.getContext('2d');
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, size, size);
  ctx.scale(ratio, ratio);
  const css = size / ratio;
  const cx = css / 2, cy = css / 2 + 6, radius = css / 2 - 22;

  ctx.fillStyle = '#1d2733';
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.fillText(rose.title, cx, 13);
  drawAxes(ctx, cx, cy, radius);
  if (!histogram) return;

  const values = rose.values(histogram);
  const fit = histogram.fits[rose.fit];
  const width = (histogram.bin_width_deg * Math.PI) / 180;
  let largest = 0;
  for (const v of values) if (v !== null && Number.isFinite(v)) largest = Math.max(largest, Math.abs(v));
  for (let d = 0; d < 180; d += 2) largest = Math.max(largest, Math.abs(fitValue(fit, (d * Math.PI) / 180)));
  // f_t and l_t vanish for discs (to rounding): drawn to scale they would be noise.
  const reference = rose.reference ? Math.abs(histogram.fits[rose.reference].c0) : largest;
  if (!(largest > 0) || largest < 1e-6 * reference) {
    ctx.fillStyle = '#5d6b7a';
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillText('≈ 0 in every direction', cx, cy + 4);
    return;
  }
  const toRadius = radius / largest;

  // Bars: each bin and its mirror half a turn away; canvas y points down, hence −θ.
  for (let b = 0; b < histogram.bins; b++) {
    const v = values[b];
    if (v === null || !Number.isFinite(v) || v === 0) continue;
    const centre = (histogram.centres_deg[b] * Math.PI) / 180;
    ctx.fillStyle = v >= 0 ? POSITIVE : NEGATIVE;
    for (const turn of [0, Math.PI]) {
      ctx.beginPath();
      ctx.moveTo(cx, cy);
      ctx.arc(cx, cy, Math.abs(v) * toRadius, -(centre + turn + width / 2), -(centre + turn - width / 2));
      ctx.closePath();
      ctx.fill();
    }
  }

  // The fitted curve, |value| as radius; dashed where the fit is negative (f_t, l_t change sign).
  ctx.strokeStyle = FIT;
  ctx.lineWidth = 1.6;
  for (const negative of [false, true]) {
    ctx.setLineDash(negative ? [4, 3] : []);
    ctx.beginPath();
    let drawing = false;
    for (let d = 0; d <= 360; d += 1) {
      const theta = (d * Math.PI) / 180;
      const v = fitValue(fit, theta);
      if ((v < 0) !== negative) {
        drawing = false;
        continue;
      }
      const x = cx + Math.abs(v) * toRadius * Math.cos(theta);
      const y = cy - Math.abs(v) * toRadius * Math.sin(theta);
      if (drawing) ctx.lineTo(x, y);
      else ctx.moveTo(x, y);
      drawing = true;
    }
    ctx.stroke();
  }
  ctx.setLineDash([]);

  ctx.fillStyle = '#5d6b7a';
  ctx.font = '10px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.fillText(`outer ring ${rose.format(largest)}`, 4, css - 4);
}

function drawAxes(ctx, cx, cy, radius) {
  ctx.strokeStyle = '#d8dee6';
  ctx.lineWidth = 1;
  for (const f of [0.5, 1]) {
    ctx.beginPath();
    ctx.arc(cx, cy, radius * f, 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.beginPath();
  ctx.moveTo(cx - radius, cy);
  ctx.lineTo(cx + radius, cy);
  ctx.moveTo(cx, cy - radius);
  ctx.lineTo(cx, cy + radius);
  ctx.stroke();
  ctx.fillStyle = '#8996a3';
  ctx.font = '10px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.fillText('0°', cx + radius + 2, cy + 3);
  ctx.textAlign = 'center';
  ctx.fillText('90°', cx, cy - radius - 3);
}

/** "a_c = 0.21, θ_c = 93°" from the series row of the histogram's sample. */
export function roseCaption(rose, row) {
  if (!row) return '';
  const a = row[rose.coefficient], theta = row[rose.direction];
  const name = rose.coefficient.replace('a_', '');
  return `a_${name} = ${sig(a, 3)}, θ_${name} = ${sig(theta, 3)}°`;
}
