// REST load: wrk with 200 connections on GET /api/runs for GRAINLAB_REST_SECONDS (default 10)
// while the list holds GRAINLAB_REST_RUNS runs (default 50, tiny scenes run to completion).
// Latency percentiles, requests per second, errors (non-2xx answers and socket errors):
// target 0.
import { spawn } from 'node:child_process';

import { check, figure, finish, getJson, postJson, startServer, waitFor } from './common.mjs';

const RUNS = Number(process.env.GRAINLAB_REST_RUNS ?? 50);
const SECONDS = Number(process.env.GRAINLAB_REST_SECONDS ?? 10);
const CONNECTIONS = Number(process.env.GRAINLAB_REST_CONNECTIONS ?? 200);
const TINY = { name: 'tiny', particles: [{ shape: 'disc', radius: 0.002, position: [0, 0] }],
               stages: [{ type: 'free', duration: 0.001 }] };

// wrk prints durations as "812.00us", "3.41ms", "1.02s".
function ms(text) {
  const m = /^([\d.]+)(us|ms|s|m)$/.exec(text);
  if (!m) return NaN;
  return Number(m[1]) * { us: 1e-3, ms: 1, s: 1e3, m: 60e3 }[m[2]];
}

function wrk(url) {
  return new Promise((resolve, reject) => {
    const p = spawn('wrk', ['-t2', `-c${CONNECTIONS}`, `-d${SECONDS}s`, '--timeout', '10s', '--latency', url]);
    let out = '';
    p.stdout.on('data', (d) => { out += d; });
    p.stderr.on('data', (d) => { out += d; });
    p.on('error', reject);
    p.on('exit', (code) => (code === 0 ? resolve(out) : reject(new Error(`wrk exited ${code}: ${out}`))));
  });
}

const server = await startServer();
try {
  let last;
  for (let k = 0; k < RUNS; k++) last = (await postJson(`${server.base}/api/runs`, { ...TINY, name: `tiny-${k}` })).body.id;
  await waitFor(server.base, last, 'completed', 120);
  const listed = (await getJson(`${server.base}/api/runs`)).runs;
  const bytes = JSON.stringify({ runs: listed }).length;
  check(`${RUNS} runs stored and listed`, listed.length === RUNS && listed.every((r) => r.status === 'completed'));

  const out = await wrk(`${server.base}/api/runs`);
  console.log(out.replace(/^/gm, '# '));
  const percentile = (p) => ms(new RegExp(`^\\s+${p}%\\s+(\\S+)`, 'm').exec(out)?.[1] ?? '');
  const requests = Number(/(\d+) requests in/.exec(out)?.[1]);
  const perSecond = Number(/Requests\/sec:\s+([\d.]+)/.exec(out)?.[1]);
  const socket = /Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)/.exec(out);
  const socketErrors = socket ? socket.slice(1).reduce((n, x) => n + Number(x), 0) : 0;
  const non2xx = Number(/Non-2xx or 3xx responses: (\d+)/.exec(out)?.[1] ?? 0);

  const S = 'REST load';
  figure(S, `wrk -t2 -c${CONNECTIONS} -d${SECONDS}s GET /api/runs (${RUNS} runs, ${(bytes / 1024).toFixed(1)} KiB)`, requests, { unit: 'requests' });
  figure(S, 'requests per second', perSecond, { unit: '/s' });
  for (const p of [50, 90, 99]) figure(S, `latency p${p}`, percentile(p), { unit: 'ms' });
  figure(S, 'non-2xx answers', non2xx, { target: '0', ok: non2xx === 0 });
  figure(S, 'socket errors (connect, read, write, timeout)', socket ? socket.slice(1).join(', ') : '0, 0, 0, 0',
         { target: '0', ok: socketErrors === 0 });
  check('wrk made requests', requests > 0);
  check(`no non-2xx answers (${non2xx})`, non2xx === 0);
  check(`no socket errors (${socketErrors})`, socketErrors === 0);
  const health = await getJson(`${server.base}/api/health`);
  check('server healthy afterwards', health.status === 'ok');
} catch (e) {
  check('REST load ran', false, e.stack);
} finally {
  const code = await server.stop('SIGTERM');
  check('server stops cleanly', code === 0, `exit ${code}`);
  finish();
}
