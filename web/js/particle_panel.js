// The particle view's panel: colour and chain controls, the legend and the canvas.
import { h, replaceChildren } from './dom.js';
import { forcePerMetre } from './format.js';
import { CELL_STROKE, ParticleView } from './particle_view.js';
import { prepareShapes } from './particle_shapes.js';
import {
  BOUNDARY_FILL, CHAIN_COLOUR, FORCE_PALETTE, ORIENTATION_PALETTE, gradientCss,
} from './colour_scales.js';

export class ParticlePanel {
  constructor(parent) {
    this.colour = h('select', { 'aria-label': 'Colour particles by', onchange: () => this.changeColour() },
      h('option', { value: 'force' }, 'mean contact force'),
      h('option', { value: 'orientation' }, 'orientation (long axis)'));
    this.chains = h('input', { type: 'checkbox', checked: true, onchange: () => this.view.setShowChains(this.chains.checked) });
    this.legend = h('div', { class: 'legend' });
    this.overlay = h('div', { class: 'particle-overlay' }, 'waiting for the particles…');
    this.canvas = h('canvas', { class: 'particle-canvas', 'aria-label': 'Particles' });
    this.element = h('div', { class: 'particle-panel panel' },
      h('div', { class: 'toolbar' },
        h('label', {}, 'Colour by ', this.colour),
        h('label', {}, this.chains, ' force chains (width ∝ fₙ)'),
        h('button', { type: 'button', onclick: () => this.view.resetView(), title: 'Or double-click the view' }, 'Fit view'),
        h('span', { class: 'hint' }, 'drag to pan, wheel to zoom')),
      h('div', { class: 'particle-canvas-box' }, this.canvas, this.overlay),
      this.legend);
    parent.append(this.element);
    this.view = new ParticleView(this.canvas);
    this.frame = null;
    this.renderLegend();
  }

  setShapes(message) {
    this.view.setShapes(prepareShapes(message));
  }

  setFrame(frame) {
    this.frame = frame;
    this.view.setFrame(frame);
    this.overlay.textContent =
      `step ${frame.step} · t = ${frame.time.toPrecision(4)} s · ${frame.count} particles · ${frame.contactCount} chain contacts`;
    this.renderLegend();
  }

  changeColour() {
    this.view.setColourMode(this.colour.value);
    this.renderLegend();
  }

  renderLegend() {
    const byForce = this.colour.value === 'force';
    const max = this.frame?.maxMeanForce ?? 0;
    replaceChildren(this.legend,
      byForce ? 'mean |f| per particle' : 'long-axis direction (discs: rotation)',
      h('span', {}, byForce ? '0' : '0°'),
      h('span', { class: 'ramp', style: { background: gradientCss(byForce ? FORCE_PALETTE : ORIENTATION_PALETTE) } }),
      h('span', {}, byForce ? forcePerMetre(max) : '180°'),
      ...(this.frame?.cell
        ? [h('span', { class: 'swatch', style: { background: CELL_STROKE } }), 'periodic cell (images of edge-crossing particles drawn inside it)']
        : [h('span', { class: 'swatch', style: { background: BOUNDARY_FILL } }), 'boundary (membrane)']),
      h('span', { class: 'swatch', style: { background: CHAIN_COLOUR } }),
      `chain: fₙ up to ${forcePerMetre(this.frame?.maxContactForce ?? 0)}`);
  }

  destroy() {
    this.view.destroy();
  }
}
