// The WebSocket stream of a real quick preset run: samples, histograms, shapes, status and
// binary frames arrive, the frame rate stays bounded, the streamed series equals the REST
// series and its CSV, and late joiners (mid-run and after the end) get the state at once.
import { WebSocket, check, finish, getJson, postJson, startServer, waitFor, watch, sleep } from './harness.mjs';

const PRESET = process.env.GRAINLAB_STREAM_PRESET ?? 'circular-quick';
const server = await startServer(['--max-concurrent', '1']);
try {
  const created = await postJson(`${server.base}/api/runs`, { preset: PRESET });
  check(`create ${PRESET}`, created.status === 201, JSON.stringify(created));
  const id = created.body.id;
  const live = watch(server.wsBase, id);
  const got = await live.done;
  const run = await getJson(`${server.base}/api/runs/${id}`);
  check('the run completed', run.status === 'completed', JSON.stringify(run));
  check('the server closed the stream normally after the end', got.closeCode === 1000, `code ${got.closeCode}`);

  const last = got.status.at(-1);
  check('status messages: running ... completed last', got.status.some((s) => s.status === 'running') &&
        last?.status === 'completed' && last.progress === 1, JSON.stringify(got.status.slice(-2)));
  check('shapes once, before any frame', got.shapes.length === 1 &&
        got.order.indexOf('shapes') < got.order.indexOf('frame'), got.order.slice(0, 5).join());
  const count = got.shapes[0]?.count;
  check(`shapes for every particle (${count})`, count === run.particles && got.shapes[0].shapes.length === count);
  check(`frames arrive (${got.frames.length})`, got.frames.length >= 3);
  check('every frame is a well-formed version-1 GLF1 frame for every particle', got.frames.every(
    (f) => f.magic === 'GLF1' && f.version === 1 && f.sizeOk && f.particles === count));
  check('frames go forward in steps', got.frames.every((f, k) => k === 0 || f.step >= got.frames[k - 1].step));
  check('force chains are drawn from particle pairs', got.frames.some((f) => f.contacts > 0) &&
        got.frames.every((f) => f.pairs.every(([i, j, fn]) => i < count && j < count && fn > 0)));
  const seconds = run.wall_seconds;
  check(`frame rate bounded: ${got.frames.length} frames in ${seconds.toFixed(2)} s (<= 20/s)`,
        got.frames.length <= 20 * seconds + 3);
  const sizes = got.frames.map((f) => f.size);
  console.log(`# frame bytes: ${Math.min(...sizes)}..${Math.max(...sizes)} for ${count} particles`);

  check(`samples arrive in order (${got.sample.length})`, got.sample.length > 5 &&
        got.sample.every((s, k) => s.seq === k));
  check(`histograms arrive (${got.histogram.length})`, got.histogram.length >= 1 &&
        Array.isArray(got.histogram.at(-1).histograms?.count));

  // The streamed series is the REST series is the CSV.
  const series = await getJson(`${server.base}/api/runs/${id}/series`);
  check('REST series has every streamed row', series.rows.length === got.sample.length);
  const sameRows = series.rows.every((row, k) => series.columns.every((c, j) => Object.is(row[j], got.sample[k].row[c])));
  check('streamed rows equal REST rows, column by column', sameRows);
  const csv = (await (await fetch(`${server.base}/api/runs/${id}/series?format=csv`)).text()).trimEnd().split('\n');
  check('CSV header is the columns', csv[0] === series.columns.join(','));
  const csvMatches = csv.slice(1).every((line, k) => line.split(',').every((cell, j) => {
    const v = series.rows[k][j];
    if (cell === '') return v === null;
    return series.columns[j] === 'stage' ? cell === v : Number(cell) === v;
  }));
  check(`CSV rows equal the JSON rows exactly (${csv.length - 1})`, csv.length - 1 === series.rows.length && csvMatches);

  // A late joiner after the end: the whole stored state, then a normal close.
  const after = await watch(server.wsBase, id).done;
  check('after the end: shapes, final status, every sample, a histogram and a frame',
        after.shapes.length === 1 && after.status.at(-1)?.status === 'completed' &&
        after.sample.length === got.sample.length && after.histogram.length === 1 && after.frames.length === 1 &&
        after.closeCode === 1000, JSON.stringify({ ...after, sample: after.sample.length, frames: after.frames.length }));

  // A late joiner mid-run gets the current state at once, then live messages.
  const second = (await postJson(`${server.base}/api/runs`, { preset: PRESET })).body.id;
  await waitFor(server.base, second, 'running');
  for (let i = 0; i < 200 && (await getJson(`${server.base}/api/runs/${second}/series`)).rows.length < 3; i++) await sleep(20);
  const mid = watch(server.wsBase, second);
  const midGot = await mid.done;
  const firstKinds = midGot.order.slice(0, 3);
  check('mid-run joiner starts with shapes and status', firstKinds[0] === 'shapes' && firstKinds[1] === 'status',
        firstKinds.join());
  check('mid-run joiner gets the samples so far, a frame and a histogram within 1 s',
        ['sample', 'frame', 'histogram'].every((k) => midGot.firstAt[k] - midGot.openedAt < 1000), JSON.stringify(midGot.firstAt));
  const midSeries = await getJson(`${server.base}/api/runs/${second}/series`);
  check('mid-run joiner misses no sample', midGot.sample.length === midSeries.rows.length &&
        midGot.sample.every((s, k) => s.seq === k));

  // Stream of an unknown run: 404 before any upgrade.
  const refused = await new Promise((resolve) => {
    const ws = new WebSocket(`${server.wsBase}/api/runs/999999/stream`);
    ws.on('unexpected-response', (req, res) => { resolve(res.statusCode); ws.terminate(); });
    ws.on('open', () => { resolve('opened'); ws.terminate(); });
    ws.on('error', () => {});
  });
  check('stream of an unknown run: 404 instead of an upgrade', refused === 404, String(refused));
} catch (e) {
  check('stream test ran', false, e.stack);
} finally {
  const code = await server.stop('SIGTERM');
  check('server stops cleanly', code === 0, `exit ${code}`);
  finish();
}
