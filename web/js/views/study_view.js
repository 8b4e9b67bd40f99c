// One study (#/studies/NAME): its progress and runs with the values each was given, and, once
// runs have finished, one quantity's ensemble mean with its 95 % band against axial strain
// (shearing stage), one line per value of the varied path chosen, with the table behind it
// as CSV. The bands are the server's (GET /api/studies/NAME/bands, computed from the stored
// series): the page never loads a run's series, whatever the study's size. The charts are the
// Compare view's.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { ChartPanel, joinTables } from '../chart_panel.js';
import { COMPARE_CHARTS, X_AXES } from '../chart_specs.js';
import { sig, timeLeft } from '../format.js';
import { paretoPanelSvg } from '../pareto_plot.js';

const POLL_MS = 2000;
const UNDER_WAY = new Set(['running', 'queued']);
// A study with a run cancelled or interrupted (and none under way) can be resumed.
const RESUMABLE = new Set(['cancelled', 'interrupted']);
const BAND_COLOURS = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#000000'];
// The runs table shows this many; the runs list (filtered by study) pages through the rest.
const RUNS_SHOWN = 200;

/** The server's bands as groups {value, ids, band: {x, mean, low, high, n}} (null for a strain not reached). */
export function bandGroups(bands) {
  return bands.groups.map((g) => ({ value: g.value, ids: g.ids, band: { x: bands.grid, mean: g.mean, low: g.low, high: g.high, n: g.n } }));
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
  const pathSelect = h('select', { id: 'study-group', 'aria-label': 'Group by', onchange: () => choose() });
  const quantitySelect = h('select', { id: 'study-quantity', 'aria-label': 'Quantity', onchange: () => choose() },
    COMPARE_CHARTS.map((spec) => h('option', { value: spec.key }, spec.title)));
  const chartBox = h('div', { class: 'study-chart' });
  const bandTable = h('tbody');
  const download = h('a', { class: 'button', download: `${name}.csv`, href: '#', hidden: true }, 'Download CSV');
  const ensembleHint = h('div', { class: 'hint' });
  // A paper study's findings, once its runs have ended (GET /api/studies/NAME/findings).
  const findingsBody = h('tbody');
  const findingsHint = h('div', { class: 'hint' });
  const findingsDownload = h('a', { class: 'button', download: `${name}-findings.csv`, href: '#', hidden: true }, 'Download findings.csv');
  const findingsPanel = h('div', { class: 'panel study-findings', hidden: true },
    h('h3', {}, 'Findings'), findingsHint, findingsDownload,
    h('table', { class: 'runs findings' },
      h('thead', {}, h('tr', {}, ['#', 'Claim', 'Verdict', 'Subject', 'Estimate', '95 % interval', 'Check'].map((t) => h('th', {}, t)))),
      findingsBody));
  // A trade-off study's Pareto plot and tradeoff.csv, once its runs have ended
  // (GET /api/studies/NAME/tradeoff).
  const tradeoffHint = h('div', { class: 'hint' });
  const tradeoffPlots = h('div', { class: 'pareto-plots' });
  const tradeoffDownload = h('a', { class: 'button', download: `${name}-tradeoff.csv`, href: '#', hidden: true }, 'Download tradeoff.csv');
  const tradeoffPanel = h('div', { class: 'panel study-tradeoff', hidden: true },
    h('h3', {}, 'Speed against accuracy'), tradeoffHint, tradeoffDownload, tradeoffPlots);
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
    findingsPanel, tradeoffPanel,
    h('div', { class: 'panel' }, h('h3', {}, 'Runs'),
      h('table', { class: 'runs study-runs' }, h('thead', {}, h('tr', {}, ['#', 'Run', 'Values', 'Status'].map((t) => h('th', {}, t)))), runsBody)));
  quantitySelect.value = 'phi';

  let destroyed = false;
  let timer = null;
  let panel = null;
  let study = null;
  let bands = null;       // the server's answer for the quantity and grouping shown
  let bandsKey = null;    // what it was asked for: quantity, group and the completed runs then
  let asked = 0;          // the latest request's number: an older answer arriving late is dropped

  async function refresh() {
    clearTimeout(timer);
    try {
      study = await api.study(name);
      const page = await api.runsPage({ study: name, limit: RUNS_SHOWN, order: 'asc' });
      if (destroyed) return;
      message.hidden = true;
      showSummary(page);
      await loadBands();
      if (study.spec?.paper && !findings && !UNDER_WAY.has(study.status)) await loadFindings();
      if (study.spec?.tradeoff) await loadTradeoff();
    } catch (error) {
      message.textContent = `The study cannot be loaded: ${error.message}`;
      message.hidden = false;
    }
    // A trade-off study whose references have all completed is done for a moment, until the
    // server has queued its other settings: it is polled until its table is there.
    const between = study?.spec?.tradeoff && !tradeoff && study.status === 'completed';
    if (!destroyed && (!study || UNDER_WAY.has(study.status) || between)) timer = setTimeout(refresh, POLL_MS);
  }

  let findings = null;
  async function loadFindings() {
    findingsPanel.hidden = false;
    try {
      findings = await api.studyFindings(name);
    } catch (error) {
      findingsHint.textContent = `No findings: ${error.message}`;
      return;
    }
    if (destroyed) return;
    const estimate = (v) => (v === null ? '–' : sig(v, 4));
    findingsHint.textContent = `The paper's claims judged on ${findings.runs} runs (${findings.seeds} seed${findings.seeds === 1 ? '' : 's'} of each assembly${findings.quick ? ', quick presets' : ''}) by grainlab paper's code.`;
    replaceChildren(findingsBody, findings.findings.flatMap((f) => f.checks.map((c, k) => h('tr', { dataset: { finding: String(f.number) } },
      h('td', {}, k === 0 ? String(f.number) : ''),
      h('td', { title: f.criterion }, k === 0 ? f.claim : ''),
      h('td', { class: 'finding-verdict' }, k === 0 ? f.verdict : ''),
      h('td', {}, c.subject),
      h('td', { class: 'finding-value', title: c.quantity, dataset: { value: String(c.value) } }, estimate(c.value)),
      h('td', {}, c.ci_low === null ? '–' : `${estimate(c.ci_low)} … ${estimate(c.ci_high)}`),
      h('td', { title: c.measured }, c.verdict)))));
    URL.revokeObjectURL(findingsDownload.href);
    findingsDownload.href = URL.createObjectURL(new Blob([findings.csv], { type: 'text/csv' }));
    findingsDownload.hidden = false;
  }

  let tradeoff = null;
  async function loadTradeoff() {
    tradeoffPanel.hidden = false;
    if (tradeoff) return;
    if (UNDER_WAY.has(study.status)) {
      tradeoffHint.textContent = 'The plot is drawn once every run has ended: the references run first, then the settings that shear their specimens.';
      return;
    }
    try {
      tradeoff = await api.studyTradeoff(name);
    } catch (error) {
      tradeoffHint.textContent = `No trade-off table: ${error.message}`;
      return;
    }
    if (destroyed) return;
    tradeoffHint.textContent = `Each setting's shearing CPU time per run against its mean |angle difference| from the same seed's reference, the mean over ${tradeoff.seeds} seeds with its 95 % interval (${tradeoff.runs} runs, ${tradeoff.failed_runs} failed), as grainlab tradeoff --seeds ${tradeoff.seeds} judges them. Filled: on the Pareto front; dashed: the noise probe.`;
    replaceChildren(tradeoffPlots, tradeoff.panels.map((p) => paretoPanelSvg(p)));
    URL.revokeObjectURL(tradeoffDownload.href);
    tradeoffDownload.href = URL.createObjectURL(new Blob([tradeoff.csv], { type: 'text/csv' }));
    tradeoffDownload.hidden = false;
  }

  // Asks again only when the choice or the number of completed runs changed.
  async function loadBands() {
    if (!study) return;
    const key = JSON.stringify([quantitySelect.value, pathSelect.value, study.by_status.completed ?? 0]);
    if (key === bandsKey) return;
    const number = ++asked;
    const answer = await api.studyBands(name, quantitySelect.value, pathSelect.value);
    if (destroyed || number !== asked) return;
    bands = answer;
    bandsKey = key;
    drawBands();
  }

  async function choose() {
    try {
      await loadBands();
    } catch (error) {
      message.textContent = `The bands cannot be loaded: ${error.message}`;
      message.hidden = false;
    }
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
    } }, 'Cancel study') : RESUMABLE.has(study.status) ? h('button', { type: 'button', onclick: async () => {
      try {
        await api.resumeStudy(name);
        refresh();
      } catch (error) {
        message.textContent = `Resuming failed: ${error.message}`;
        message.hidden = false;
      }
    } }, 'Resume study') : null;
    const pct = `${Math.round(study.progress * 100)}%`;
    const left = UNDER_WAY.has(study.status) ? timeLeft(study) : null;
    replaceChildren(summary,
      h('span', { class: `status ${study.status}` }, study.status), ' ',
      h('span', { class: 'progress' }, h('span', { class: 'bar' }, h('span', { style: { width: pct } })), h('span', { class: 'label' }, pct)), ' ',
      h('span', { class: 'study-counts' }, `${by.completed ?? 0} done · ${by.running ?? 0} running · ${(by.failed ?? 0) + (by.interrupted ?? 0)} failed · ${by.queued ?? 0} queued of ${study.runs}`),
      ' ', left ? h('span', { class: 'time-left', title: left.title, dataset: { seconds: String(study.seconds_left) } }, left.text) : null,
      ' ', cancel, ' ', h('button', { type: 'button', class: 'danger', onclick: async () => {
        if (!window.confirm(`Delete the study ${name} with its ${study.runs} runs and everything they stored?`)) return;
        try {
          await api.deleteStudy(name);
          window.location.hash = '#/studies';
        } catch (error) {
          message.textContent = `Deleting failed: ${error.message}`;
          message.hidden = false;
        }
      } }, 'Delete study'),
      study.spec ? h('details', {}, h('summary', {}, 'Spec'), h('pre', {}, JSON.stringify(study.spec, null, 2))) : null);
    const parameters = new Map((study.run_parameters ?? []).map((r) => [r.id, r.parameters]));
    replaceChildren(runsBody, page.runs.map((run) => h('tr', { dataset: { runId: String(run.id) } },
      h('td', {}, String(run.id)),
      h('td', {}, h('a', { href: `#/run/${run.id}` }, run.name)),
      h('td', {}, Object.entries(parameters.get(run.id) ?? {}).map(([p, v]) => `${p} = ${JSON.stringify(v)}`).join(', ')),
      h('td', {}, h('span', { class: `status ${run.status}`, title: run.error ?? '' }, run.status)))),
    page.total > page.runs.length ? h('tr', { class: 'more' }, h('td', { colspan: 4 },
      `The first ${page.runs.length} of ${page.total}: `, h('a', { href: `#/runs?study=${encodeURIComponent(name)}` }, 'all of them in the runs list'))) : null);
    const paths = study.spec?.paper ? ['preset', 'seed'] : study.spec?.tradeoff ? ['setting', 'preset', 'seed'] : Object.keys(study.spec?.vary ?? {});
    if (pathSelect.options.length !== paths.length + 1) {
      replaceChildren(pathSelect, h('option', { value: '' }, '(all runs together)'), paths.map((p) => h('option', { value: p }, p)));
      // The first varied path that is not the seed: seeds are what an ensemble averages over.
      pathSelect.value = paths.find((p) => p !== 'seed') ?? '';
    }
  }

  function drawBands() {
    const spec = COMPARE_CHARTS.find((s) => s.key === bands.quantity) ?? { key: bands.quantity, title: bands.title };
    panel?.destroy();
    panel = null;
    if (!bands.runs) {
      ensembleHint.textContent = 'No run of this study has completed yet.';
      replaceChildren(bandTable);
      download.hidden = true;
      return;
    }
    const path = bands.group_by;
    const groups = bandGroups(bands);
    ensembleHint.textContent = `${bands.runs} completed run${bands.runs === 1 ? '' : 's'}: the mean of each group and its 95 % ${bands.interval === 't' ? 'Student-t' : 'circular'} interval, on ${bands.grid.length} strains from the first reached to the last.`;
    const series = [];
    const fills = [];
    const tables = [];
    groups.forEach((g, k) => {
      const colour = BAND_COLOURS[k % BAND_COLOURS.length];
      const label = path ? `${path} = ${g.value}` : 'all runs';
      fills.push({ series: [series.length, series.length + 1], fill: `${colour}2e` });
      series.push({ label: `${label} 95 % high`, stroke: colour, width: 0.5 },
        { label: `${label} 95 % low`, stroke: colour, width: 0.5 },
        { label: `${label}: mean of ${g.ids.length}`, stroke: colour, width: 2 });
      tables.push([g.band.x, g.band.high], [g.band.x, g.band.low], [g.band.x, g.band.mean]);
    });
    panel = new ChartPanel(chartBox, {
      key: `study-${spec.key}`, title: spec.title, xLabel: X_AXES.strain.label, series, bands: fills,
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
