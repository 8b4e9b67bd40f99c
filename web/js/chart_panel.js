// One chart in a panel: uPlot, sized to its container, with an optional vertical marker at
// the replay position.
//
// Why uPlot: it draws straight to a canvas from column arrays, collapses the points that fall
// in one pixel column before stroking, and re-renders 10,000-point series in a few
// milliseconds in headless Chromium's software raster (tests/web/render_perf_test.mjs), where
// SVG charting libraries with a DOM node per point stall. It is an ES module in npm, served
// from web/node_modules with no bundler.
import uPlot from '../node_modules/uplot/dist/uPlot.esm.js';
import { h } from './dom.js';
import { sig } from './format.js';
import { SERIES_COLOURS } from './colour_scales.js';

const HEIGHT = 250;

export class ChartPanel {
  /**
   * @param {HTMLElement} parent
   * @param {{title: string, xLabel: string, series: {label, scale?, dash?, stroke?, width?}[],
   *          axes: {label, scale?, side?}[], spanGaps?: boolean,
   *          bands?: {series: [number, number], fill: string}[]}} spec
   *   bands: shade between two series (indices into spec.series, upper first), e.g. a 95 % interval.
   */
  constructor(parent, spec) {
    this.marker = null;
    this.points = 0;
    this.element = h('div', { class: 'chart-panel', dataset: { chart: spec.key ?? '' } },
      h('h3', {}, spec.title));
    this.empty = h('div', { class: 'chart-empty' }, spec.emptyText ?? 'No data yet.');
    this.body = h('div');
    this.element.append(this.empty, this.body);
    parent.append(this.element);

    const format = (_, v) => (v === null || v === undefined ? '–' : sig(v, 4));
    const scales = { x: { time: false } };
    for (const axis of spec.axes) scales[axis.scale ?? 'y'] = { auto: true };
    this.plot = new uPlot({
      width: Math.max(200, this.body.clientWidth || parent.clientWidth || 400),
      height: HEIGHT,
      scales,
      series: [
        { label: spec.xLabel, value: format },
        ...spec.series.map((s, k) => ({
          label: s.label,
          scale: s.scale ?? 'y',
          stroke: s.stroke ?? SERIES_COLOURS[k % SERIES_COLOURS.length],
          width: s.width ?? 1.5,
          dash: s.dash,
          spanGaps: spec.spanGaps ?? false,
          value: format,
        })),
      ],
      axes: [
        { label: spec.xLabel, labelSize: 18, size: 36 },
        ...spec.axes.map((a, k) => ({
          scale: a.scale ?? 'y',
          label: a.label,
          side: a.side ?? 3,
          labelSize: 18,
          size: 58,
          grid: { show: k === 0 },
          values: (_, ticks) => ticks.map((t) => sig(t, 3)),
        })),
      ],
      bands: (spec.bands ?? []).map((b) => ({ series: [b.series[0] + 1, b.series[1] + 1], fill: b.fill })),
      cursor: { drag: { x: true, y: false } },
      hooks: { draw: [(u) => this.drawMarker(u)] },
    }, [[], ...spec.series.map(() => [])], this.body);
    this.element.uplot = this.plot;  // what is plotted (uplot.data), for the tests to read

    this.resizeObserver = new ResizeObserver(() => {
      const width = this.body.clientWidth;
      if (width > 0 && width !== this.plot.width) this.plot.setSize({ width, height: HEIGHT });
    });
    this.resizeObserver.observe(this.body);
  }

  /** x ascending; ys one array per series, null for a gap. */
  setData(x, ys) {
    // Denser than the chart's pixel columns: 1-px lines, which Skia's software raster draws
    // on its hairline path, 4× faster than 1.5 px here, and the eye cannot separate them anyway.
    const width = x.length > this.plot.bbox.width / (window.devicePixelRatio || 1) ? 1 : 1.5;
    for (const series of this.plot.series.slice(1)) series.width = width;
    this.points = x.length;
    this.element.dataset.points = String(x.length);
    this.empty.style.display = x.length ? 'none' : '';
    this.plot.setData([x, ...ys]);
  }

  /** The replay position on the x axis, or null for none. */
  setMarker(x) {
    if (x === this.marker) return;
    this.marker = x;
    this.plot.redraw(false, false);
  }

  drawMarker(u) {
    if (this.marker === null || this.marker === undefined) return;
    const px = u.valToPos(this.marker, 'x', true);
    if (!Number.isFinite(px) || px < u.bbox.left || px > u.bbox.left + u.bbox.width) return;
    const ctx = u.ctx;
    ctx.save();
    ctx.setLineDash([]);  // a dashed series may have left its dash on the context
    ctx.strokeStyle = 'rgba(179, 38, 30, 0.8)';
    ctx.lineWidth = 1.5 * (window.devicePixelRatio || 1);
    ctx.beginPath();
    ctx.moveTo(px, u.bbox.top);
    ctx.lineTo(px, u.bbox.top + u.bbox.height);
    ctx.stroke();
    ctx.restore();
  }

  destroy() {
    this.resizeObserver.disconnect();
    this.plot.destroy();
    this.element.remove();
  }
}

/** Aligns several runs' (x, y) tables on one x axis for overlaying (uPlot.join). */
export function joinTables(tables) {
  return uPlot.join(tables);
}
