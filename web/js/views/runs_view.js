// The runs list: status, progress, preset and creation time of every run, newest first,
// refreshed every two seconds; open, cancel, delete, and pick runs to compare.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { TERMINAL_STATUSES, duration, localTime, percent, sig } from '../format.js';

const REFRESH_MS = 2000;
const CONFIRM_MS = 4000;

export function runsView(root) {
  const selected = new Set();
  const rows = new Map();  // id → {element, update(run)}
  const tbody = h('tbody');
  const compareButton = h('a', { class: 'button', href: '#/compare' }, 'Compare selected');
  const message = h('div', { class: 'hint' });
  const emptyState = h('div', { class: 'empty-state', hidden: true },
    'No runs yet. ', h('a', { href: '#/new' }, 'Start one'), '.');
  replaceChildren(root,
    h('div', { class: 'view-title' },
      h('h2', {}, 'Runs'),
      h('a', { class: 'button primary', href: '#/new' }, 'New run'),
      compareButton, message),
    h('table', { class: 'runs' },
      h('thead', {}, h('tr', {},
        ['', '#', 'Name', 'Preset', 'Status', 'Progress', 'Particles', 'Created', 'Time', 'Peak φ_mob', '']
          .map((t) => h('th', {}, t)))),
      tbody),
    emptyState);

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
      type: 'checkbox', 'aria-label': `select run ${id} for comparison`,
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
    let runs;
    try {
      runs = await api.runs();
      message.textContent = '';
    } catch (error) {
      message.textContent = `Cannot list the runs: ${error.message}`;
    }
    if (destroyed || mine !== generation) return;
    if (runs) {
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
          selected.delete(id);
        }
      }
      emptyState.hidden = runs.length > 0;
      updateCompareLink();
    }
    timer = setTimeout(refresh, REFRESH_MS);
  }

  refresh();
  return {
    destroy() {
      destroyed = true;
      clearTimeout(timer);
    },
  };
}
