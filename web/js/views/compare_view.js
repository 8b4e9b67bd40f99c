// Compare: several runs overlaid on the same charts (one quantity per chart, one line per
// run) against axial strain in the shearing stage, as the paper compares bedding angles.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { ChartPanel, joinTables } from '../chart_panel.js';
import { COMPARE_CHARTS, X_AXES, chartDomain } from '../chart_specs.js';
import { SeriesTable, shearingStages } from '../series_table.js';
import { ensembleBand } from '../ensemble_stats.js';

// The picker offers this many of the newest runs (and the chosen ones besides).
const PICKER_RUNS = 100;

export function compareView(root, params) {
  const chosen = new Set((params.get('ids') ?? '').split(',').map(Number).filter((n) => Number.isInteger(n) && n > 0));
  const picker = h('div', { class: 'compare-picker' });
  const status = h('div', { class: 'hint' });
  const grid = h('div', { class: 'compare-grid' });
  // Ensemble mode: the ticked runs as seeds of one ensemble, drawn as their mean and its 95 %
  // t-interval (on the first run's strains), with each run faint beneath.
  let asEnsemble = params.get('mode') === 'ensemble';
  const modeToggle = h('label', { class: 'compare-mode' },
    h('input', {
      type: 'checkbox', checked: asEnsemble, id: 'compare-ensemble',
      onchange: (event) => { asEnsemble = event.target.checked; redraw(); },
    }),
    'Mean of the ticked runs with its 95 % band (as seeds of one ensemble)');
  replaceChildren(root,
    h('div', { class: 'view-title' }, h('h2', {}, 'Compare runs'),
      h('span', { class: 'hint' }, 'Tick the runs to overlay; each chart shows one quantity against axial strain (shearing stage).')),
    h('div', { class: 'panel' }, picker, modeToggle, status),
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
    const mode = asEnsemble ? '&mode=ensemble' : '';
    history.replaceState(null, '', ids.length ? `#/compare?ids=${ids.join(',')}${mode}` : '#/compare');
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
      if (asEnsemble && runs.length >= 2) {
        panels.push(ensemblePanel(spec, runs, domains));
        continue;
      }
      const panel = new ChartPanel(grid, {
        key: spec.key,
        title: spec.title,
        xLabel: X_AXES.strain.label,
        series: runs.map(({ run }) => ({ label: `#${run.id} ${run.name}` })),
        axes: [{ label: spec.title }],
        // Runs sampled at other strains leave alignment holes that are spanned; a direction's own
        // gaps (below its noise floor) are kept.
        spanGaps: !spec.gaps,
        emptyText: 'None of these runs has reached its shearing stage.',
      });
      const tables = runs.map(({ table }, k) => [domains[k].x, spec.values(table, domains[k].rows)]);
      const joined = tables.some((t) => t[0].length) ? joinTables(tables) : [[], ...tables.map(() => [])];
      panel.setData(joined[0], joined.slice(1));
      panels.push(panel);
    }
  }

  function ensemblePanel(spec, runs, domains) {
    const tables = runs.map(({ table }, k) => [domains[k].x, spec.values(table, domains[k].rows)]);
    const band = ensembleBand(tables, { isAxial: Boolean(spec.gaps), quorum: Boolean(spec.gaps) });
    const colour = '#0072B2';
    const faint = runs.map(({ run }) => ({ label: `#${run.id}`, stroke: 'rgba(0, 0, 0, 0.25)', width: 0.8 }));
    const panel = new ChartPanel(grid, {
      key: spec.key,
      title: `${spec.title}: mean of ${runs.length} runs, 95 % band`,
      xLabel: X_AXES.strain.label,
      series: [...faint,
        { label: '95 % high', stroke: colour, width: 0.5 },
        { label: '95 % low', stroke: colour, width: 0.5 },
        { label: `mean of ${runs.length}`, stroke: colour, width: 2 }],
      bands: [{ series: [runs.length, runs.length + 1], fill: 'rgba(0, 114, 178, 0.18)' }],
      axes: [{ label: spec.title }],
      spanGaps: false,
      emptyText: 'None of these runs has reached its shearing stage.',
    });
    const x = band.x;
    const perRun = tables.map(([rx, ry]) => {
      // Each run on the mean's strains, so all series share one x.
      const out = [];
      let k = 0;
      for (const xi of x) {
        while (k < rx.length && rx[k] < xi) k++;
        out.push(k < rx.length && rx[k] === xi ? ry[k] : undefined);
      }
      return out;
    });
    panel.setData(x, [...perRun, band.high, band.low, band.mean]);
    panel.element.dataset.ensemble = String(runs.length);
    return panel;
  }

  (async () => {
    // The newest runs, and the chosen ones among older runs: never the whole list, which a
    // study makes thousands long (older runs are ticked from the runs list's pages).
    let runs = [];
    let total = 0;
    try {
      const page = await api.runsPage({ limit: PICKER_RUNS });
      total = page.total;
      const listed = new Set(page.runs.map((run) => run.id));
      const older = await Promise.all([...chosen].filter((id) => !listed.has(id))
        .map((id) => api.run(id).catch(() => null)));  // null: deleted since the link was made
      runs = [...page.runs, ...older.filter(Boolean).sort((a, b) => b.id - a.id)];
    } catch (error) {
      status.textContent = `Cannot list the runs: ${error.message}`;
    }
    if (destroyed) return;
    if (!runs.length) status.textContent = 'No runs yet.';
    else if (total > PICKER_RUNS) {
      picker.before(h('div', { class: 'hint' },
        `The ${PICKER_RUNS} newest of ${total} runs, and those ticked; tick older ones in the `,
        h('a', { href: '#/runs' }, 'runs list'), ' and press Compare selected.'));
    }
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
