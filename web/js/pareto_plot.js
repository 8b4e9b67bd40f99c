// A trade-off study's Pareto plot, as `grainlab tradeoff --seeds N` draws pareto.svg: per preset,
// each setting's shearing CPU time per run (log scale) against the mean over seeds of its mean
// |angle difference| from the same seed's reference, with that mean's 95 % interval as a bar;
// the settings on the Pareto front joined by a staircase, the noise probe's level dashed.
// Drawn from the server's panels (GET /api/studies/NAME/tradeoff): SVG, no chart library.
const SVG = 'http://www.w3.org/2000/svg';
const WIDTH = 560;
const HEIGHT = 340;
const MARGIN = { left: 62, right: 16, top: 28, bottom: 46 };
const AXIS_COLOURS = {
  reference: '#000000', baseline: '#555555', noise: '#999999', timestep_safety: '#0072B2',
  inertial_number: '#D55E00', vertices: '#009E73', sample_strain: '#CC79A7', engine: '#E69F00', box2d: '#56B4E9',
};

function el(name, attributes = {}, text) {
  const node = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
  if (text !== undefined) node.textContent = text;
  return node;
}

/** Tick values for a log axis between lo and hi: the powers of ten, with 2 and 5 when there are few. */
export function logTicks(lo, hi) {
  const ticks = [];
  for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); e++) {
    for (const m of [1, 2, 5]) {
      const v = m * 10 ** e;
      if (v >= lo && v <= hi) ticks.push(v);
    }
  }
  return ticks.length >= 2 ? ticks : [lo, hi];
}

/** Round tick values (1, 2 or 5 times a power of ten apart) covering lo..hi, about five of them. */
export function linearTicks(lo, hi) {
  const raw = (hi - lo) / 5;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw);
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) ticks.push(Math.abs(v) < 1e-9 * step ? 0 : v);
  return ticks;
}

/** The points a panel can draw: a cost > 0 and an error that is a number. */
export function drawable(points) {
  return points.filter((p) => p.cpu_s !== null && p.cpu_s > 0 && p.error_deg !== null);
}

