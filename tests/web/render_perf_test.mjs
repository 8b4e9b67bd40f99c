// Drawing speed in headless Chromium's software rendering (--disable-gpu), with the
// dashboard's own modules served by the real server:
//  - the particle view: 2,500 elongated polygons with ~4,900 force-chain lines, coloured by
//    mean force and outlined, decoded from binary frames in the stream's format and drawn
//    once per animation frame for 3 s — at least 20 frames/s;
//  - the run view's seven charts with 10,000 samples each, appended to and redrawn once per
//    animation frame as a live run does — at least 20 updates/s.
// The measured rates are printed for the log (ctest keeps it).
import { check, runBrowserTest, screenshot } from './harness.mjs';

const MIN_FPS = 20;
const POLYGONS = 2500;
const CHART_POINTS = 10000;

await runBrowserTest([], async ({ server, browser }) => {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
  // An empty page of the server's origin, so the modules load from web/ as the dashboard's do.
  await page.route(`${server.base}/perf.html`, (route) => route.fulfill({
    contentType: 'text/html',
    body: '<!doctype html><html><head><link rel="stylesheet" href="/node_modules/uplot/dist/uPlot.min.css">'
      + '<link rel="stylesheet" href="/css/app.css"></head><body>'
      + '<div class="particle-canvas-box" style="width:900px;height:700px"><canvas class="particle-canvas"></canvas></div>'
      + '<div id="charts" style="width:1380px"></div></body></html>',
  }));
  await page.goto(`${server.base}/perf.html`);

  // ---- particles ----
  const particles = await page.evaluate(async ({ count, seconds }) => {
    const { ParticleView } = await import('/js/particle_view.js');
    const { prepareShapes } = await import('/js/particle_shapes.js');
    const { decodeFrame } = await import('/js/frame_codec.js');
    // A 50 × 50 lattice of the paper's elongated hexagons (L = 5 mm, aspect 1.5) at random angles.
    const side = Math.ceil(Math.sqrt(count));
    const spacing = 0.0045;  // touching or nearly, as in a compacted specimen
    const shapes = [];
    const polygon = [];
    for (let k = 0; k < 6; k++) polygon.push(0.0025 * Math.cos((k * Math.PI) / 3), (0.0025 / 1.5) * Math.sin((k * Math.PI) / 3));
    for (let i = 0; i < count; i++) shapes.push({ polygon });
    const view = new ParticleView(document.querySelector('canvas'));
    view.setShapes(prepareShapes({ count, shapes, boundary: [], walls: [] }));

    let seed = 7;
    const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
    const contacts = [];
    for (let i = 0; i < count; i++) {
      if ((i + 1) % side !== 0 && i + 1 < count) contacts.push([i, i + 1]);
      if (i + side < count) contacts.push([i, i + side]);
    }
    // 30 frames in the stream's binary layout, each a little moved and rotated.
    const frames = [];
    for (let f = 0; f < 30; f++) {
      const buffer = new ArrayBuffer(40 + count * 16 + contacts.length * 12);
      const header = new DataView(buffer);
      'GLF1'.split('').forEach((c, k) => header.setUint8(k, c.charCodeAt(0)));
      header.setUint16(4, 1, true);
      header.setUint16(6, 40, true);
      header.setBigInt64(8, BigInt(f * 1000), true);
      header.setFloat64(16, f * 1e-3, true);
      header.setUint32(24, count, true);
      header.setUint32(28, contacts.length, true);
      const p = new Float32Array(buffer, 40, count * 4);
      let maxMean = 0;
      for (let i = 0; i < count; i++) {
        p[4 * i] = (i % side) * spacing + 0.0002 * Math.sin(f / 3 + i);
        p[4 * i + 1] = Math.floor(i / side) * spacing + 0.0002 * Math.cos(f / 4 + i);
        p[4 * i + 2] = i * 2.4 + f * 0.05;
        p[4 * i + 3] = 1000 * random() ** 2;
        maxMean = Math.max(maxMean, p[4 * i + 3]);
      }
      const words = new Uint32Array(buffer, 40 + count * 16, contacts.length * 3);
      const floats = new Float32Array(buffer, 40 + count * 16, contacts.length * 3);
      let maxContact = 0;
      contacts.forEach(([i, j], k) => {
        words[3 * k] = i;
        words[3 * k + 1] = j;
        floats[3 * k + 2] = 2000 * random() ** 3;
        maxContact = Math.max(maxContact, floats[3 * k + 2]);
      });
      header.setFloat32(32, maxMean, true);
      header.setFloat32(36, maxContact, true);
      frames.push(buffer);
    }

    // As the live view does: each animation frame hands the view the next decoded frame
    // (setFrame), and the view draws it at the next animation frame. Draws are counted.
    let drawn = 0;
    let drawMs = 0;
    const draw = view.draw.bind(view);
    view.draw = () => {
      const t0 = performance.now();
      draw();
      drawMs += performance.now() - t0;
      drawn++;
    };
    let handed = 0;
    const start = performance.now();
    await new Promise((done) => {
      const tick = () => {
        view.setFrame(decodeFrame(frames[handed++ % frames.length]));
        if (performance.now() - start < seconds * 1000) requestAnimationFrame(tick);
        else done();
      };
      requestAnimationFrame(tick);
    });
    const elapsed = (performance.now() - start) / 1000;
    const animated = { fps: drawn / elapsed, frames: drawn, meanDrawMs: drawMs / drawn };

    // For the log: the same drawing back to back, each forced through rasterisation by reading
    // a pixel (the animation-frame rate above is what a person sees, and what is asserted).
    const ctx = document.querySelector('canvas').getContext('2d');
    const flushed0 = performance.now();
    for (let k = 0; k < 30; k++) {
      view.setFrame(decodeFrame(frames[k]));
      view.draw();
      ctx.getImageData(0, 0, 1, 1);
    }
    const flushedMs = (performance.now() - flushed0) / 30;
    return {
      ...animated, flushedMs,
      contacts: contacts.length, canvas: [ctx.canvas.width, ctx.canvas.height],
    };
  }, { count: POLYGONS, seconds: 3 });
  console.log(`     particles: ${POLYGONS} polygons + ${particles.contacts} chain lines on a ${particles.canvas.join('×')} canvas: `
    + `${particles.fps.toFixed(1)} frames/s over ${particles.frames} animation frames `
    + `(${particles.meanDrawMs.toFixed(1)} ms of script per frame; ${particles.flushedMs.toFixed(1)} ms per frame including rasterisation)`);
  check(`${POLYGONS} polygons are drawn at ≥ ${MIN_FPS} frames/s`, particles.fps >= MIN_FPS, `${particles.fps.toFixed(1)} frames/s`);
  await screenshot(page, 'perf-particles');

  // ---- charts ----
  const charts = await page.evaluate(async ({ points, seconds }) => {
    const { RunCharts } = await import('/js/run_charts.js');
    const { SeriesTable } = await import('/js/series_table.js');
    const table = new SeriesTable();
    // DEM series are trends with fluctuations correlated from one sample to the next: a
    // smooth trend plus a seeded random walk (pulled back towards the trend) per column.
    let seed = 11;
    const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648) - 0.5;
    const walks = new Map();
    const wave = (name, e, level, spread) => {
      const walk = 0.98 * (walks.get(name) ?? 0) + 0.2 * random();
      walks.set(name, walk);
      return level + spread * (Math.sin(3 * e) + walk);
    };
    const sample = (k) => {
      const e = k / points;  // 0..1 over the samples
      return {
        stage: 'shearing', time: k * 1e-4, step: k * 100, axial_strain: 0.2 * e,
        phi_mob_deg: wave('phi', e, 20, 5), q: wave('q', e, 1e5, 3e4), volumetric_strain: wave('ev', e, -0.01, 0.01),
        a_c: wave('ac', e, 0.3, 0.1), a_n: wave('an', e, 0.5, 0.1), a_t: wave('at', e, 0.1, 0.05),
        a_ln: wave('aln', e, 0.05, 0.02), a_lt: wave('alt', e, 0.08, 0.02),
        theta_c_deg: wave('tc', e, 95, 10), theta_n_deg: wave('tn', e, 92, 8), theta_t_deg: wave('tt', e, 90, 12),
        theta_ln_deg: wave('tln', e, 30, 5), theta_lt_deg: wave('tlt', e, 35, 5),
        omega_macro_deg: wave('om', e, 5, 3), omega_micro_deg: wave('omi', e, 5, 3.5),
        omega_eq10_deg: wave('o10', e, 4, 3), omega_eq11_deg: wave('o11', e, 6, 3),
        sigma12: wave('s12', e, 10, 50), sigma21: wave('s21', e, 10, 45),
        theta_sigma_macro_deg: wave('ts', e, 95, 5), theta_strain_rate_deg: 90, omega_strain_rate_deg: wave('oe', e, 5, 3),
      };
    };
    for (let k = 0; k < points; k++) table.appendSample(k, sample(k));
    const runCharts = new RunCharts(document.getElementById('charts'), new Set(['shearing']));
    await new Promise((r) => requestAnimationFrame(r));

    // Live: one more sample per animation frame and all seven charts redrawn from the table.
    let updates = 0;
    let drawMs = 0;
    const start = performance.now();
    while (performance.now() - start < seconds * 1000) {
      table.appendSample(points + updates, sample(points + updates));
      const t0 = performance.now();
      runCharts.table = table;
      runCharts.draw();
      drawMs += performance.now() - t0;
      updates++;
      await new Promise((r) => requestAnimationFrame(r));
    }
    const elapsed = (performance.now() - start) / 1000;

    // Replay: moving the marker over 10,000 points.
    const m0 = performance.now();
    for (let k = 0; k < 60; k++) runCharts.setMarkerRow(Math.floor((k / 60) * points));
    await new Promise((r) => requestAnimationFrame(r));
    const markerMs = (performance.now() - m0) / 60;
    const counts = [...document.querySelectorAll('.chart-panel')].map((p) => Number(p.dataset.points));
    return { updatesPerSecond: updates / elapsed, meanDrawMs: drawMs / updates, markerMs, counts };
  }, { points: CHART_POINTS, seconds: 3 });
  console.log(`     charts: 7 charts × ${CHART_POINTS} samples (${charts.counts.join(', ')} points): `
    + `${charts.updatesPerSecond.toFixed(1)} live updates/s (${charts.meanDrawMs.toFixed(1)} ms to rebuild all seven); `
    + `replay marker ${charts.markerMs.toFixed(2)} ms per move`);
  check(`every chart holds ≥ ${CHART_POINTS} points`, charts.counts.length === 7 && charts.counts.every((n) => n >= CHART_POINTS));
  check(`seven ${CHART_POINTS}-point charts update at ≥ ${MIN_FPS} per second`, charts.updatesPerSecond >= MIN_FPS,
    `${charts.updatesPerSecond.toFixed(1)} updates/s`);
  check('the replay marker moves in under 50 ms', charts.markerMs < 50, `${charts.markerMs.toFixed(2)} ms`);
  await page.evaluate(() => document.querySelector('.particle-canvas-box').remove());
  await screenshot(page, 'perf-charts');
  check('no page errors', errors.length === 0, errors.join('\n'));
});
