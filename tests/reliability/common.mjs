// Shared by the reliability scripts (scripts/reliability, ctest label `reliability`): start
// `grainlab serve` itself (the program people run, not the test server) on a free loopback
// port with a throw-away data directory, sample its memory, report figures.
//
// Figures go to stdout as lines `figure {json}` ({section, name, value, unit, target, ok});
// scripts/reliability collects them into its table and docs/reliability.md's markdown.
// Pass/fail checks print `ok   - ...` / `FAIL - ...` and set the exit code (harness.mjs).
import { spawn } from 'node:child_process';
import { mkdirSync, readFileSync, readdirSync } from 'node:fs';
import http from 'node:http';
import { join } from 'node:path';

export { check, finish, getJson, postJson, sleep, TMP, waitFor, watch, WebSocket } from '../server/harness.mjs';
import { TMP } from '../server/harness.mjs';

export const CLI = process.env.GRAINLAB_CLI ?? 'build/grainlab';

export const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

/** One measured figure: printed for a person and as a machine-readable line. */
export function figure(section, name, value, { unit = '', target = '', ok = null, digits = 3 } = {}) {
  const shown = typeof value === 'number' ? Number(value.toPrecision(digits)) : value;
  console.log(`figure ${JSON.stringify({ section, name, value: shown, unit, target, ok })}`);
}

/**
 * Starts `grainlab serve` with its database in `dataDir` (default: a fresh one under TMP).
 * Resolves to { pid, port, base, wsBase, log(), stop(signal) }.
 */
export async function startServer({ args = [], dataDir, prefix = [] } = {}) {
  const dir = dataDir ?? join(TMP, `data-${Date.now()}-${Math.random().toString(36).slice(2, 6)}`);
  mkdirSync(dir, { recursive: true });
  const db = join(dir, 'grainlab.db');
  const command = [...prefix, CLI, 'serve', '--host', '127.0.0.1', '--port', '0', '--db', db,
                   '--web', process.env.GRAINLAB_WEB ?? 'web', ...args];
  const proc = spawn(command[0], command.slice(1), { stdio: ['ignore', 'ignore', 'pipe'] });
  let log = '';
  const port = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`server did not start: ${log}`)), 20000);
    proc.stderr.on('data', (d) => {
      if (log.length < 1 << 20) log += d;  // an accept loop that logs without end must not fill us
      const m = /listening on http:\/\/127\.0\.0\.1:(\d+)/.exec(log);
      if (m) { clearTimeout(timer); resolve(Number(m[1])); }
    });
    proc.on('exit', (code) => reject(new Error(`server exited ${code}: ${log}`)));
  });
  const exited = new Promise((r) => proc.on('exit', (code, signal) => r(code ?? signal)));
  process.on('exit', () => proc.kill('SIGKILL'));
  return {
    pid: proc.pid,
    port,
    db,
    dataDir: dir,
    base: `http://127.0.0.1:${port}`,
    wsBase: `ws://127.0.0.1:${port}`,
    log: () => log,
    stop: async (signal = 'SIGTERM') => { proc.kill(signal); return exited; },
  };
}

/** The process's resident memory, MiB (VmRSS in /proc/PID/status). */
export function rssMiB(pid) {
  const m = /VmRSS:\s+(\d+) kB/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
  return m ? Number(m[1]) / 1024 : NaN;
}

/** Samples rssMiB(pid) every `ms` until stop(); stop() resolves to { max, samples }. */
export function sampleRss(pid, ms = 100) {
  const samples = [];
  const take = () => { try { samples.push(rssMiB(pid)); } catch { /* exited */ } };
  take();
  const timer = setInterval(take, ms);
  return { stop: () => { clearInterval(timer); take(); return { max: Math.max(...samples), samples }; } };
}

/** Open file descriptors of a process, and its soft limit on them. */
export function openFiles(pid) {
  const count = readdirSync(`/proc/${pid}/fd`).length;
  const m = /Max open files\s+(\d+|unlimited)/.exec(readFileSync(`/proc/${pid}/limits`, 'utf8'));
  return { count, limit: m ? Number(m[1]) || Infinity : NaN };
}

/** circular-quick with a slower shearing stage: long enough to measure its speed. */
export async function longScene(base, strainRate = Number(process.env.GRAINLAB_RELIABILITY_STRAIN_RATE ?? 0.1)) {
  const scene = await (await fetch(`${base}/api/presets/circular-quick`)).json();
  const shearing = scene.stages.find((s) => s.type === 'biaxial');
  shearing.strain_rate = strainRate;
  scene.name = 'reliability-load';
  return scene;
}

/** A run's engine speed from GET /api/runs/{id}: particle-steps per second of wall time. */
export const particleStepsPerSecond = (run) => (run.steps * run.particles) / run.wall_seconds;

/**
 * GET `url` once on a connection of its own (as a new client would: fetch would reuse a
 * kept-alive one) and returns its latency in ms; throws on a non-2xx answer or after
 * `timeoutMs`.
 */
export function timedGet(url, timeoutMs = 10000) {
  return new Promise((resolve, reject) => {
    const t0 = performance.now();
    const req = http.get(url, { agent: false, timeout: timeoutMs }, (res) => {
      res.resume();
      res.on('end', () => (res.statusCode < 300 ? resolve(performance.now() - t0) : reject(new Error(`${url}: ${res.statusCode}`))));
    });
    req.on('timeout', () => req.destroy(new Error(`${url}: no answer within ${timeoutMs} ms`)));
    req.on('error', reject);
  });
}