/** One panel as an <svg>: each point a circle carrying its cpu_s and error_deg as data-*. */
export function paretoPanelSvg(panel) {
  const svg = el('svg', { class: 'pareto-plot', viewBox: `0 0 ${WIDTH} ${HEIGHT}`, width: WIDTH, height: HEIGHT, role: 'img' });
  svg.append(el('title', {}, panel.title));
  svg.append(el('text', { x: WIDTH / 2, y: 18, 'text-anchor': 'middle', class: 'pareto-title' }, panel.title));
  const points = drawable(panel.points);
  if (!points.length) {
    svg.append(el('text', { x: WIDTH / 2, y: HEIGHT / 2, 'text-anchor': 'middle' }, 'no setting measured'));
    return svg;
  }
  const xs = points.map((p) => p.cpu_s);
  const ys = points.flatMap((p) => [p.error_deg, p.error_low_deg, p.error_high_deg]).filter((v) => v !== null);
  if (panel.noise_floor_deg !== null) ys.push(panel.noise_floor_deg);
  const xLo = Math.min(...xs) / 1.5, xHi = Math.max(...xs) * 1.5;
  const yLo = Math.min(0, ...ys), yHi = Math.max(...ys) * 1.1 || 1;
  const plotW = WIDTH - MARGIN.left - MARGIN.right, plotH = HEIGHT - MARGIN.top - MARGIN.bottom;
  const x = (v) => MARGIN.left + (Math.log10(v) - Math.log10(xLo)) / (Math.log10(xHi) - Math.log10(xLo)) * plotW;
  const y = (v) => MARGIN.top + (1 - (v - yLo) / (yHi - yLo)) * plotH;

  const axes = el('g', { class: 'pareto-axes', stroke: '#888', 'font-size': 11 });
  axes.append(el('rect', { x: MARGIN.left, y: MARGIN.top, width: plotW, height: plotH, fill: 'none' }));
  for (const t of logTicks(xLo, xHi)) {
    axes.append(el('line', { x1: x(t), x2: x(t), y1: MARGIN.top + plotH, y2: MARGIN.top + plotH + 4 }));
    axes.append(el('text', { x: x(t), y: MARGIN.top + plotH + 16, 'text-anchor': 'middle', stroke: 'none', fill: 'currentColor' }, String(Number(t.toPrecision(3)))));
  }
  for (const v of linearTicks(yLo, yHi)) {
    axes.append(el('line', { x1: MARGIN.left - 4, x2: MARGIN.left, y1: y(v), y2: y(v) }));
    axes.append(el('text', { x: MARGIN.left - 7, y: y(v) + 4, 'text-anchor': 'end', stroke: 'none', fill: 'currentColor' }, String(Number(v.toPrecision(3)))));
  }
  axes.append(el('text', { x: MARGIN.left + plotW / 2, y: HEIGHT - 8, 'text-anchor': 'middle', stroke: 'none', fill: 'currentColor' }, 'CPU time of the shearing per run (s, log scale)'));
  axes.append(el('text', { x: 14, y: MARGIN.top + plotH / 2, 'text-anchor': 'middle', stroke: 'none', fill: 'currentColor', transform: `rotate(-90 14 ${MARGIN.top + plotH / 2})` }, 'mean |angle difference| (°), 95 %'));
  svg.append(axes);

  // No difference at all: where the reference sits (an interval may reach below it).
  if (yLo < 0) svg.append(el('line', { class: 'pareto-zero', x1: MARGIN.left, x2: MARGIN.left + plotW, y1: y(0), y2: y(0), stroke: '#ddd' }));
  if (panel.noise_floor_deg !== null) {
    svg.append(el('line', { class: 'pareto-noise', x1: MARGIN.left, x2: MARGIN.left + plotW, y1: y(panel.noise_floor_deg), y2: y(panel.noise_floor_deg), stroke: '#999', 'stroke-dasharray': '5 4' }));
  }
  // The front as a staircase: from each front point right, then down to the next.
  const front = points.filter((p) => p.on_front).sort((a, b) => a.cpu_s - b.cpu_s);
  if (front.length > 1) {
    let d = `M ${x(front[0].cpu_s)} ${y(front[0].error_deg)}`;
    for (const p of front.slice(1)) d += ` H ${x(p.cpu_s)} V ${y(p.error_deg)}`;
    svg.append(el('path', { class: 'pareto-front', d, fill: 'none', stroke: '#444', 'stroke-width': 1 }));
  }
  for (const p of points) {
    const colour = AXIS_COLOURS[p.axis] ?? '#333';
    const g = el('g', { class: 'pareto-point' });
    if (p.error_low_deg !== null && p.error_high_deg !== null) {
      g.append(el('line', { x1: x(p.cpu_s), x2: x(p.cpu_s), y1: y(p.error_low_deg), y2: y(p.error_high_deg), stroke: colour, 'stroke-width': 1.5 }));
    }
    const dot = el('circle', {
      cx: x(p.cpu_s), cy: y(p.error_deg), r: p.on_front ? 5 : 4, fill: p.on_front ? colour : '#fff', stroke: colour, 'stroke-width': 2,
      'data-cpu-s': p.cpu_s, 'data-error-deg': p.error_deg, 'data-label': p.label, 'data-axis': p.axis, 'data-on-front': p.on_front,
    });
    dot.append(el('title', {}, `${p.label}: ${Number(p.cpu_s.toPrecision(3))} s, ${Number(p.error_deg.toPrecision(3))}°`
      + (p.error_low_deg !== null ? ` (${Number(p.error_low_deg.toPrecision(3))} to ${Number(p.error_high_deg.toPrecision(3))})` : '')));
    g.append(dot);
    g.append(el('text', { x: x(p.cpu_s) + 7, y: y(p.error_deg) - 6, 'font-size': 11, fill: colour }, p.label));
    svg.append(g);
  }
  return svg;
}
