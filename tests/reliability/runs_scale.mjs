// The runs list at the scale a study reaches (scripts/reliability scale): a few real runs are
// simulated, then copied in SQLite (rows and whole series) to GRAINLAB_SCALE_RUNS runs
// (default 10,000) in 20 studies, and the server is started again on that database. Measured:
// GET /api/runs?limit=50 one request at a time (median, target <= 20 ms) and with filters,
// a deep page and the whole list for comparison; wrk with 50 connections on the page; the
// server's memory; and the dashboard's runs view first draw in Chromium (median of 5 loads,
// target <= 1 s). The copies carry no frames or histograms: the list never reads them.
import { spawn, spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { join, resolve } from 'node:path';

import { check, figure, finish, getJson, median, postJson, rssMiB, sampleRss, startServer, timedGet, waitFor } from './common.mjs';

const RUNS = Number(process.env.GRAINLAB_SCALE_RUNS ?? 10000);
const SECONDS = Number(process.env.GRAINLAB_SCALE_SECONDS ?? 10);
const CLIENTS = Number(process.env.GRAINLAB_SCALE_CLIENTS ?? 50);
const PRESETS = ['circular-quick', 'elongated-bedding-30-quick', 'elongated-random-quick'];
const WEB = resolve(process.env.GRAINLAB_WEB ?? 'web');
const S = 'runs list at scale';

const percentile = (xs, p) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(p * xs.length))];

// wrk prints durations as "812.00us", "3.41ms", "1.02s".
function ms(text) {
  const m = /^([\d.]+)(us|ms|s|m)$/.exec(text);
  return m ? Number(m[1]) * { us: 1e-3, ms: 1, s: 1e3, m: 60e3 }[m[2]] : NaN;
}

function wrk(url) {
  return new Promise((resolvePromise, reject) => {
    const p = spawn('wrk', ['-t2', `-c${CLIENTS}`, `-d${SECONDS}s`, '--timeout', '10s', '--latency', url]);
    let out = '';
    p.stdout.on('data', (d) => { out += d; });
    p.stderr.on('data', (d) => { out += d; });
    p.on('error', reject);
    p.on('exit', (code) => (code === 0 ? resolvePromise(out) : reject(new Error(`wrk exited ${code}: ${out}`))));
  });
}

// Copies of the real runs up to RUNS in all, each with its source's whole series; 1 in 20
// failed (with a reason), every 500 in a study of their own, named STUDY/NNNNN as a sweep
// import names them. Ids follow the copies' order: the database is fresh, nothing deleted.
function copyRuns(db, real) {
  const copies = RUNS - real;
  const sql = `
    BEGIN;
    WITH RECURSIVE n(k) AS (SELECT 1 UNION ALL SELECT k + 1 FROM n WHERE k < ${copies})
    INSERT INTO runs (name, preset, scene, status, error, stage, progress, particles, steps, created_at,
                      started_at, finished_at, wall_seconds, peak_phi_mob_deg, shapes, cpu_seconds,
                      estimated_seconds, warnings, study)
    SELECT 'scale-' || (k / 500) || '/' || printf('%05d', k), r.preset, r.scene,
           CASE WHEN k % 20 = 0 THEN 'failed' ELSE r.status END,
           CASE WHEN k % 20 = 0 THEN 'copied as failed to fill the list' ELSE r.error END,
           r.stage, r.progress, r.particles, r.steps, r.created_at + k, r.started_at + k, r.finished_at + k,
           r.wall_seconds, r.peak_phi_mob_deg, r.shapes, r.cpu_seconds, r.estimated_seconds, r.warnings,
           'scale-' || (k / 500)
    FROM n JOIN runs r ON r.id = 1 + (k % ${real}) ORDER BY k;
    INSERT INTO samples (run_id, seq, step, time, stage, vals)
    SELECT c.id, s.seq, s.step, s.time, s.stage, s.vals
    FROM runs c JOIN samples s ON s.run_id = 1 + ((c.id - ${real}) % ${real}) WHERE c.id > ${real};
    COMMIT;
    SELECT COUNT(*), (SELECT COUNT(*) FROM samples) FROM runs;`;
  const out = spawnSync('sqlite3', [db], { input: sql, encoding: 'utf8' });
  if (out.status !== 0) throw new Error(`sqlite3: ${out.stderr}`);
  return out.stdout.trim().split('|').map(Number);
}

async function firstDraws(base, loads = 5) {
  const require = createRequire(join(WEB, 'package.json'));
  const { chromium } = require('playwright-core');
  const browser = await chromium.launch({ executablePath: process.env.GRAINLAB_CHROMIUM ?? '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run'], headless: true });
  const times = [];
  try {
    for (let k = 0; k < loads; k++) {
      const page = await browser.newPage({ viewport: { width: 1300, height: 1000 } });
      await page.goto(`${base}/#/runs`);
      // From the start of navigation to the 50 rows in the table, by the page's own clock.
      const drawn = await page.waitForFunction(() => document.querySelectorAll('table.runs tbody tr').length === 50
        && performance.now(), null, { timeout: 30000, polling: 'raf' });
      times.push(await drawn.jsonValue());
      await page.close();
    }
  } finally {
    await browser.close();
  }
  return times;
}

