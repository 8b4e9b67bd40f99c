// Studies: the sweeps launched here or imported, with their progress (done, running, failed,
// queued), polled every 2 s while any is under way; a form that launches a sweep (a preset,
// `path = values` rows, seeds: POST /api/studies) showing its run count first and the
// server's refusal beside the row it names; the paper and the speed-accuracy trade-off
// (`grainlab tradeoff --seeds N`) launched by their own small forms; cancel. A study's name opens its page
// (#/studies/NAME, study_view.js) and its run count the runs list filtered by it.
import { api } from '../api.js';
import { timeLeft } from '../format.js';
import { h, replaceChildren } from '../dom.js';
import { parseValues, runCount, sweepSpec } from '../study_spec.js';

const POLL_MS = 2000;
const DEFAULT_PRESET = 'circular-quick';
const UNDER_WAY = new Set(['running', 'queued']);
// A study with a run cancelled or interrupted (and none under way) can be resumed.
const RESUMABLE = new Set(['cancelled', 'interrupted']);

export function studiesView(root) {
  const tableBody = h('tbody');
  const empty = h('div', { class: 'empty-state', hidden: true }, 'No studies yet: launch one below, or import a sweep.');
  const listError = h('div', { class: 'form-error', hidden: true });
  let timer = null;
  let destroyed = false;

  // ---- the launch form ----
  const nameInput = h('input', { id: 'study-name', type: 'text', autocomplete: 'off', placeholder: 'e.g. friction-series', oninput: () => showCount() });
  const nameError = h('div', { class: 'field-error', dataset: { errorFor: 'name' } });
  const presetSelect = h('select', { id: 'study-preset', 'aria-label': 'Preset', onchange: () => showCount() });
  const presetError = h('div', { class: 'field-error', dataset: { errorFor: 'base' } });
  const modeSelect = h('select', { id: 'study-mode', 'aria-label': 'Mode', onchange: () => showCount() },
    h('option', { value: 'grid' }, 'grid: every combination'),
    h('option', { value: 'zip' }, 'zip: the lists in lockstep'));
  const seedsInput = h('input', { id: 'study-seeds', type: 'text', autocomplete: 'off', placeholder: 'e.g. 1, 2, 3 (empty: the preset\'s)', oninput: () => showCount() });
  const seedsError = h('div', { class: 'field-error', dataset: { errorFor: 'vary.seed' } });
  const rowsBox = h('div', { class: 'study-rows' });
  const varyError = h('div', { class: 'field-error', dataset: { errorFor: 'vary' } });
  const count = h('span', { class: 'study-count', 'aria-live': 'polite' });
  const launchButton = h('button', { type: 'submit', class: 'primary' }, 'Launch study');
  const formError = h('div', { class: 'form-error', hidden: true });
  const rows = [];

  function addRow(path = '', values = '') {
    const pathInput = h('input', { type: 'text', class: 'study-path', autocomplete: 'off', placeholder: 'material.friction', value: path, oninput: () => showCount(), 'aria-label': 'Scene path' });
    const valuesInput = h('input', { type: 'text', class: 'study-values', autocomplete: 'off', placeholder: '0.3, 0.5, 0.7', value: values, oninput: () => showCount(), 'aria-label': 'Values' });
    const error = h('div', { class: 'field-error' });
    const row = { pathInput, valuesInput, error };
    const remove = h('button', { type: 'button', class: 'study-remove', title: 'Remove this row', onclick: () => {
      rows.splice(rows.indexOf(row), 1);
      row.element.remove();
      showCount();
    } }, '×');
    row.element = h('div', { class: 'study-row' }, pathInput, h('span', {}, '='), valuesInput, remove, error);
    rows.push(row);
    rowsBox.append(row.element);
    showCount();
  }

  /** The form as a sweep spec, or throws {field, message} for what cannot be read. */
  function spec() {
    return sweepSpec({
      name: nameInput.value.trim(),
      preset: presetSelect.value,
      mode: modeSelect.value,
      seeds: seedsInput.value,
      rows: rows.map((r) => ({ path: r.pathInput.value.trim(), values: r.valuesInput.value })),
    });
  }

  function showCount() {
    try {
      const n = runCount(spec());
      count.textContent = `${n} run${n === 1 ? '' : 's'}`;
      count.classList.remove('invalid');
    } catch (error) {
      count.textContent = error.message;
      count.classList.add('invalid');
    }
  }

  function clearErrors() {
    formError.hidden = true;
    for (const node of [nameError, presetError, seedsError, varyError, ...rows.map((r) => r.error)]) node.textContent = '';
  }

  /** The server's (or the form's) refusal beside the field it names. */
  function showError(field, message) {
    const row = field?.startsWith('vary.') && rows.find((r) => `vary.${r.pathInput.value.trim()}` === field);
    const target = field === 'name' ? nameError
      : field === 'base' || field?.startsWith('base.') ? presetError
        : field === 'vary.seed' && parseValues(seedsInput.value).length ? seedsError
          : row ? row.error
            : field === 'vary' || field?.startsWith('vary.') ? varyError : null;
    if (target) {
      target.textContent = message;
    } else {
      formError.textContent = field ? `${field}: ${message}` : message;
      formError.hidden = false;
    }
  }

  async function launch() {
    clearErrors();
    let body;
    try {
      body = spec();
    } catch (error) {
      showError(error.field, error.message);
      return;
    }
    launchButton.disabled = true;
    try {
      const study = await api.launchStudy(body);
      nameInput.value = '';
      count.textContent = `launched ${study.name}: ${study.runs} runs`;
      await refresh();
    } catch (error) {
      showError(error.field, error.message);
    } finally {
      launchButton.disabled = false;
    }
  }

  const form = h('form', { class: 'panel study-form', novalidate: true, onsubmit: (event) => { event.preventDefault(); launch(); } },
    h('h3', {}, 'Launch a study'),
    h('div', { class: 'form-grid' },
      h('label', { for: 'study-name' }, 'Name'), h('div', { class: 'field-input' }, nameInput, nameError),
      h('label', { for: 'study-preset' }, 'Preset'), h('div', { class: 'field-input' }, presetSelect, presetError),
      h('label', {}, 'Vary'), h('div', { class: 'field-input' }, rowsBox,
        h('div', {}, h('button', { type: 'button', onclick: () => addRow() }, 'Add a path')),
        h('div', { class: 'hint' }, 'a scene path (stages.2.strain_rate, material.friction, assembly.bedding_angle_deg) = its values, separated by commas'),
        varyError),
      h('label', { for: 'study-seeds' }, 'Seeds'), h('div', { class: 'field-input' }, seedsInput, seedsError),
      h('label', { for: 'study-mode' }, 'Mode'), h('div', { class: 'field-input' }, modeSelect)),
    h('div', { class: 'form-actions' }, launchButton, count),
    formError);

  // ---- the paper: its six assemblies x N seeds, as `grainlab paper` runs them ----
  const paperName = h('input', { id: 'paper-name', type: 'text', autocomplete: 'off', placeholder: 'e.g. paper-8 (empty: paper-N-seeds)' });
  const paperSeeds = h('input', { id: 'paper-seeds', type: 'number', min: '1', step: '1', value: '1' });
  const paperQuick = h('input', { id: 'paper-quick', type: 'checkbox', checked: true });
  const paperError = h('div', { class: 'form-error', hidden: true });
  const paperButton = h('button', { type: 'submit', class: 'primary' }, 'Launch the paper');
  async function launchPaper() {
    paperError.hidden = true;
    const seeds = Number(paperSeeds.value);
    const body = { paper: { seeds: Number.isInteger(seeds) ? seeds : paperSeeds.value, quick: paperQuick.checked } };
    if (paperName.value.trim()) body.name = paperName.value.trim();
    paperButton.disabled = true;
    try {
      const study = await api.launchStudy(body);
      paperName.value = '';
      await refresh();
      paperError.textContent = '';
      count.textContent = `launched ${study.name}: ${study.runs} runs`;
    } catch (error) {
      paperError.textContent = error.field ? `${error.field}: ${error.message}` : error.message;
      paperError.hidden = false;
    } finally {
      paperButton.disabled = false;
    }
  }
  const paperForm = h('form', { class: 'panel paper-form', novalidate: true, onsubmit: (event) => { event.preventDefault(); launchPaper(); } },
    h('h3', {}, 'Launch the paper'),
    h('div', { class: 'hint' }, 'The paper\'s six biaxial tests (circular, random, bedded at 0, 30, 60, 90°), each with seeds 1 to N, as grainlab paper runs them; once they have run, the study\'s page shows the findings.'),
    h('div', { class: 'form-grid' },
      h('label', { for: 'paper-name' }, 'Name'), h('div', { class: 'field-input' }, paperName),
      h('label', { for: 'paper-seeds' }, 'Seeds'), h('div', { class: 'field-input' }, paperSeeds),
      h('label', { for: 'paper-quick' }, 'Quick presets'), h('div', { class: 'field-input' }, paperQuick)),
    h('div', { class: 'form-actions' }, paperButton),
    paperError);

  // ---- the trade-off: `grainlab tradeoff --seeds N`, speed against accuracy ----
  const tradeoffName = h('input', { id: 'tradeoff-name', type: 'text', autocomplete: 'off', placeholder: 'e.g. timestep-4 (empty: tradeoff-N-seeds)' });
  const tradeoffSeeds = h('input', { id: 'tradeoff-seeds', type: 'number', min: '2', step: '1', value: '2' });
  const tradeoffQuick = h('input', { id: 'tradeoff-quick', type: 'checkbox', checked: true });
  const tradeoffPresets = h('input', { id: 'tradeoff-presets', type: 'text', autocomplete: 'off', placeholder: 'e.g. circular-quick (empty: the plan\'s)' });
  const tradeoffAxes = h('input', { id: 'tradeoff-axes', type: 'text', autocomplete: 'off', placeholder: 'e.g. timestep_safety, inertial_number (empty: all)' });
  const tradeoffError = h('div', { class: 'form-error', hidden: true });
  const tradeoffButton = h('button', { type: 'submit', class: 'primary' }, 'Launch the trade-off');
  const names = (text) => text.split(',').map((s) => s.trim()).filter(Boolean);
  async function launchTradeoff() {
    tradeoffError.hidden = true;
    const seeds = Number(tradeoffSeeds.value);
    const body = { tradeoff: { seeds: Number.isInteger(seeds) ? seeds : tradeoffSeeds.value, quick: tradeoffQuick.checked } };
    if (names(tradeoffPresets.value).length) body.tradeoff.presets = names(tradeoffPresets.value);
    if (names(tradeoffAxes.value).length) body.tradeoff.axes = names(tradeoffAxes.value);
    if (tradeoffName.value.trim()) body.name = tradeoffName.value.trim();
    tradeoffButton.disabled = true;
    try {
      const study = await api.launchStudy(body);
      tradeoffName.value = '';
      await refresh();
      count.textContent = `launched ${study.name}: ${study.runs} reference runs first`;
    } catch (error) {
      tradeoffError.textContent = error.field ? `${error.field}: ${error.message}` : error.message;
      tradeoffError.hidden = false;
    } finally {
      tradeoffButton.disabled = false;
    }
  }
  const tradeoffForm = h('form', { class: 'panel tradeoff-form', novalidate: true, onsubmit: (event) => { event.preventDefault(); launchTradeoff(); } },
    h('h3', {}, 'Launch a speed-accuracy trade-off'),
    h('div', { class: 'hint' }, 'Each fidelity setting (timestep, shearing rate, vertices, sampling, engine) on N seeds against the most accurate setting, as grainlab tradeoff --seeds N runs it: the references first, then the settings that shear their specimens; once they have run, the study\'s page shows the Pareto plot and tradeoff.csv.'),
    h('div', { class: 'form-grid' },
      h('label', { for: 'tradeoff-name' }, 'Name'), h('div', { class: 'field-input' }, tradeoffName),
      h('label', { for: 'tradeoff-seeds' }, 'Seeds'), h('div', { class: 'field-input' }, tradeoffSeeds),
      h('label', { for: 'tradeoff-quick' }, 'Quick plan'), h('div', { class: 'field-input' }, tradeoffQuick),
      h('label', { for: 'tradeoff-presets' }, 'Presets'), h('div', { class: 'field-input' }, tradeoffPresets),
      h('label', { for: 'tradeoff-axes' }, 'Axes'), h('div', { class: 'field-input' }, tradeoffAxes,
        h('div', { class: 'hint' }, 'timestep_safety, inertial_number, vertices, sample_strain, engine, noise; the reference always runs'))),
    h('div', { class: 'form-actions' }, tradeoffButton),
    tradeoffError);

  // ---- the list ----
  const rowsByName = new Map();
  function studyRow(study) {
    const cells = {
      name: h('td'), source: h('td'), status: h('td'), progress: h('td'), counts: h('td'), actions: h('td', { class: 'actions' }),
    };
    const element = h('tr', { dataset: { study: study.name } }, Object.values(cells));
    const cancelButton = h('button', { type: 'button', onclick: async () => {
      try {
        await api.cancelStudy(study.name);
        refresh();
      } catch (error) {
        listError.textContent = `Cancelling ${study.name} failed: ${error.message}`;
        listError.hidden = false;
      }
    } }, 'Cancel');
    const resumeButton = h('button', { type: 'button', onclick: async () => {
      try {
        await api.resumeStudy(study.name);
        refresh();
      } catch (error) {
        listError.textContent = `Resuming ${study.name} failed: ${error.message}`;
        listError.hidden = false;
      }
    } }, 'Resume');
    function update(s) {
      replaceChildren(cells.name, h('a', { href: `#/studies/${encodeURIComponent(s.name)}` }, s.name));
      cells.source.textContent = s.source ?? 'imported';
      replaceChildren(cells.status, h('span', { class: `status ${s.status}` }, s.status));
      const pct = `${Math.round(s.progress * 100)}%`;
      replaceChildren(cells.progress, h('span', { class: 'progress' },
        h('span', { class: 'bar' }, h('span', { style: { width: pct } })), h('span', { class: 'label' }, pct)));
      const left = UNDER_WAY.has(s.status) ? timeLeft(s) : null;
      if (left) cells.progress.append(' ', h('span', { class: 'time-left', title: left.title, dataset: { seconds: String(s.seconds_left) } }, left.text));
      const by = s.by_status;
      replaceChildren(cells.counts,
        h('a', { href: `#/runs?study=${encodeURIComponent(s.name)}`, title: 'its runs' },
          `${by.completed ?? 0} done · ${by.running ?? 0} running · ${(by.failed ?? 0) + (by.interrupted ?? 0)} failed · ${by.queued ?? 0} queued`,
          by.cancelled ? ` · ${by.cancelled} cancelled` : '', ` of ${s.runs}`));
      replaceChildren(cells.actions, UNDER_WAY.has(s.status) ? cancelButton : RESUMABLE.has(s.status) ? resumeButton : null);
    }
    return { element, update };
  }

  async function refresh() {
    clearTimeout(timer);
    let studies;
    try {
      studies = await api.studies();
      listError.hidden = true;
    } catch (error) {
      listError.textContent = `The studies cannot be loaded: ${error.message}`;
      listError.hidden = false;
      studies = null;
    }
    if (destroyed) return;
    if (studies) {
      const seen = new Set();
      for (const study of studies) {
        seen.add(study.name);
        let row = rowsByName.get(study.name);
        if (!row) {
          row = studyRow(study);
          rowsByName.set(study.name, row);
        }
        row.update(study);
        tableBody.append(row.element);  // (appending keeps the server's order: by name)
      }
      for (const [name, row] of rowsByName) {
        if (!seen.has(name)) {
          row.element.remove();
          rowsByName.delete(name);
        }
      }
      empty.hidden = studies.length > 0;
    }
    // Poll while anything is under way (or the list could not be read).
    if (!studies || studies.some((s) => UNDER_WAY.has(s.status))) timer = setTimeout(refresh, POLL_MS);
  }

  replaceChildren(root,
    h('div', { class: 'view-title' }, h('h2', {}, 'Studies')),
    h('div', { class: 'panel' },
      h('table', { class: 'runs studies' },
        h('thead', {}, h('tr', {}, ['Study', 'Source', 'Status', 'Progress', 'Runs', ''].map((t) => h('th', {}, t)))),
        tableBody),
      empty, listError),
    form, paperForm, tradeoffForm);

  (async () => {
    try {
      const presets = await api.presets();
      if (destroyed) return;
      replaceChildren(presetSelect, presets.map((name) => h('option', { value: name }, name)));
      presetSelect.value = presets.includes(DEFAULT_PRESET) ? DEFAULT_PRESET : presets[0];
    } catch (error) {
      presetError.textContent = `The presets cannot be loaded: ${error.message}`;
    }
    showCount();
  })();
  addRow('material.friction', '0.3, 0.5');
  refresh();

  return {
    destroy() {
      destroyed = true;
      clearTimeout(timer);
    },
  };
}
