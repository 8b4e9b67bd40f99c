// Compare: several runs overlaid on the same charts (one quantity per chart, one line per
// run) against axial strain in the shearing stage, as the paper compares bedding angles.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { ChartPanel, joinTables } from '../chart_panel.js';
import { COMPARE_CHARTS, X_AXES, chartDomain } from '../chart_specs.js';
import { SeriesTable, shearingStages } from '../series_table.js';

export function compareView(root, params) {
  const chosen = new Set((params.get('ids') ?? '').split(',').map(Number).filter((n) => Number.isInteger(n) && n > 0));
  const picker = h('div', { class: 'compare-picker' });
  const status = h('div', { class: 'hint' });
  const grid = h('div', { class: 'compare-grid' });
  replaceChildren(root,
    h('div', { class: 'view-title' }, h('h2', {}, 'Compare runs'),
      h('span', { class: 'hint' }, 'Tick the runs to overlay; each chart shows one quantity against axial strain (shearing stage).')),
    h('div', { class: 'panel' }, picker, status),
    h('div', { style: { height: '0.8rem' } }),
    grid);

  const loaded = new Map();  // id → {run, table}
  let panels = [];
  let destroyed = false;
  let generation = 0;

  async function load(id) {
    if (!loaded.has(id)) {
      const [run, series] = await Promise.all([api.run(id), api.series(id)]);
      loaded.set(id, { run, table: SeriesTable.fromRest(series) });
    }
    return loaded.get(id);
  }

  async function redraw() {
    const mine = ++generation;
    const ids = [...chosen].sort((a, b) => a - b);
    history.replaceState(null, '', ids.length ? `#/compare?ids=${ids.join(',')}` : '#/compare');
    let runs;
    try {
      runs = await Promise.all(ids.map(load));
    } catch (error) {
      status.textContent = `Loading a run failed: ${error.message}`;
      return;
    }
    if (destroyed || mine !== generation) return;
    status.textContent = ids.length ? '' : 'Pick at least one run.';
    for (const panel of panels) panel.destroy();
    panels = [];
    if (!runs.length) return;
    const domains = runs.map(({ run, table }) => chartDomain(table, X_AXES.strain, shearingStages(run.scene)));
    for (const spec of COMPARE_CHARTS) {
      const panel = new ChartPanel(grid, {
        key: spec.key,
        title: spec.title,
        xLabel: X_AXES.strain.label,
        series: runs.map(({ run }) => ({ label: `#${run.id} ${run.name}` })),
        axes: [{ label: spec.title }],
        spanGaps: true,
        emptyText: 'None of these runs has reached its shearing stage.',
      });
      const tables = runs.map(({ table }, k) => [domains[k].x, spec.values(table, domains[k].rows)]);
      const joined = tables.some((t) => t[0].length) ? joinTables(tables) : [[], ...tables.map(() => [])];
      panel.setData(joined[0], joined.slice(1));
      panels.push(panel);
    }
  }

  (async () => {
    let runs = [];
    try {
      runs = await api.runs();
    } catch (error) {
      status.textContent = `Cannot list the runs: ${error.message}`;
    }
    if (destroyed) return;
    if (!runs.length) status.textContent = 'No runs yet.';
    const known = new Set(runs.map((run) => run.id));
    for (const id of chosen) if (!known.has(id)) chosen.delete(id);  // deleted since the link was made
    replaceChildren(picker, runs.map((run) => h('label', {},
      h('input', {
        type: 'checkbox', checked: chosen.has(run.id), dataset: { runId: String(run.id) },
        onchange: (event) => {
          if (event.target.checked) chosen.add(run.id); else chosen.delete(run.id);
          redraw();
        },
      }),
      `#${run.id} ${run.name}`, h('span', { class: `status ${run.status}` }, run.status))));
    redraw();
  })();

  return {
    destroy() {
      destroyed = true;
      for (const panel of panels) panel.destroy();
    },
  };
}
