// The five rose diagrams of one sample, with a_k and θ_k from the series row beside each.
import { h } from './dom.js';
import { ROSES, drawRose, roseCaption } from './rose_diagram.js';

export class RosePanel {
  constructor(parent) {
    this.items = ROSES.map((rose) => {
      const canvas = h('canvas', { dataset: { rose: rose.key } });
      const caption = h('div', { class: 'caption' });
      return { rose, canvas, caption, element: h('div', { class: 'rose' }, canvas, caption) };
    });
    this.heading = h('div', { class: 'hint' }, 'Waiting for the first contacts…');
    this.element = h('div', { class: 'panel rose-panel' },
      h('h3', {}, 'Rose diagrams'),
      this.heading,
      h('div', { class: 'rose-grid' }, this.items.map((item) => item.element)),
      h('div', { class: 'rose-key' },
        'Bars: per-bin means over 180° (drawn twice: θ and θ + 180° are one direction); ',
        'orange where negative. Red: the fitted c₀ + c₁ cos 2θ + c₂ sin 2θ, dashed where negative.'));
    parent.append(this.element);
    this.message = null;
    this.row = null;
    this.resizeObserver = new ResizeObserver(() => this.draw());
    this.resizeObserver.observe(this.element);
  }

  /** A histogram message ({seq, step, stage, histograms}) and its sample's series row. */
  show(message, row) {
    this.message = message;
    this.row = row;
    this.element.dataset.seq = String(message.seq);
    const h0 = message.histograms;
    this.heading.textContent =
      `Sample ${message.seq} (${message.stage}, step ${message.step}): ${h0.contacts} contacts, ${h0.ends} contact ends, ${h0.bins} bins`;
    this.draw();
  }

  draw() {
    for (const item of this.items) {
      drawRose(item.canvas, item.rose, this.message?.histograms ?? null);
      item.caption.textContent = roseCaption(item.rose, this.row);
    }
  }

  destroy() {
    this.resizeObserver.disconnect();
  }
}
