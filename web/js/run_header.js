// The run view's header: name, status, progress, facts (stage, preset, particles, timing,
// the estimate the run was queued with, peak φ_mob, the run it started from) and the actions. Built once and updated
// in place every second while the run is live, so a click on Cancel is never lost to a
// re-render.
import { api } from './api.js';
import { h } from './dom.js';
import { TERMINAL_STATUSES, duration, localTime, percent, sig } from './format.js';

export class RunHeader {
  constructor(parent, onCancel, onResume) {
    this.title = h('h2');
    this.status = h('span', { class: 'status' });
    this.bar = h('span');
    this.progressLabel = h('span', { class: 'label' });
    this.facts = h('span', { class: 'facts' });
    // The validity envelope's warnings (docs/validity.md): the run goes on, its results may not mean what they say.
    this.warnings = h('ul', { class: 'warnings', hidden: true });
    this.cancel = h('button', { type: 'button', class: 'danger', onclick: onCancel }, 'Cancel run');
    // An interrupted run (server stopped or killed, wall-time limit) goes on from its checkpoint.
    this.resume = h('button', { type: 'button', onclick: onResume, hidden: true }, 'Resume run');
    // A finished run's specimen, kept at the end of each stage: another test on it (start_from).
    this.branch = h('a', { class: 'button', hidden: true }, 'New test on this specimen');
    this.csv = h('a', { class: 'button' }, 'Download CSV');
    this.compare = h('a', { class: 'button' }, 'Compare…');
    this.element = h('div', { class: 'run-header' },
      this.title, this.status,
      h('span', { class: 'progress', title: 'progress' }, h('span', { class: 'bar' }, this.bar), this.progressLabel),
      this.facts,
      h('span', { class: 'actions' }, this.cancel, this.resume, this.branch, this.csv, this.compare),
      this.warnings);
    parent.append(this.element);
  }

  /** `run` from GET /api/runs/{id}; `live` the latest stream status message, or null. */
  update(run, live) {
    const status = live?.status ?? run.status;
    const progress = live?.progress ?? run.progress ?? 0;
    const stage = live?.stage || run.stage;
    const running = !TERMINAL_STATUSES.has(status);
    const started = run.started_at ? Date.parse(run.started_at) / 1000 : null;
    let timing = null;
    if (running && started) {
      const elapsed = Date.now() / 1000 - started;
      timing = `${duration(elapsed)} elapsed`;
      // Below 2 % the estimate is noise.
      if (progress >= 0.02) timing += `, about ${duration((elapsed * (1 - progress)) / progress)} left`;
    } else if (run.wall_seconds !== null && run.wall_seconds !== undefined) {
      timing = `took ${duration(run.wall_seconds)}`;
    }
    // The server's estimate when the run was queued: a lower bound (criterion stages add to it).
    const estimate = run.estimated_seconds != null ? `estimated ≥ ${duration(run.estimated_seconds)}` : null;
    this.title.textContent = `#${run.id} ${run.name}`;
    this.status.className = `status ${status}`;
    this.status.dataset.status = status;
    this.status.textContent = status;
    this.bar.style.width = percent(progress, 1);
    this.progressLabel.textContent = percent(progress);
    this.facts.textContent = [
      stage ? `stage ${stage}` : null,
      run.origin === 'lammps' ? 'imported from LAMMPS' : run.preset ? `preset ${run.preset}` : 'custom scene',
      run.started_from ? `from run #${run.started_from.run_id}'s ${run.started_from.stage}` : null,
      `${run.particles} particles`,
      `created ${localTime(run.created_at)}`,
      timing,
      estimate,
      run.peak_phi_mob_deg !== null ? `peak φ_mob ${sig(run.peak_phi_mob_deg, 3)}°` : null,
    ].filter(Boolean).join(' · ');
    const warnings = run.warnings ?? [];
    this.warnings.hidden = warnings.length === 0;
    this.warnings.replaceChildren(...warnings.map((w) => h('li', {},
      `warning: ${w.field}: ${w.quantity} ${sig(w.value, 3)} (limit ${sig(w.limit, 3)})` +
      `${w.step != null ? ` at step ${w.step}` : ''}: ${w.meaning}`)));
    this.cancel.hidden = !running;
    this.resume.hidden = running || !run.resumable;
    this.branch.hidden = running || !(run.specimen_stages?.length > 0);
    this.branch.href = `#/new?from=${run.id}`;
    this.csv.href = api.csvUrl(run.id);
    this.csv.download = `grainlab-run-${run.id}-series.csv`;
    this.compare.href = `#/compare?ids=${run.id}`;
  }
}
