// The particle view: discs and polygons at their true shapes on a plain Canvas2D, coloured
// by mean contact force or orientation, force chains as lines of width ∝ f_n, pan and zoom.
//
// Why Canvas2D and this batching: in headless Chromium without a GPU (software raster), a
// fill per particle costs a call each, while one path holding every particle rasterises
// super-linearly (measured: 2,500 hexagons in one path 55 ms, in paths of 32–64 about 7 ms).
// Particles are therefore grouped by palette entry (a counting sort per frame) and each group
// is filled and outlined in paths of at most PATH_CHUNK shapes; chains likewise by width
// class, with butt caps (round caps doubled their cost). tests/web/render_perf_test.mjs
// measures 2,500 polygons against 20 frames/s.
//
// A run in a periodic cell (a frame with `cell`): the cell's outline is drawn, everything is
// clipped to it, each particle is drawn wrapped into the cell and, if it crosses an edge, its
// images on the other sides too (web/js/cell_images.js); a chain across an edge is drawn to the
// other particle's nearest image, from both ends. Nothing is drawn outside the cell.
import { CLUMP, DISC } from './particle_shapes.js';
import { cellCorners, nearestImage, placeInCell } from './cell_images.js';
import {
  BOUNDARY_FILL, BOUNDARY_STROKE, CHAIN_COLOUR, FORCE_PALETTE, ORIENTATION_PALETTE,
} from './colour_scales.js';

const CHAIN_CLASSES = 10;
const PATH_CHUNK = 48;  // shapes or chain lines per path: see above
const OUTLINE_MIN_PIXELS = 2.5;  // particles smaller than this on screen are filled only
export const CELL_STROKE = '#1f5f8b';