const first = await startServer();
let server = null;
try {
  // ---- real runs ----
  const ids = [];
  for (const preset of PRESETS) ids.push((await postJson(`${first.base}/api/runs`, { preset })).body.id);
  for (const id of ids) await waitFor(first.base, id, 'completed', 900);
  const real = await getJson(`${first.base}/api/runs`);
  check(`${PRESETS.length} real runs completed`, real.runs.length === PRESETS.length && real.runs.every((r) => r.status === 'completed'));
  check('stopped cleanly before the copy', (await first.stop('SIGTERM')) === 0);

  // ---- copies ----
  const t0 = performance.now();
  const [runs, samples] = copyRuns(first.db, PRESETS.length);
  figure(S, 'runs in the database (3 real, the rest copies with their series)', runs);
  figure(S, 'series rows stored', samples);
  figure(S, 'time to copy them (sqlite3)', (performance.now() - t0) / 1000, { unit: 's' });
  check(`${RUNS} runs stored`, runs === RUNS);

  server = await startServer({ dataDir: first.dataDir });
  const base = server.base;
  figure(S, 'server RSS after start', rssMiB(server.pid), { unit: 'MiB' });

  // ---- one request at a time ----
  const page = `${base}/api/runs?limit=50`;
  const body = await getJson(page);
  check('a page holds 50 runs and counts them all', body.runs.length === 50 && body.total === RUNS, `${body.runs.length} of ${body.total}`);
  figure(S, 'GET /api/runs?limit=50: answer size', JSON.stringify(body).length / 1024, { unit: 'KiB' });
  const timed = async (url, n) => {
    for (let k = 0; k < 5; k++) await timedGet(url);  // warm: statements prepared, pages cached
    const xs = [];
    for (let k = 0; k < n; k++) xs.push(await timedGet(url));
    return xs;
  };
  const pageTimes = await timed(page, 200);
  const pageMedian = median(pageTimes);
  figure(S, 'GET /api/runs?limit=50, one at a time: median (200 requests)', pageMedian,
         { unit: 'ms', target: '<= 20 ms', ok: pageMedian <= 20 });
  figure(S, 'the same: p90', percentile(pageTimes, 0.9), { unit: 'ms' });
  for (const [what, query] of [[`the last page (offset ${RUNS - 50})`, `limit=50&offset=${RUNS - 50}`],
                               ['status=failed', 'limit=50&status=failed'],
                               ['study=scale-7', 'limit=50&study=scale-7'],
                               ['q=00042 (a name substring: no index, the count reads every name)', 'limit=50&q=00042'],
                               ['sort=peak_phi_mob_deg&order=desc', 'limit=50&sort=peak_phi_mob_deg&order=desc']]) {
    figure(S, `GET /api/runs?limit=50, ${what}: median (50)`, median(await timed(`${base}/api/runs?${query}`, 50)), { unit: 'ms' });
  }

  // ---- 50 clients ----
  const rss = sampleRss(server.pid);
  const out = await wrk(page);
  const rssDuring = rss.stop();
  console.log(out.replace(/^/gm, '# '));
  const requests = Number(/(\d+) requests in/.exec(out)?.[1]);
  const perSecond = Number(/Requests\/sec:\s+([\d.]+)/.exec(out)?.[1]);
  const socket = /Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)/.exec(out);
  const errors = (socket ? socket.slice(1).reduce((n, x) => n + Number(x), 0) : 0) + Number(/Non-2xx or 3xx responses: (\d+)/.exec(out)?.[1] ?? 0);
  const wrkPercentile = (p) => ms(new RegExp(`^\\s+${p}%\\s+(\\S+)`, 'm').exec(out)?.[1] ?? '');
  figure(S, `wrk -t2 -c${CLIENTS} -d${SECONDS}s GET /api/runs?limit=50: requests per second`, perSecond, { unit: '/s' });
  figure(S, 'the same: latency p50', wrkPercentile(50), { unit: 'ms' });
  figure(S, 'the same: latency p99', wrkPercentile(99), { unit: 'ms' });
  figure(S, 'the same: errors (non-2xx and socket)', errors, { target: '0', ok: errors === 0 });
  figure(S, 'server RSS max under the 50 clients', rssDuring.max, { unit: 'MiB' });
  check('wrk made requests without errors', requests > 0 && errors === 0);

  // ---- the dashboard ----
  const draws = await firstDraws(base);
  const drawMedian = median(draws);
  figure(S, 'dashboard runs view, first draw of its 50 rows in Chromium: median of 5 loads', drawMedian,
         { unit: 'ms', target: '<= 1000 ms', ok: drawMedian <= 1000 });
  figure(S, 'the same: slowest load', Math.max(...draws), { unit: 'ms' });

  // ---- the whole list, as a client without limit still gets it ----
  const whole = await timed(`${base}/api/runs`, 3);
  const wholeBody = await getJson(`${base}/api/runs`);
  figure(S, `GET /api/runs without limit (every run, ${(JSON.stringify(wholeBody).length / 1048576).toFixed(1)} MiB): median (3)`,
         median(whole), { unit: 'ms' });
  figure(S, 'server RSS after the whole list was asked for', rssMiB(server.pid), { unit: 'MiB' });
  check('the whole list holds every run', wholeBody.runs.length === RUNS);
} catch (e) {
  check('the runs-list scale measurement ran', false, e.stack);
} finally {
  if (server) check('server stops cleanly', (await server.stop('SIGTERM')) === 0);
  finish();
}
