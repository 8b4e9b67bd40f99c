// One study (#/studies/NAME): its progress and runs with the values each was given, and, once
// runs have finished, one quantity's ensemble mean with its 95 % band against axial strain
// (shearing stage), one line per value of the varied path chosen, with the table behind it
// as CSV. The statistics are ensemble_stats.js's, the charts the Compare view's.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { ChartPanel, joinTables } from '../chart_panel.js';
import { COMPARE_CHARTS, X_AXES, chartDomain } from '../chart_specs.js';
import { SeriesTable, shearingStages } from '../series_table.js';
import { ensembleBand } from '../ensemble_stats.js';
import { sig } from '../format.js';

const POLL_MS = 2000;
const UNDER_WAY = new Set(['running', 'queued']);
const BAND_COLOURS = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#000000'];

/**
 * The groups' bands: runs [{id, parameters, table, scene}] grouped by the value of `path`
 * (every run in one group when path is ''), each {value, ids, band}.
 */
export function studyBands(runs, path, spec) {
  const groups = new Map();
  for (const run of runs) {
    const value = path ? JSON.stringify(run.parameters?.[path] ?? null) : 'all runs';
    if (!groups.has(value)) groups.set(value, []);
    groups.get(value).push(run);
  }
  return [...groups].map(([value, members]) => {
    const tables = members.map((run) => {
      const domain = chartDomain(run.table, X_AXES.strain, shearingStages(run.scene));
      return [domain.x, spec.values(run.table, domain.rows)];
    }).filter(([x]) => x.length);
    const band = ensembleBand(tables, { isAxial: Boolean(spec.gaps), quorum: Boolean(spec.gaps) });
    return { value, ids: members.map((run) => run.id), band };
  });
}

/** The last strain every run of the group reaches, and the mean there: [x, mean, low, high, n] or null. */
export function commonEnd(group) {
  const { band } = group;
  for (let i = band.x.length - 1; i >= 0; i--) {
    if (band.n[i] === group.ids.length && band.mean[i] !== null) return [band.x[i], band.mean[i], band.low[i], band.high[i], band.n[i]];
  }
  return null;
}

