// The runs list: one page of the runs (50), filtered by status, preset, study and name and
// sorted on the server (GET /api/runs?limit=&offset=&status=&preset=&study=&q=&sort=&order=),
// refreshed every two seconds; open, cancel, delete, and pick runs to compare. The page,
// filters and order live in the address (#/runs?study=s&page=2): a reload or a link keeps them.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { TERMINAL_STATUSES, duration, localTime, percent, sig } from '../format.js';

const REFRESH_MS = 2000;
const CONFIRM_MS = 4000;
const NAME_TYPING_MS = 250;  // the name filter asks the server once typing pauses
export const PAGE_SIZE = 50;
const STATUSES = ['queued', 'running', 'completed', 'failed', 'cancelled', 'interrupted'];
// The columns, and the server's sort key for those it can sort by.
const COLUMNS = [
  ['', null], ['#', 'created_at'], ['Name', 'name'], ['Preset', 'preset'], ['Status', 'status'],
  ['Progress', null], ['Particles', null], ['Created', 'created_at'], ['Time', 'wall_seconds'],
  ['Peak φ_mob', 'peak_phi_mob_deg'], ['', null],
];
// The server's own default order per key: newest first, the others upwards.
const defaultOrder = (sort) => (sort === 'created_at' ? 'desc' : 'asc');

