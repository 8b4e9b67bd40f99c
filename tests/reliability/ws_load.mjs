// Load: 50 WebSocket clients on one run, one of them stalled (it pauses its socket and never
// reads). The same run with 0 and with 50 watchers, alternated, GRAINLAB_LOAD_PAIRS pairs
// (default 3): the run's engine speed (particle-steps per second of wall time, from
// GET /api/runs/{id}) with and without them, and the server's resident memory throughout.
//
// Memory bound. Every message is encoded once and shared by all the watchers' queues
// (stream_hub.cpp posts one Outgoing, a shared_ptr, to every session), and a session's queue
// holds at most SendQueue::Limits::maxBytes = 16 MiB of them (send_queue.hpp) before the
// server drops the client. So watchers can add at most 16 MiB of queued messages (the
// stalled one's backlog; the readers' queues hold a subset of the same messages) plus each
// connection's own buffers (Beast's read buffer and stream state, a few KiB; 256 KiB each is
// allowed). The limit is the server's RSS with nobody watching (the largest sample of the
// unwatched runs) + 16 MiB + 50 x 0.25 MiB.
import { setPriority } from 'node:os';

import { check, figure, finish, getJson, longScene, median, particleStepsPerSecond, postJson, sampleRss,
         startServer, waitFor, watch } from './common.mjs';

const PAIRS = Number(process.env.GRAINLAB_LOAD_PAIRS ?? 3);
const CLIENTS = Number(process.env.GRAINLAB_LOAD_CLIENTS ?? 50);
const QUEUE_CAP_MIB = 16;       // SendQueue::Limits::maxBytes
const PER_CONNECTION_MIB = 0.25;

const server = await startServer({ args: ['--max-concurrent', '1'] });
// The clients stand for people on other machines: their parsing is not the server's cost, so
// this process yields the CPU to the server (which keeps its normal priority).
setPriority(19);
try {
  const scene = await longScene(server.base);

  async function oneRun(clients) {
    const rss = sampleRss(server.pid);
    const { body } = await postJson(`${server.base}/api/runs`, scene);
    const watchers = [];
    for (let k = 0; k < clients; k++) watchers.push(watch(server.wsBase, body.id, { paused: k === 0, light: true, timeoutMs: 600000 }));
    const run = await waitFor(server.base, body.id, 'completed', 600);
    const readers = await Promise.all(watchers.slice(1).map((w) => w.done));
    const memory = rss.stop();
    for (const w of watchers.slice(0, 1)) w.ws.terminate();
    return { speed: particleStepsPerSecond(run), wall: run.wall_seconds, cpu: run.cpu_seconds, rssMax: memory.max, readers };
  }

  await oneRun(0);  // warm-up: page cache, allocator, CPU frequency
  const base = [];
  const loaded = [];
  for (let p = 0; p < PAIRS; p++) {
    base.push(await oneRun(0));
    loaded.push(await oneRun(CLIENTS));
    const [b, l] = [base.at(-1), loaded.at(-1)];
    console.log(`# pair ${p + 1}: ${(b.speed / 1e6).toFixed(2)} vs ${(l.speed / 1e6).toFixed(2)} M particle-steps/s ` +
                `(wall ${b.wall.toFixed(2)} vs ${l.wall.toFixed(2)} s, wall/cpu ${(b.wall / b.cpu).toFixed(3)} vs ` +
                `${(l.wall / l.cpu).toFixed(3)}), max RSS ${b.rssMax.toFixed(1)} vs ${l.rssMax.toFixed(1)} MiB`);
  }

  const speedBase = median(base.map((r) => r.speed));
  const speedLoaded = median(loaded.map((r) => r.speed));
  const slowdown = 1 - speedLoaded / speedBase;
  // wall/cpu of the simulation thread: what waiting cost it, independent of how fast the
  // shared machine happens to be (tests/server/slow_clients_test.mjs).
  const waitBase = median(base.map((r) => r.wall / r.cpu));
  const waitLoaded = median(loaded.map((r) => r.wall / r.cpu));
  const rssBase = Math.max(...base.map((r) => r.rssMax));
  const rssLoaded = Math.max(...loaded.map((r) => r.rssMax));
  const rssLimit = rssBase + QUEUE_CAP_MIB + CLIENTS * PER_CONNECTION_MIB;
  const S = 'websocket load';
  figure(S, 'run length (wall s, median, unwatched)', median(base.map((r) => r.wall)), { unit: 's' });
  figure(S, 'engine speed, 0 clients (median)', speedBase / 1e6, { unit: 'M particle-steps/s' });
  figure(S, `engine speed, ${CLIENTS} clients, 1 stalled (median)`, speedLoaded / 1e6, { unit: 'M particle-steps/s' });
  figure(S, 'slowdown (1 - ratio of medians)', 100 * slowdown, { unit: '%', target: '< 10 %', ok: slowdown < 0.10 });
  figure(S, 'wall/cpu of the run thread, 0 vs 50 clients', `${waitBase.toFixed(3)} vs ${waitLoaded.toFixed(3)}`,
         { target: 'ratio < 1.10', ok: waitLoaded / waitBase < 1.10 });
  figure(S, 'pairs measured', PAIRS);
  figure(S, 'server RSS max, 0 clients', rssBase, { unit: 'MiB' });
  figure(S, `server RSS max, ${CLIENTS} clients`, rssLoaded, { unit: 'MiB', target: `< ${rssLimit.toFixed(0)} MiB (unwatched + 16 MiB queue cap + ${CLIENTS} x 0.25 MiB)`, ok: rssLoaded < rssLimit });
  figure(S, 'RSS growth, last loaded run over first', loaded.at(-1).rssMax - loaded[0].rssMax, { unit: 'MiB' });

  check(`${CLIENTS - 1} reading clients saw every run to 'completed' with frames and a normal close`,
        loaded.every((r) => r.readers.every((g) => g.status.at(-1)?.status === 'completed' && g.frames.length > 0 && g.closeCode === 1000)));
  check(`server memory bounded: max RSS ${rssLoaded.toFixed(1)} MiB < ${rssLimit.toFixed(1)} MiB`, rssLoaded < rssLimit);
  const health = await getJson(`${server.base}/api/health`);
  check('server healthy afterwards', health.status === 'ok', JSON.stringify(health));
} catch (e) {
  check('websocket load ran', false, e.stack);
} finally {
  const code = await server.stop('SIGTERM');
  check('server stops cleanly', code === 0, `exit ${code}`);
  finish();
}
