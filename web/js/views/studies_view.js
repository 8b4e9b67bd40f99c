// Studies: the sweeps launched here or imported, with their progress (done, running, failed,
// queued), polled every 2 s while any is under way; a form that launches a sweep (a preset,
// `path = values` rows, seeds: POST /api/studies) showing its run count first and the
// server's refusal beside the row it names; cancel. A study's name opens its page
// (#/studies/NAME, study_view.js) and its run count the runs list filtered by it.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { parseValues, runCount, sweepSpec } from '../study_spec.js';

const POLL_MS = 2000;
const DEFAULT_PRESET = 'circular-quick';
const UNDER_WAY = new Set(['running', 'queued']);

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
    function update(s) {
      replaceChildren(cells.name, h('a', { href: `#/studies/${encodeURIComponent(s.name)}` }, s.name));
      cells.source.textContent = s.source ?? 'imported';
      replaceChildren(cells.status, h('span', { class: `status ${s.status}` }, s.status));
      const pct = `${Math.round(s.progress * 100)}%`;
      replaceChildren(cells.progress, h('span', { class: 'progress' },
        h('span', { class: 'bar' }, h('span', { style: { width: pct } })), h('span', { class: 'label' }, pct)));
      const by = s.by_status;
      replaceChildren(cells.counts,
        h('a', { href: `#/runs?study=${encodeURIComponent(s.name)}`, title: 'its runs' },
          `${by.completed ?? 0} done · ${by.running ?? 0} running · ${(by.failed ?? 0) + (by.interrupted ?? 0)} failed · ${by.queued ?? 0} queued`,
          by.cancelled ? ` · ${by.cancelled} cancelled` : '', ` of ${s.runs}`));
      replaceChildren(cells.actions, UNDER_WAY.has(s.status) ? cancelButton : null);
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
    form);

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