export function runsView(root, params = new URLSearchParams()) {
  const selected = new Set();
  const rows = new Map();  // id → {element, update(run)}
  const state = {
    status: params.get('status') ?? '',
    preset: params.get('preset') ?? '',
    study: params.get('study') ?? '',
    q: params.get('q') ?? '',
    sort: params.get('sort') ?? 'created_at',
    order: params.get('order') ?? '',
    page: Math.max(1, Number.parseInt(params.get('page') ?? '1', 10) || 1),
  };
  if (!state.order) state.order = defaultOrder(state.sort);

  const tbody = h('tbody');
  const compareButton = h('a', { class: 'button', href: '#/compare' }, 'Compare selected');
  const message = h('div', { class: 'hint' });
  const emptyState = h('div', { class: 'empty-state', hidden: true });

  // ---- filters ----
  const statusFilter = h('select', { 'aria-label': 'status filter', class: 'filter-status',
    onchange: () => setFilter('status', statusFilter.value) },
  h('option', { value: '' }, 'any status'), STATUSES.map((s) => h('option', { value: s }, s)));
  statusFilter.value = state.status;
  const presetFilter = h('select', { 'aria-label': 'preset filter', class: 'filter-preset',
    onchange: () => setFilter('preset', presetFilter.value) },
  h('option', { value: '' }, 'any preset'));
  const addPreset = (name) => presetFilter.append(h('option', { value: name }, name));
  if (state.preset) addPreset(state.preset);
  presetFilter.value = state.preset;
  api.presets().then((names) => {
    for (const name of names) if (name !== state.preset) addPreset(name);
    presetFilter.value = state.preset;
  }).catch(() => {});  // the filter then offers what the address named
  let typingTimer = 0;
  const nameFilter = h('input', { type: 'search', placeholder: 'name contains…', 'aria-label': 'name filter',
    class: 'filter-name', value: state.q,
    oninput: () => {
      clearTimeout(typingTimer);
      typingTimer = setTimeout(() => setFilter('q', nameFilter.value.trim()), NAME_TYPING_MS);
    } });
  const studyFilter = h('select', { 'aria-label': 'study filter', class: 'filter-study',
    onchange: () => setFilter('study', studyFilter.value) },
  h('option', { value: '' }, 'any study'));
  if (state.study) studyFilter.append(h('option', { value: state.study }, state.study));
  studyFilter.value = state.study;
  api.studies().then((studies) => {
    for (const study of studies) {
      const label = `${study.name} (${study.runs} run${study.runs === 1 ? '' : 's'}, ${study.status})`;
      const existing = [...studyFilter.options].find((o) => o.value === study.name);
      if (existing) existing.textContent = label;
      else studyFilter.append(h('option', { value: study.name }, label));
    }
    studyFilter.value = state.study;
  }).catch(() => {});  // the filter then offers what the address named

  // ---- pager ----
  const prevButton = h('button', { type: 'button', class: 'pager-prev', onclick: () => goTo(state.page - 1) }, '‹ Previous');
  const nextButton = h('button', { type: 'button', class: 'pager-next', onclick: () => goTo(state.page + 1) }, 'Next ›');
  const pageLabel = h('span', { class: 'pager-label hint' });

  const headRow = h('tr', {});
  replaceChildren(root,
    h('div', { class: 'view-title' },
      h('h2', {}, 'Runs'),
      h('a', { class: 'button primary', href: '#/new' }, 'New run'),
      compareButton, message),
    h('div', { class: 'runs-filters' }, statusFilter, presetFilter, studyFilter, nameFilter),
    h('table', { class: 'runs' }, h('thead', {}, headRow), tbody),
    emptyState,
    h('div', { class: 'pager' }, prevButton, pageLabel, nextButton));

  function drawHeader() {
    replaceChildren(headRow, COLUMNS.map(([title, key]) => {
      if (!key) return h('th', {}, title);
      const active = state.sort === key;
      const arrow = active ? (state.order === 'desc' ? ' ↓' : ' ↑') : '';
      return h('th', { 'aria-sort': active ? (state.order === 'desc' ? 'descending' : 'ascending') : null },
        h('button', { type: 'button', class: 'sort', dataset: { sort: key },
          onclick: () => {
            if (state.sort === key) state.order = state.order === 'desc' ? 'asc' : 'desc';
            else Object.assign(state, { sort: key, order: defaultOrder(key) });
            state.page = 1;
            drawHeader();
            refresh();
          } }, title + arrow));
    }));
  }

  function setFilter(key, value) {
    if (state[key] === value) return;
    state[key] = value;
    state.page = 1;
    refresh();
  }

  function goTo(page) {
    state.page = Math.max(1, page);
    refresh();
  }

  // The address says what the page shows (without a history entry per keystroke).
  function remember() {
    const query = new URLSearchParams();
    for (const key of ['status', 'preset', 'study', 'q']) if (state[key]) query.set(key, state[key]);
    if (state.sort !== 'created_at') query.set('sort', state.sort);
    if (state.order !== defaultOrder(state.sort)) query.set('order', state.order);
    if (state.page > 1) query.set('page', String(state.page));
    const text = query.toString();
    const hash = `#/runs${text ? `?${text}` : ''}`;
    if (location.hash !== hash && (location.hash || hash !== '#/runs')) history.replaceState(null, '', hash);
  }

  let timer = 0;
  let generation = 0;  // a refresh started later supersedes one still waiting for the server
  let destroyed = false;

  function updateCompareLink() {
    const ids = [...selected];
    compareButton.href = ids.length ? `#/compare?ids=${ids.join(',')}` : '#/compare';
    compareButton.textContent = ids.length ? `Compare selected (${ids.length})` : 'Compare selected';
  }

  function makeRow(id) {
    const cells = {};
    for (const key of ['pick', 'id', 'name', 'preset', 'status', 'progress', 'particles', 'created', 'time', 'peak', 'actions']) {
      cells[key] = h('td', { class: key === 'actions' ? 'actions' : null });
    }
    const pick = h('input', {
      type: 'checkbox', 'aria-label': `select run ${id} for comparison`, checked: selected.has(id),
      onchange: () => {
        if (pick.checked) selected.add(id); else selected.delete(id);
        updateCompareLink();
      },
    });
    cells.pick.append(pick);
    const element = h('tr', { dataset: { runId: String(id) } }, Object.values(cells));
    let confirmTimer = 0;
    let lastStatus = null;

    const deleteButton = h('button', {
      type: 'button', class: 'danger',
      onclick: async () => {
        if (!deleteButton.classList.contains('confirming')) {
          deleteButton.classList.add('confirming');
          deleteButton.textContent = 'Confirm delete';
          confirmTimer = setTimeout(() => {
            deleteButton.classList.remove('confirming');
            deleteButton.textContent = 'Delete';
          }, CONFIRM_MS);
          return;
        }
        clearTimeout(confirmTimer);
        try {
          await api.remove(id);
          selected.delete(id);
          updateCompareLink();
          element.remove();
          rows.delete(id);
          refresh();
        } catch (error) {
          message.textContent = `Deleting run ${id} failed: ${error.message}`;
        }
      },
    }, 'Delete');
    const cancelButton = h('button', {
      type: 'button',
      onclick: async () => {
        try {
          await api.cancel(id);
          refresh();
        } catch (error) {
          message.textContent = `Cancelling run ${id} failed: ${error.message}`;
        }
      },
    }, 'Cancel');

    function update(run) {
      cells.id.textContent = String(run.id);
      replaceChildren(cells.name, h('a', { href: `#/run/${run.id}` }, run.name || '(unnamed)'),
        run.study ? h('a', { class: 'study-tag', href: `#/runs?study=${encodeURIComponent(run.study)}`,
          title: `the runs of study ${run.study}` }, run.study) : null,
        run.started_from ? h('span', { class: 'hint' }, ` on #${run.started_from.run_id}'s ${run.started_from.stage}`) : null);
      cells.preset.textContent = run.preset ?? 'custom';
      replaceChildren(cells.status, h('span', { class: `status ${run.status}`, title: run.error ?? '' }, run.status));
      replaceChildren(cells.progress, h('span', { class: 'progress' },
        h('span', { class: 'bar' }, h('span', { style: { width: percent(run.progress, 1) } })),
        h('span', { class: 'label' }, percent(run.progress))));
      cells.particles.textContent = String(run.particles);
      cells.created.textContent = localTime(run.created_at);
      const started = run.started_at ? Date.parse(run.started_at) : null;
      cells.time.textContent = run.wall_seconds !== null ? duration(run.wall_seconds)
        : started ? `${duration((Date.now() - started) / 1000)}…` : '–';
      cells.peak.textContent = run.peak_phi_mob_deg !== null ? `${sig(run.peak_phi_mob_deg, 3)}°` : '–';
      if (run.status !== lastStatus) {
        lastStatus = run.status;
        replaceChildren(cells.actions,
          h('a', { class: 'button', href: `#/run/${run.id}` }, 'Open'),
          TERMINAL_STATUSES.has(run.status) ? null : cancelButton,
          deleteButton);
      }
    }
    return { element, update };
  }

  async function refresh() {
    clearTimeout(timer);
    const mine = ++generation;
    remember();
    let answer;
    try {
      answer = await api.runsPage({
        limit: PAGE_SIZE, offset: (state.page - 1) * PAGE_SIZE, status: state.status, preset: state.preset,
        study: state.study, q: state.q,
        sort: state.sort === 'created_at' ? '' : state.sort,
        order: state.order === defaultOrder(state.sort) ? '' : state.order,
      });
      message.textContent = '';
    } catch (error) {
      message.textContent = `Cannot list the runs: ${error.message}`;
    }
    if (destroyed || mine !== generation) return;
    if (answer) {
      const pages = Math.max(1, Math.ceil(answer.total / PAGE_SIZE));
      if (state.page > pages) {  // runs deleted under the page: show the last one there is
        state.page = pages;
        refresh();
        return;
      }
      const runs = answer.runs;
      const seen = new Set();
      runs.forEach((run, position) => {
        seen.add(run.id);
        let row = rows.get(run.id);
        if (!row) {
          row = makeRow(run.id);
          rows.set(run.id, row);
        }
        row.update(run);
        if (tbody.children[position] !== row.element) tbody.insertBefore(row.element, tbody.children[position] ?? null);
      });
      for (const [id, row] of rows) {
        if (!seen.has(id)) {
          row.element.remove();
          rows.delete(id);
        }
      }
      const filtered = Boolean(state.status || state.preset || state.study || state.q);
      emptyState.hidden = runs.length > 0;
      replaceChildren(emptyState, filtered ? 'No runs match these filters.'
        : ['No runs yet. ', h('a', { href: '#/new' }, 'Start one'), '.']);
      pageLabel.textContent = `Page ${state.page} of ${pages} · ${answer.total} run${answer.total === 1 ? '' : 's'}`;
      prevButton.disabled = state.page <= 1;
      nextButton.disabled = !answer.next;
      updateCompareLink();
    }
    timer = setTimeout(refresh, REFRESH_MS);
  }

  drawHeader();
  refresh();
  return {
    destroy() {
      destroyed = true;
      clearTimeout(timer);
      clearTimeout(typingTimer);
    },
  };
}
