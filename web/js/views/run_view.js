// One run, live while it runs (the WebSocket stream) and replayed once it has ended (the REST
// series, histograms and stored frames), with one strain slider driving every view.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import { TERMINAL_STATUSES } from '../format.js';
import { ParticlePanel } from '../particle_panel.js';
import { ReplayBar } from '../replay_bar.js';
import { RunHeader } from '../run_header.js';
import { ReplaySource } from '../replay_source.js';
import { RosePanel } from '../rose_panel.js';
import { RunCharts } from '../run_charts.js';
import { RunStream } from '../run_stream.js';
import { SeriesTable, shearingAxis, shearingStages } from '../series_table.js';

const RECONNECT_TRIES = 5;

export function runView(root, id) {
  const top = h('div');
  const errorBox = h('div', { class: 'run-error', hidden: true });
  const body = h('div', { class: 'run-body' });
  const below = h('div');
  replaceChildren(root, h('section', { class: 'run-view' }, top, errorBox, body, below));

  const header = new RunHeader(top, () => cancel(), () => resume());
  const particles = new ParticlePanel(body);
  const roses = new RosePanel(body);
  const replayBar = new ReplayBar(below, (row) => select(row));
  let charts = null;

  let run = null;
  let table = new SeriesTable();
  let stream = null;
  let source = null;
  let lastStatus = null;
  let reconnects = 0;
  let frameToken = 0;
  let destroyed = false;
  const timers = new Set();

  const later = (fn, ms) => {
    const t = setTimeout(() => {
      timers.delete(t);
      if (!destroyed) fn();
    }, ms);
    timers.add(t);
  };

  function showError(message) {
    errorBox.hidden = !message;
    errorBox.textContent = message ?? '';
  }

  function renderHeader() {
    header.update(run, lastStatus);
    showError(run.error || lastStatus?.error || null);
  }

  async function cancel() {
    try {
      await api.cancel(run.id);
    } catch (error) {
      showError(`Cancel failed: ${error.message}`);
    }
  }

  async function resume() {
    try {
      await api.resume(run.id);
      // The view starts over: the stored samples, then the resumed run live.
      window.location.reload();
    } catch (error) {
      showError(`Resume failed: ${error.message}`);
    }
  }

  function whereText(row) {
    const r = table.row(row);
    if (!r) return '';
    const strain = r.axial_strain === null ? '–' : (100 * r.axial_strain).toFixed(2);
    return `sample ${table.seqs[row]} · ${r.stage} · ε₂₂ = ${strain} % · step ${r.step}`;
  }

  // ---- live ----
  function startLive() {
    stream = new RunStream(id, {
      onShapes: (message) => particles.setShapes(message),
      onFrame: (frame) => particles.setFrame(frame),
      onStatus: (message) => {
        const changed = message.status !== (lastStatus?.status ?? run.status);
        lastStatus = message;
        if (changed) refreshRun();
        renderHeader();
      },
      onSample: (message) => {
        if (!table.appendSample(message.seq, message.row)) return;
        charts.update(table);
        replayBar.setLive(whereText(table.length - 1));
      },
      onHistogram: (message) => roses.show(message, table.row(table.rowOfSeq(message.seq))),
      onClose: () => afterStream(),
    });
    stream.open();
    replayBar.setLive('waiting for the first sample…');
    tickHeader();
  }

  function tickHeader() {
    later(() => {
      if (stream) {
        renderHeader();
        tickHeader();
      }
    }, 1000);
  }

  async function refreshRun() {
    try {
      run = await api.run(id);
      renderHeader();
    } catch (error) {
      showError(error.message);
    }
  }

  async function afterStream() {
    stream = null;
    if (TERMINAL_STATUSES.has(lastStatus?.status)) {
      await refreshRun();
      await startReplay();
      return;
    }
    // The connection broke before the run ended: ask, then reconnect or replay.
    await refreshRun();
    if (TERMINAL_STATUSES.has(run.status)) {
      await startReplay();
    } else if (reconnects++ < RECONNECT_TRIES) {
      later(startLive, 1000 * reconnects);
    } else {
      showError('The live stream keeps dropping; reload the page to try again.');
    }
  }

  // ---- replay ----
  async function startReplay() {
    source = new ReplaySource(id);
    try {
      const [series] = await Promise.all([api.series(id), source.load()]);
      if (destroyed) return;
      if (source.frames.length) particles.setShapes(await api.shapes(id));
      if (destroyed) return;
      table = SeriesTable.fromRest(series);
    } catch (error) {
      showError(`Loading the stored run failed: ${error.message}`);
      return;
    }
    charts.update(table);
    replayBar.setReplay(table.length, Math.max(0, table.length - 1));
    if (table.length) select(table.length - 1);
    else replayBar.setWhere('this run stored no samples');
    if (!source.frames.length) particles.overlay.textContent = 'no particle frames were stored for this run';
  }

  function select(row) {
    const r = table.row(row);
    if (!r || !source) return;
    replayBar.setWhere(whereText(row));
    charts.setMarkerRow(row);
    const histogram = source.histogramAt(table.seqs[row]);
    if (histogram) roses.show(histogram, table.row(table.rowOfSeq(histogram.seq)));
    const info = source.frameNearest(r.step);
    if (!info) return;
    const token = ++frameToken;
    source.frame(info).then((frame) => {
      if (token === frameToken && !destroyed) particles.setFrame(frame);
    }, (error) => showError(`Loading a frame failed: ${error.message}`));
  }

  // ---- start ----
  (async () => {
    try {
      run = await api.run(id);
    } catch (error) {
      replaceChildren(root, h('div', { class: 'empty-state' }, `Run ${id}: ${error.message}. `, h('a', { href: '#/runs' }, 'Back to the runs')));
      return;
    }
    if (destroyed) return;
    charts = new RunCharts(below, shearingStages(run.scene), shearingAxis(run.scene));
    renderHeader();
    if (TERMINAL_STATUSES.has(run.status)) await startReplay();
    else startLive();
  })();

  return {
    destroy() {
      destroyed = true;
      for (const t of timers) clearTimeout(t);
      stream?.close();
      particles.destroy();
      roses.destroy();
      charts?.destroy();
    },
  };
}