export class ParticleView {
  /** @param {HTMLCanvasElement} canvas */
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d', { alpha: false });
    this.shapes = null;
    this.frame = null;
    this.placed = null;
    this.colourMode = 'force';
    this.showChains = true;
    this.view = null;  // {cx, cy, scale}: world point at the canvas centre, pixels per metre
    this.order = new Uint32Array(0);
    this.bucket = new Uint16Array(0);
    this.typicalRadius = 0;
    this.pending = 0;
    this.installInteraction();
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(canvas);
    this.resize();
  }

  destroy() {
    this.resizeObserver.disconnect();
    if (this.pending) cancelAnimationFrame(this.pending);
    this.abort.abort();
  }

  setShapes(shapes) {
    this.shapes = shapes;
    this.order = new Uint32Array(shapes.count);
    this.bucket = new Uint16Array(shapes.count);
    // The median bounding radius: how big a particle is on screen decides outlines and chain widths.
    const sorted = Array.from(shapes.radius).sort((a, b) => a - b);
    this.typicalRadius = sorted[Math.floor(sorted.length / 2)] ?? 0;
    this.view = null;
    this.place();
    this.requestDraw();
  }

  /** Where a cell's particles and their images are drawn, once per frame (null: no cell). */
  place() {
    const frame = this.frame;
    this.placed = frame?.cell && this.shapes && frame.count === this.shapes.count
      ? placeInCell(frame.cell, frame.particles, frame.count, this.shapes.radius) : null;
    if (this.placed) {
      this.canvas.dataset.cell = cellCorners(frame.cell).join(',');
      this.canvas.dataset.cellImages = String(this.placed.images.length / 3);
    } else {
      delete this.canvas.dataset.cell;
      delete this.canvas.dataset.cellImages;
    }
  }

  setFrame(frame) {
    if (this.shapes && frame.count !== this.shapes.count) return;  // shapes of another run
    this.frame = frame;
    this.place();
    this.canvas.dataset.step = String(frame.step);
    this.canvas.dataset.particles = String(frame.count);
    this.requestDraw();
  }

  setColourMode(mode) {
    this.colourMode = mode;
    this.requestDraw();
  }

  setShowChains(show) {
    this.showChains = show;
    this.requestDraw();
  }

  resetView() {
    this.view = null;
    this.requestDraw();
  }

  /** Draws at the next animation frame; several requests before it draw once. */
  requestDraw() {
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.draw();
    });
  }

  resize() {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    if (width !== this.canvas.width || height !== this.canvas.height) {
      this.canvas.width = width;
      this.canvas.height = height;
      this.draw();
    }
  }

  /** Frames the whole specimen (a periodic cell: its outline). */
  fit() {
    const { particles, count } = this.frame;
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    if (this.frame.cell) {
      const c = cellCorners(this.frame.cell);
      for (let k = 0; k < 8; k += 2) {
        minX = Math.min(minX, c[k]); maxX = Math.max(maxX, c[k]);
        minY = Math.min(minY, c[k + 1]); maxY = Math.max(maxY, c[k + 1]);
      }
    }
    for (let i = 0; i < count && !this.frame.cell; i++) {
      const r = this.shapes.radius[i];
      const x = particles[4 * i], y = particles[4 * i + 1];
      minX = Math.min(minX, x - r); maxX = Math.max(maxX, x + r);
      minY = Math.min(minY, y - r); maxY = Math.max(maxY, y + r);
    }
    if (!(maxX > minX && maxY > minY)) {
      this.view = { cx: 0, cy: 0, scale: 1000 };
      return;
    }
    const ratio = window.devicePixelRatio || 1;
    const width = this.canvas.width / ratio, height = this.canvas.height / ratio;
    this.view = {
      cx: (minX + maxX) / 2,
      cy: (minY + maxY) / 2,
      scale: 0.94 * Math.min(width / (maxX - minX), height / (maxY - minY)),
    };
  }

  draw() {
    const ctx = this.ctx;
    const { width, height } = this.canvas;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#fbfcfd';
    ctx.fillRect(0, 0, width, height);
    if (!this.shapes || !this.frame) return;
    if (!this.view) this.fit();
    const ratio = window.devicePixelRatio || 1;
    const k = this.view.scale * ratio;  // device pixels per metre
    // World coordinates with y up: the path is built in metres and the canvas scales it.
    ctx.setTransform(k, 0, 0, -k, width / 2 - k * this.view.cx, height / 2 + k * this.view.cy);
    // The world-to-pixel map (CSS pixels, y down), for tests and tools that read the picture.
    this.canvas.dataset.view = `${this.view.cx},${this.view.cy},${this.view.scale}`;
    this.drawWalls(ctx, k);
    if (this.placed) {
      ctx.save();
      this.traceCell(ctx);
      ctx.clip();
    }
    this.drawParticles(ctx, k);
    if (this.showChains) this.drawChains(ctx, k);
    if (this.placed) {
      ctx.restore();
      this.traceCell(ctx);
      ctx.lineWidth = 2 / k;
      ctx.strokeStyle = CELL_STROKE;
      ctx.stroke();
    }
  }

  traceCell(ctx) {
    const c = cellCorners(this.frame.cell);
    ctx.beginPath();
    ctx.moveTo(c[0], c[1]);
    for (let a = 2; a < 8; a += 2) ctx.lineTo(c[a], c[a + 1]);
    ctx.closePath();
  }

  drawWalls(ctx, k) {
    if (!this.shapes.walls.length) return;
    const reach = (this.canvas.width + this.canvas.height) / k;
    ctx.beginPath();
    for (const wall of this.shapes.walls) {
      const [px, py] = wall.point;
      const [nx, ny] = wall.normal;
      ctx.moveTo(px - ny * reach, py + nx * reach);
      ctx.lineTo(px + ny * reach, py - nx * reach);
    }
    ctx.lineWidth = 3 / k;
    ctx.strokeStyle = '#44505c';
    ctx.stroke();
  }

  drawParticles(ctx, k) {
    const { particles, count } = this.frame;
    const shapes = this.shapes;
    const palette = this.colourMode === 'orientation' ? ORIENTATION_PALETTE : FORCE_PALETTE;
    const boundaryBucket = palette.length;
    const bucketCount = palette.length + 1;
    const bucket = this.bucket;
    const scale = this.frame.maxMeanForce > 0 ? (palette.length - 1) / this.frame.maxMeanForce : 0;
    const sizes = new Uint32Array(bucketCount + 1);
    for (let i = 0; i < count; i++) {
      let b;
      if (shapes.boundary[i]) {
        b = boundaryBucket;
      } else if (this.colourMode === 'orientation') {
        let axis = (particles[4 * i + 2] + shapes.axisAngle[i]) % Math.PI;
        if (axis < 0) axis += Math.PI;
        b = Math.min(palette.length - 1, Math.floor((axis / Math.PI) * palette.length));
      } else {
        b = Math.min(palette.length - 1, Math.round(particles[4 * i + 3] * scale));
      }
      bucket[i] = b;
      sizes[b + 1]++;
    }
    for (let b = 0; b < bucketCount; b++) sizes[b + 1] += sizes[b];  // bucket start offsets
    const start = sizes.slice();
    const order = this.order;
    for (let i = 0; i < count; i++) order[start[bucket[i]]++] = i;

    // A cell's images, grouped by their particle's bucket: drawn in the same paths.
    const placed = this.placed;
    const imagesOf = placed ? new Array(bucketCount).fill(null).map(() => []) : null;
    if (placed) for (let a = 0; a < placed.images.length; a += 3) imagesOf[bucket[placed.images[a]]].push(a);
    const outline = this.typicalRadius * k >= OUTLINE_MIN_PIXELS;
    ctx.lineWidth = 0.8 / k;
    ctx.lineJoin = 'round';
    for (let b = 0; b < bucketCount; b++) {
      ctx.fillStyle = b === boundaryBucket ? BOUNDARY_FILL : palette[b];
      ctx.strokeStyle = b === boundaryBucket ? BOUNDARY_STROKE : 'rgba(40, 45, 55, 0.45)';
      for (let from = sizes[b]; from < sizes[b + 1]; from += PATH_CHUNK) {
        ctx.beginPath();
        const to = Math.min(sizes[b + 1], from + PATH_CHUNK);
        for (let n = from; n < to; n++) {
          const i = order[n];
          if (placed) this.tracePath(ctx, i, particles, placed.x[i], placed.y[i]);
          else this.tracePath(ctx, i, particles, particles[4 * i], particles[4 * i + 1]);
        }
        ctx.fill();
        if (outline || b === boundaryBucket) ctx.stroke();
      }
      if (!placed) continue;
      const images = imagesOf[b], all = placed.images;
      for (let from = 0; from < images.length; from += PATH_CHUNK) {
        ctx.beginPath();
        const to = Math.min(images.length, from + PATH_CHUNK);
        for (let n = from; n < to; n++) {
          const a = images[n];
          this.tracePath(ctx, all[a], particles, all[a + 1], all[a + 2]);
        }
        ctx.fill();
        if (outline) ctx.stroke();
      }
    }
  }

  /** Particle i's outline with its centroid at (x, y). */
  tracePath(ctx, i, particles, x, y) {
    const shapes = this.shapes;
    if (shapes.kind[i] === DISC) {
      const r = shapes.radius[i];
      ctx.moveTo(x + r, y);
      ctx.arc(x, y, r, 0, 2 * Math.PI);
      return;
    }
    const angle = particles[4 * i + 2];
    const c = Math.cos(angle), s = Math.sin(angle);
    if (shapes.kind[i] === CLUMP) {
      const m = shapes.members;
      for (let a = 3 * shapes.memberStart[i]; a < 3 * shapes.memberStart[i + 1]; a += 3) {
        const mx = x + c * m[a] - s * m[a + 1], my = y + s * m[a] + c * m[a + 1], r = m[a + 2];
        ctx.moveTo(mx + r, my);
        ctx.arc(mx, my, r, 0, 2 * Math.PI);
      }
      return;
    }
    const v = shapes.vertices;
    const from = 2 * shapes.vertexStart[i], to = 2 * shapes.vertexStart[i + 1];
    ctx.moveTo(x + c * v[from] - s * v[from + 1], y + s * v[from] + c * v[from + 1]);
    for (let a = from + 2; a < to; a += 2) ctx.lineTo(x + c * v[a] - s * v[a + 1], y + s * v[a] + c * v[a + 1]);
    ctx.closePath();
  }

  drawChains(ctx, k) {
    const { particles, contactCount, contactIndices, contactForces, maxContactForce, cell } = this.frame;
    const placed = this.placed;
    if (!contactCount || !(maxContactForce > 0)) return;
    // The strongest chain is as wide as 0.7 of a typical particle radius on screen.
    const widest = Math.max(2, 0.7 * this.typicalRadius * k);
    ctx.strokeStyle = CHAIN_COLOUR;
    ctx.lineCap = 'butt';
    for (let c = 0; c < CHAIN_CLASSES; c++) {
      const low = c / CHAIN_CLASSES, high = (c + 1) / CHAIN_CLASSES;
      ctx.lineWidth = (widest * (c + 0.5)) / CHAIN_CLASSES / k;
      let lines = 0;
      ctx.beginPath();
      for (let n = 0; n < contactCount; n++) {
        const f = contactForces[3 * n + 2] / maxContactForce;
        if (f <= low || f > high) continue;
        const i = contactIndices[3 * n], j = contactIndices[3 * n + 1];
        if (placed) {
          // To j's nearest image, and from j to i's: across an edge both halves show in the cell.
          const xi = placed.x[i], yi = placed.y[i], xj = placed.x[j], yj = placed.y[j];
          const [dx, dy] = nearestImage(cell, xj - xi, yj - yi);
          ctx.moveTo(xi, yi);
          ctx.lineTo(xi + dx, yi + dy);
          if (Math.abs(xi + dx - xj) + Math.abs(yi + dy - yj) > 1e-9) {
            ctx.moveTo(xj, yj);
            ctx.lineTo(xj - dx, yj - dy);
          }
        } else {
          ctx.moveTo(particles[4 * i], particles[4 * i + 1]);
          ctx.lineTo(particles[4 * j], particles[4 * j + 1]);
        }
        if (++lines % PATH_CHUNK === 0) {
          ctx.stroke();
          ctx.beginPath();
        }
      }
      if (lines % PATH_CHUNK) ctx.stroke();
    }
  }


  installInteraction() {
    this.abort = new AbortController();
    const options = { signal: this.abort.signal };
    const canvas = this.canvas;
    let drag = null;
    canvas.addEventListener('pointerdown', (event) => {
      if (!this.view) return;
      drag = { x: event.clientX, y: event.clientY };
      canvas.setPointerCapture(event.pointerId);
      canvas.classList.add('dragging');
    }, options);
    canvas.addEventListener('pointermove', (event) => {
      if (!drag) return;
      this.view.cx -= (event.clientX - drag.x) / this.view.scale;
      this.view.cy += (event.clientY - drag.y) / this.view.scale;
      drag = { x: event.clientX, y: event.clientY };
      this.requestDraw();
    }, options);
    const endDrag = () => {
      drag = null;
      canvas.classList.remove('dragging');
    };
    canvas.addEventListener('pointerup', endDrag, options);
    canvas.addEventListener('pointercancel', endDrag, options);
    canvas.addEventListener('wheel', (event) => {
      if (!this.view) return;
      event.preventDefault();
      // Zoom about the cursor: the world point under it stays put.
      const rect = canvas.getBoundingClientRect();
      const px = event.clientX - rect.left - rect.width / 2;
      const py = event.clientY - rect.top - rect.height / 2;
      const factor = Math.exp(-event.deltaY * 0.0015);
      const wx = this.view.cx + px / this.view.scale, wy = this.view.cy - py / this.view.scale;
      this.view.scale *= factor;
      this.view.cx = wx - px / this.view.scale;
      this.view.cy = wy + py / this.view.scale;
      this.requestDraw();
    }, { ...options, passive: false });
    canvas.addEventListener('dblclick', () => this.resetView(), options);
  }
}
