// The run's charts against axial strain (the shearing stage, as the paper plots them), against
// the rotation of the strain-rate axes (a rotation stage), or against time (every stage, to
// watch compaction). Until the person picks one, the x axis is time while the shearing stage
// has not started and the shearing stage's own axis from its first sample on.
// Redrawn at most once per animation frame however fast samples arrive.
import { h } from './dom.js';
import { ChartPanel } from './chart_panel.js';
import { RUN_CHARTS, X_AXES, chartDomain } from './chart_specs.js';

export class RunCharts {
  /** shearingAxis: the x axis to switch to when shearing starts (series_table.js shearingAxis). */
  constructor(parent, shearing, shearingAxis = 'strain') {
    this.shearing = shearing;
    this.shearingAxis = shearingAxis;
    this.table = null;
    this.markerRow = null;
    this.pending = 0;
    this.chosen = false;  // the person picked the x axis: keep it
    this.xSelect = h('select', {
      'aria-label': 'x axis',
      onchange: () => {
        this.chosen = true;
        this.build();
      },
    },
      h('option', { value: 'strain' }, 'axial strain (shearing stage)'),
      h('option', { value: 'time' }, 'time (all stages)'),
      h('option', { value: 'rotation' }, 'rotation angle (shearing stage)'));
    this.xSelect.value = 'time';
    this.grid = h('div', { class: 'charts-grid' });
    this.element = h('section', {},
      h('div', { class: 'charts-head' }, h('h3', {}, 'Charts'), h('label', {}, 'x axis: ', this.xSelect),
        h('span', { class: 'hint' }, 'drag across a chart to zoom, double-click to zoom out')),
      this.grid);
    parent.append(this.element);
    this.panels = [];
    this.build();
  }

  get xAxis() {
    return X_AXES[this.xSelect.value];
  }

  build() {
    for (const panel of this.panels) panel.destroy();
    const emptyText = this.xAxis.shearingOnly
      ? 'The shearing stage has not started: choose time as the x axis to watch the earlier stages.'
      : 'No samples yet.';
    this.panels = RUN_CHARTS.map((spec) => new ChartPanel(this.grid, { ...spec, xLabel: this.xAxis.label, emptyText }));
    this.domain = null;
    this.draw();
  }

  update(table) {
    this.table = table;
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.draw();
    });
  }

  draw() {
    if (!this.table) return;
    const table = this.table;
    if (!this.chosen && this.xSelect.value === 'time' && this.shearingAxis !== 'time' && this.hasShearing(table)) {
      this.xSelect.value = this.shearingAxis;
      this.build();  // draws again with the new axis
      return;
    }
    this.domain = chartDomain(table, this.xAxis, this.shearing);
    const { rows, x } = this.domain;
    RUN_CHARTS.forEach((spec, k) => {
      this.panels[k].setData(x, spec.series.map((s) => s.values(table, rows)));
    });
    this.applyMarker();
  }

  hasShearing(table) {
    const stages = table.column('stage');
    return Boolean(stages && stages.some((stage) => this.shearing.has(stage)));
  }

  /** Marks series row `row` on every chart (or clears the mark for null). */
  setMarkerRow(row) {
    this.markerRow = row;
    this.applyMarker();
  }

  applyMarker() {
    let x = null;
    if (this.markerRow !== null && this.domain) {
      const at = this.domain.rows.indexOf(this.markerRow);
      if (at >= 0) x = this.domain.x[at];
    }
    for (const panel of this.panels) panel.setMarker(x);
  }

  destroy() {
    if (this.pending) cancelAnimationFrame(this.pending);
    for (const panel of this.panels) panel.destroy();
  }
}
