// 50 WebSocket clients watching one run, one of which never reads: the run must finish no
// more than 10% slower than with nobody watching, and the 49 readers must see it to the end.
//
// "Slower" is measured on the simulation thread itself. Its work does not depend on who
// watches (each message is encoded once and handed to the I/O strand in one post, whatever
// the number of watchers: stream_hub_test.cpp), so what watchers can cost it is time off its
// core: waiting for a CPU the I/O threads took, or blocking on anything. wall/cpu of that
// thread is 1 plus that waiting share, measured within one run, so it does not move when a
// shared machine runs faster or slower; wall time alone did (the same unwatched run took
// 1.15-1.70 s within one minute here, and CI failed on it). The test compares medians of
// wall/cpu over runs with and without watchers, alternated; wall times are printed too. Over
// the limit, it measures as many pairs again and judges on all of them (a burst on the host
// is not in every pair; a real cost is).
import { check, finish, getJson, postJson, startServer, waitFor, watch } from './harness.mjs';

const PRESET = process.env.GRAINLAB_STREAM_PRESET ?? 'circular-quick';
const REPEATS = Number(process.env.GRAINLAB_SLOW_REPEATS ?? 5);
const CLIENTS = Number(process.env.GRAINLAB_SLOW_CLIENTS ?? 50);
const LIMIT = Number(process.env.GRAINLAB_SLOW_LIMIT ?? 1.10);

const median = (xs) => { const s = [...xs].sort((a, b) => a - b); const m = s.length >> 1; return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2; };

import { setPriority } from 'node:os';

const server = await startServer(['--max-concurrent', '1']);
// The 50 clients stand for people on other machines: their parsing is not the server's cost,
// so this process yields the CPU to the server (which keeps its normal priority).
setPriority(19);
try {
  async function oneRun(clients) {
    const id = (await postJson(`${server.base}/api/runs`, { preset: PRESET })).body.id;
    const watchers = [];
    for (let k = 0; k < clients; k++) watchers.push(watch(server.wsBase, id, { paused: k === 0, light: true }));
    const run = await waitFor(server.base, id, 'completed', 300);
    const readers = await Promise.all(watchers.slice(1).map((w) => w.done));
    for (const w of watchers.slice(0, 1)) w.ws.terminate();
    return { wall: run.wall_seconds, cpu: run.cpu_seconds, readers };
  }

  await oneRun(0);  // warm-up: page cache, allocator, CPU frequency
  const base = [];    // { wall, cpu } with nobody watching
  const loaded = [];  // { wall, cpu } with CLIENTS watching
  let readersOk = true;
  let frames = 0;
  async function pairs(count) {
    for (let r = 0; r < count; r++) {
      base.push(await oneRun(0));
      const run = await oneRun(CLIENTS);
      loaded.push(run);
      readersOk &&= run.readers.every((g) => g.status.at(-1)?.status === 'completed' && g.frames.length > 0 && g.closeCode === 1000);
      frames += run.readers.reduce((n, g) => n + g.frames.length, 0) / run.readers.length;
    }
  }
  const slowdown = () => median(loaded.map((r) => r.wall / r.cpu)) / median(base.map((r) => r.wall / r.cpu));
  await pairs(REPEATS);
  if (slowdown() > LIMIT) {
    // A burst on the shared host can hold the simulation thread off its core through several
    // runs in a row. Judge on twice as many alternated pairs before calling it a regression:
    // a real cost (a 20 µs stall per watcher measured 1.50) is in every pair, a burst is not.
    console.log(`# slowdown ${((slowdown() - 1) * 100).toFixed(1)}% over ${REPEATS} pairs: measuring ${REPEATS} more`);
    await pairs(REPEATS);
  }
  const show = (xs) => xs.map((x) => x.toFixed(3)).join(' ');
  const wallBase = base.map((r) => r.wall);
  const wallLoaded = loaded.map((r) => r.wall);
  const waitBase = base.map((r) => r.wall / r.cpu);
  const waitLoaded = loaded.map((r) => r.wall / r.cpu);
  const ratio = slowdown();
  console.log(`# wall seconds, nobody watching: ${show(wallBase)} (median ${median(wallBase).toFixed(3)})`);
  console.log(`# wall seconds, ${CLIENTS} watching (1 never reading): ${show(wallLoaded)} (median ${median(wallLoaded).toFixed(3)})`);
  console.log(`# wall/cpu of the simulation thread, nobody watching: ${show(waitBase)} (median ${median(waitBase).toFixed(3)})`);
  console.log(`# wall/cpu of the simulation thread, ${CLIENTS} watching: ${show(waitLoaded)} (median ${median(waitLoaded).toFixed(3)})`);
  console.log(`# slowdown ${((ratio - 1) * 100).toFixed(1)}% (wall medians alone: ${((median(wallLoaded) / median(wallBase) - 1) * 100).toFixed(1)}%); ` +
              `${(frames / loaded.length).toFixed(0)} frames per reader per run`);
  check(`${CLIENTS - 1} reading clients each saw every run to 'completed' with frames`, readersOk);
  check('every run reports the CPU time of its simulation thread',
        [...base, ...loaded].every((r) => Number.isFinite(r.cpu) && r.cpu > 0 && r.cpu <= r.wall + 0.01));
  check(`run with ${CLIENTS} watchers no more than ${((LIMIT - 1) * 100).toFixed(0)}% slower (wall/cpu median ${median(waitLoaded).toFixed(3)} vs ${median(waitBase).toFixed(3)})`,
        ratio <= LIMIT);
  const health = await getJson(`${server.base}/api/health`);
  check('server healthy afterwards with no watcher left', health.status === 'ok' && health.watchers === 0, JSON.stringify(health));
} catch (e) {
  check('slow-client test ran', false, e.stack);
} finally {
  const code = await server.stop('SIGTERM');
  check('server stops cleanly with a stalled client connected', code === 0, `exit ${code}`);
  finish();
}