/** The bands as CSV: axial strain, then mean, low, high, n per group. */
export function bandsCsv(groups, path, spec) {
  const header = ['axial_strain_percent'];
  for (const g of groups) for (const what of ['mean', 'low95', 'high95', 'n']) header.push(`${path || 'study'}=${g.value} ${what}`);
  const columns = groups.flatMap((g) => [[g.band.x, g.band.mean], [g.band.x, g.band.low], [g.band.x, g.band.high], [g.band.x, g.band.n]]);
  if (!columns.length) return `${header.join(',')}\n`;
  const joined = joinTables(columns);
  const quote = (text) => (/[",\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text);
  const lines = [`# ${spec.key}: ${spec.title}`, header.map(quote).join(',')];
  for (let i = 0; i < joined[0].length; i++) {
    lines.push([joined[0][i], ...joined.slice(1).map((c) => c[i])].map((v) => (v === null || v === undefined ? '' : String(v))).join(','));
  }
  return `${lines.join('\n')}\n`;
}

export function studyView(root, name) {
  const title = h('h2', {}, `Study ${name}`);
  const summary = h('div', { class: 'study-summary' });
  const message = h('div', { class: 'form-error', hidden: true });
  const runsBody = h('tbody');
  const pathSelect = h('select', { id: 'study-group', 'aria-label': 'Group by', onchange: () => drawBands() });
  const quantitySelect = h('select', { id: 'study-quantity', 'aria-label': 'Quantity', onchange: () => drawBands() },
    COMPARE_CHARTS.map((spec) => h('option', { value: spec.key }, spec.title)));
  const chartBox = h('div', { class: 'study-chart' });
  const bandTable = h('tbody');
  const download = h('a', { class: 'button', download: `${name}.csv`, href: '#', hidden: true }, 'Download CSV');
  const ensembleHint = h('div', { class: 'hint' });
  replaceChildren(root,
    h('div', { class: 'view-title' }, title, h('a', { href: '#/studies' }, 'All studies'),
      h('a', { href: `#/runs?study=${encodeURIComponent(name)}` }, 'Its runs in the runs list')),
    h('div', { class: 'panel' }, summary, message),
    h('div', { class: 'panel' },
      h('h3', {}, 'Ensemble'),
      h('div', { class: 'toolbar' },
        h('label', { for: 'study-quantity' }, 'Quantity '), quantitySelect,
        h('label', { for: 'study-group' }, 'One line per value of '), pathSelect, download),
      ensembleHint, chartBox,
      h('table', { class: 'runs study-bands' },
        h('thead', {}, h('tr', {}, ['Value', 'Runs', 'Axial strain (%)', 'Mean', '95 % band'].map((t) => h('th', {}, t)))),
        bandTable)),
    h('div', { class: 'panel' }, h('h3', {}, 'Runs'),
      h('table', { class: 'runs study-runs' }, h('thead', {}, h('tr', {}, ['#', 'Run', 'Values', 'Status'].map((t) => h('th', {}, t)))), runsBody)));
  quantitySelect.value = 'phi';

  let destroyed = false;
  let timer = null;
  let panel = null;
  let study = null;
  const loaded = new Map();  // id -> {id, parameters, table, scene}: completed runs, read once

  async function refresh() {
    clearTimeout(timer);
    try {
      study = await api.study(name);
      const page = await api.runsPage({ study: name, limit: 1000, order: 'asc' });
      if (destroyed) return;
      message.hidden = true;
      showSummary(page);
      const parameters = new Map((study.run_parameters ?? []).map((r) => [r.id, r.parameters]));
      const completed = page.runs.filter((run) => run.status === 'completed' && !loaded.has(run.id));
      const fresh = await Promise.all(completed.map(async (run) => {
        const [full, series] = await Promise.all([api.run(run.id), api.series(run.id)]);
        return { id: run.id, parameters: parameters.get(run.id) ?? {}, table: SeriesTable.fromRest(series), scene: full.scene };
      }));
      if (destroyed) return;
      for (const run of fresh) loaded.set(run.id, run);
      if (fresh.length || !panel) drawBands();
    } catch (error) {
      message.textContent = `The study cannot be loaded: ${error.message}`;
      message.hidden = false;
    }
    if (!destroyed && (!study || UNDER_WAY.has(study.status))) timer = setTimeout(refresh, POLL_MS);
  }

  function showSummary(page) {
    const by = study.by_status;
    const cancel = UNDER_WAY.has(study.status) ? h('button', { type: 'button', onclick: async () => {
      try {
        await api.cancelStudy(name);
        refresh();
      } catch (error) {
        message.textContent = `Cancelling failed: ${error.message}`;
        message.hidden = false;
      }
    } }, 'Cancel study') : null;
    const pct = `${Math.round(study.progress * 100)}%`;
    replaceChildren(summary,
      h('span', { class: `status ${study.status}` }, study.status), ' ',
      h('span', { class: 'progress' }, h('span', { class: 'bar' }, h('span', { style: { width: pct } })), h('span', { class: 'label' }, pct)), ' ',
      h('span', { class: 'study-counts' }, `${by.completed ?? 0} done · ${by.running ?? 0} running · ${(by.failed ?? 0) + (by.interrupted ?? 0)} failed · ${by.queued ?? 0} queued of ${study.runs}`),
      ' ', cancel,
      study.spec ? h('details', {}, h('summary', {}, 'Spec'), h('pre', {}, JSON.stringify(study.spec, null, 2))) : null);
    const parameters = new Map((study.run_parameters ?? []).map((r) => [r.id, r.parameters]));
    replaceChildren(runsBody, page.runs.map((run) => h('tr', { dataset: { runId: String(run.id) } },
      h('td', {}, String(run.id)),
      h('td', {}, h('a', { href: `#/run/${run.id}` }, run.name)),
      h('td', {}, Object.entries(parameters.get(run.id) ?? {}).map(([p, v]) => `${p} = ${JSON.stringify(v)}`).join(', ')),
      h('td', {}, h('span', { class: `status ${run.status}`, title: run.error ?? '' }, run.status)))));
    const paths = Object.keys(study.spec?.vary ?? {});
    if (pathSelect.options.length !== paths.length + 1) {
      replaceChildren(pathSelect, h('option', { value: '' }, '(all runs together)'), paths.map((p) => h('option', { value: p }, p)));
      // The first varied path that is not the seed: seeds are what an ensemble averages over.
      pathSelect.value = paths.find((p) => p !== 'seed') ?? '';
    }
  }

  function drawBands() {
    const spec = COMPARE_CHARTS.find((s) => s.key === quantitySelect.value);
    const runs = [...loaded.values()].sort((a, b) => a.id - b.id);
    panel?.destroy();
    panel = null;
    if (!runs.length) {
      ensembleHint.textContent = 'No run of this study has completed yet.';
      replaceChildren(bandTable);
      download.hidden = true;
      return;
    }
    const path = pathSelect.value;
    const groups = studyBands(runs, path, spec);
    ensembleHint.textContent = `${runs.length} completed run${runs.length === 1 ? '' : 's'}: the mean of each group and its 95 % t-interval at the first run's strains.`;
    const series = [];
    const bands = [];
    const tables = [];
    groups.forEach((g, k) => {
      const colour = BAND_COLOURS[k % BAND_COLOURS.length];
      const label = path ? `${path} = ${g.value}` : 'all runs';
      bands.push({ series: [series.length, series.length + 1], fill: `${colour}2e` });
      series.push({ label: `${label} 95 % high`, stroke: colour, width: 0.5 },
        { label: `${label} 95 % low`, stroke: colour, width: 0.5 },
        { label: `${label}: mean of ${g.ids.length}`, stroke: colour, width: 2 });
      tables.push([g.band.x, g.band.high], [g.band.x, g.band.low], [g.band.x, g.band.mean]);
    });
    panel = new ChartPanel(chartBox, {
      key: `study-${spec.key}`, title: spec.title, xLabel: X_AXES.strain.label, series, bands,
      axes: [{ label: spec.title }], spanGaps: false, emptyText: 'No completed run has reached its shearing stage.',
    });
    const joined = tables.some(([x]) => x.length) ? joinTables(tables) : [[], ...tables.map(() => [])];
    panel.setData(joined[0], joined.slice(1));
    replaceChildren(bandTable, groups.map((g) => {
      const end = commonEnd(g);
      return h('tr', { dataset: { value: g.value } },
        h('td', {}, path ? `${path} = ${g.value}` : 'all runs'),
        h('td', { class: 'band-runs' }, String(g.ids.length)),
        h('td', { class: 'band-strain', dataset: { strain: end ? String(end[0]) : '' } }, end ? sig(end[0], 4) : '–'),
        h('td', { class: 'band-mean', dataset: { mean: end ? String(end[1]) : '' } }, end ? sig(end[1], 5) : '–'),
        h('td', {}, end && end[2] !== null ? `${sig(end[2], 4)} … ${sig(end[3], 4)}` : '–'));
    }));
    URL.revokeObjectURL(download.href);
    download.href = URL.createObjectURL(new Blob([bandsCsv(groups, path, spec)], { type: 'text/csv' }));
    download.download = `${name}-${spec.key}.csv`;
    download.hidden = false;
  }

  refresh();
  return {
    destroy() {
      destroyed = true;
      clearTimeout(timer);
      panel?.destroy();
    },
  };
}
