// The strain slider: one position in the series that every view follows.
import { h } from './dom.js';

export class ReplayBar {
  constructor(parent, onSelect) {
    this.slider = h('input', {
      type: 'range', min: 0, max: 0, value: 0, step: 1, disabled: true, 'aria-label': 'Replay position',
      oninput: () => onSelect(Number(this.slider.value)),
    });
    this.mode = h('strong', {}, 'Live');
    this.where = h('span', { class: 'where' }, '');
    this.element = h('div', { class: 'replay-bar' }, this.mode, this.slider, this.where);
    parent.append(this.element);
  }

  setLive(text) {
    this.mode.textContent = 'Live';
    this.slider.disabled = true;
    this.where.textContent = text;
  }

  /** Enables the slider over `count` samples at position `index`. */
  setReplay(count, index) {
    this.mode.textContent = 'Replay';
    this.slider.max = String(Math.max(0, count - 1));
    this.slider.value = String(index);
    this.slider.disabled = count < 2;
  }

  setWhere(text) {
    this.where.textContent = text;
  }
}
