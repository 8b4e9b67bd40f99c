// The particle view of a run in a periodic cell: a cell scene posted to the API runs, its stored
// frames carry the cell's edges (decoded by the dashboard's own frame_codec.js), and the run
// view draws the cell's outline, the image of a disc that crosses an edge on the far side, and
// nothing outside the cell (read from the canvas's pixels, placed through the world-to-pixel
// map the view exposes); a replayed stored frame likewise. No console errors.
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { WEB, check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const { decodeFrame } = await import(pathToFileURL(join(WEB, 'js', 'frame_codec.js')).href);

const W = 0.02;  // the cell: 20 mm square
const R = 0.002;
// A crosses the left edge (its image is at x + W on the right); B and C are well inside.
const CELL = {
  name: 'cell view',
  particles: [
    { shape: 'disc', radius: R, position: [0.0005, 0.005] },
    { shape: 'disc', radius: R, position: [0.01, 0.01] },
    { shape: 'disc', radius: R, position: [0.006, 0.016] },
  ],
  boundary: { type: 'periodic', size: [W, W] },
  stages: [{ type: 'free', duration: 0.002 }],
  output: { sample_interval: 0.0005 },
};

await runBrowserTest([], async ({ server, browser }) => {
  const { base } = server;
  const json = async (path, init) => (await fetch(`${base}${path}`, init)).json();
  const { id } = await json('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(CELL) });
  const done = await waitUntil(async () => ((await json(`/api/runs/${id}`)).status === 'completed'), 60);
  check('the cell scene runs through the API', Boolean(done));
  const index = await json(`/api/runs/${id}/frames`);
  const last = index.frames[index.frames.length - 1];
  const frame = decodeFrame(await (await fetch(`${base}/api/runs/${id}/frames?index=${last.index}`)).arrayBuffer());
  check('its stored frames carry the cell edges h1 = (W, 0), h2 = (0, W)',
    frame.cell && Math.abs(frame.cell[0] - W) < 1e-9 && frame.cell[1] === 0 && frame.cell[2] === 0 && Math.abs(frame.cell[3] - W) < 1e-9,
    JSON.stringify(frame.cell));

  const page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  await page.goto(`${base}/#/run/${id}`);
  const canvas = page.locator('canvas.particle-canvas');
  await canvas.waitFor({ state: 'visible' });
  const drawn = await waitUntil(async () => canvas.evaluate((c) => (c.dataset.cell && c.dataset.view ? { ...c.dataset } : null)), 30);
  check('the view knows the cell', Boolean(drawn));
  const corners = (drawn?.cell ?? '').split(',').map(Number);
  const expected = [0, 0, W, 0, W, W, 0, W];
  check('its outline is the parallelogram 0, h1, h1 + h2, h2', corners.length === 8 && corners.every((v, k) => Math.abs(v - expected[k]) < 1e-9), drawn?.cell);
  check('one image: the disc across the left edge', drawn?.cellImages === '1', drawn?.cellImages);
  await screenshot(page, 'cell-view');

  // The colour at world points, through the view's map (CSS pixels; the canvas may be denser).
  const colourAt = (points) => canvas.evaluate((c, pts) => {
    const [cx, cy, scale] = c.dataset.view.split(',').map(Number);
    const ratio = c.width / c.clientWidth;
    const ctx = c.getContext('2d');
    return pts.map(([x, y]) => {
      const px = Math.round((c.clientWidth / 2 + (x - cx) * scale) * ratio);
      const py = Math.round((c.clientHeight / 2 - (y - cy) * scale) * ratio);
      return Array.from(ctx.getImageData(px, py, 1, 1).data.slice(0, 3));
    });
  }, points);
  const background = [0xfb, 0xfc, 0xfd];  // the view's fill
  const differs = (a, b) => Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) > 12;
  const [image, own, empty, clipped, edge] = await colourAt([
    [W - 0.0005, 0.005],   // inside A's image on the right edge
    [0.0008, 0.005],       // inside A itself, left of the edge
    [W - 0.0005, 0.012],   // the same distance from the edge where no particle is
    [-0.0008, 0.005],      // A's own disc beyond the left edge: clipped away
    [0, 0.012],            // on the left edge, away from A
  ]);
  check('the crossing disc is drawn again on the far side of the cell, in its own colour',
    differs(image, background) && !differs(image, own), `${image}, its own ${own}, background ${background}`);
  check('where no particle is, the cell is empty', !differs(empty, background), `${empty}`);
  check('nothing is drawn outside the cell (the disc is clipped at the edge)', !differs(clipped, background), `${clipped}`);
  // The outline's colour, #1f5f8b: blue above red and green.
  check('the outline is drawn on the edge', edge[2] > edge[0] + 60 && edge[2] > edge[1] + 20, `${edge}`);

  // Replay: the slider back to the first sample loads a stored frame, still drawn in its cell.
  const slider = page.locator('.replay-bar input[type=range]');
  await waitUntil(() => page.$eval('.replay-bar input[type=range]', (e) => !e.disabled), 30);
  const stepBefore = await canvas.evaluate((c) => c.dataset.step);
  await slider.fill('0');
  const replayed = await waitUntil(async () => canvas.evaluate((c, before) => (c.dataset.step !== before ? { ...c.dataset } : null), stepBefore), 20);
  check('a replayed (stored) frame is drawn in its cell too, with the crossing disc\'s image',
    replayed && replayed.cell === drawn.cell && replayed.cellImages === '1', `step ${stepBefore} → ${replayed?.step}`);
  check('no console errors, page exceptions or failed requests', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
