// Shared by the server's node tests: start the real server on a free loopback port with a
// throw-away database, talk to it with fetch and `ws`, decode frames, count checks.
import { spawn } from 'node:child_process';
import { mkdirSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';

const require = createRequire(join(process.env.GRAINLAB_WEB ?? 'web', 'package.json'));
export const WebSocket = require('ws');

export const TMP = join(process.env.GRAINLAB_TEST_TMP ?? '/tmp', `node-${process.pid}`);
mkdirSync(TMP, { recursive: true });
process.on('exit', () => rmSync(TMP, { recursive: true, force: true }));

let passed = 0;
let failed = 0;
export function check(what, ok, detail = '') {
  if (ok) { passed++; console.log(`ok   - ${what}`); } else { failed++; console.log(`FAIL - ${what} ${detail}`); }
}
export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exitCode = failed === 0 ? 0 : 1;
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** Starts the server; resolves to { base, wsBase, stop(signal) }. */
export async function startServer(args = []) {
  const db = join(TMP, `db-${Date.now()}`, 'grainlab.db');
  const proc = spawn(process.env.GRAINLAB_SERVER, ['--host', '127.0.0.1', '--port', '0', '--db', db, ...args],
    { stdio: ['ignore', 'ignore', 'pipe'] });
  let log = '';
  const port = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`server did not start: ${log}`)), 20000);
    proc.stderr.on('data', (d) => {
      log += d;
      const m = /listening on http:\/\/127\.0\.0\.1:(\d+)/.exec(log);
      if (m) { clearTimeout(timer); resolve(Number(m[1])); }
    });
    proc.on('exit', (code) => reject(new Error(`server exited ${code}: ${log}`)));
  });
  // A server that exits before the test stops it crashed (or quit): that fails the test, even
  // if nothing the test checks afterwards notices. Killed by a signal, node gives a null code
  // and the signal's name: report the name.
  let stopping = false;
  let crashed = false;
  const exited = new Promise((r) => proc.on('exit', (code, signal) => {
    if (!stopping) {
      crashed = true;
      check('the server runs until the test stops it', false, `(it exited by itself with ${code ?? signal}) ${log}`);
      process.exitCode = 1;
    }
    r(code ?? signal);
  }));
  process.on('exit', () => proc.kill('SIGKILL'));
  return {
    pid: proc.pid,
    base: `http://127.0.0.1:${port}`,
    wsBase: `ws://127.0.0.1:${port}`,
    log: () => log,
    // Resolves to the exit code (or signal); asked to stop with SIGTERM, the server must exit 0.
    stop: async (signal = 'SIGTERM') => {
      stopping = true;
      proc.kill(signal);
      const code = await exited;
      if (signal === 'SIGTERM' && code !== 0 && !crashed) check('the server stops cleanly on SIGTERM', false, `(exit ${code}) ${log}`);
      return code;
    },
  };
}

export async function getJson(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: ${r.status} ${await r.text()}`);
  return r.json();
}

export async function postJson(url, body) {
  const r = await fetch(url, { method: 'POST', body: JSON.stringify(body), headers: { 'content-type': 'application/json' } });
  return { status: r.status, body: await r.json() };
}

/** Polls the run until its status is `want` (or any terminal one); at most `seconds`. */
export async function waitFor(base, id, want, seconds = 60) {
  let run;
  for (let i = 0; i < seconds * 20; i++) {
    run = await getJson(`${base}/api/runs/${id}`);
    if (run.status === want) return run;
    if (['completed', 'failed', 'cancelled', 'interrupted'].includes(run.status) && run.status !== want) break;
    await sleep(50);
  }
  throw new Error(`run ${id} is ${run?.status}, not ${want}: ${JSON.stringify(run)}`);
}

/** Decodes a binary frame (docs/stream-protocol.md, version 1). */
export function decodeFrame(buffer) {
  const b = Buffer.isBuffer(buffer) ? buffer : Buffer.from(buffer);
  const magic = b.toString('latin1', 0, 4);
  const version = b.readUInt16LE(4);
  const headerBytes = b.readUInt16LE(6);
  const step = Number(b.readBigInt64LE(8));
  const time = b.readDoubleLE(16);
  const particles = b.readUInt32LE(24);
  const contacts = b.readUInt32LE(28);
  const maxMeanForce = b.readFloatLE(32);
  const maxContactForce = b.readFloatLE(36);
  const expected = headerBytes + 16 * particles + 12 * contacts;
  const p = (k, f) => b.readFloatLE(headerBytes + 16 * k + 4 * f);
  const c = headerBytes + 16 * particles;
  const pairs = [];
  for (let k = 0; k < contacts; k++)
    pairs.push([b.readUInt32LE(c + 12 * k), b.readUInt32LE(c + 12 * k + 4), b.readFloatLE(c + 12 * k + 8)]);
  return { magic, version, headerBytes, step, time, particles, contacts, maxMeanForce, maxContactForce,
           size: b.length, sizeOk: b.length === expected, x0: particles ? p(0, 0) : NaN, pairs };
}

/**
 * Watches a run's stream; resolves when the server closes it (after the terminal status) with
 * every message by kind. `paused` opens the connection and then never reads from it.
 */
export function watch(wsBase, id, { paused = false, light = false, timeoutMs = 120000 } = {}) {
  const ws = new WebSocket(`${wsBase}/api/runs/${id}/stream`);
  const got = { shapes: [], status: [], sample: [], histogram: [], frames: [], order: [], firstAt: {}, openedAt: 0 };
  const done = new Promise((resolve, reject) => {
    const timer = setTimeout(() => { ws.terminate(); reject(new Error(`stream ${id} did not end`)); }, timeoutMs);
    ws.on('open', () => {
      got.openedAt = Date.now();
      if (paused) ws._socket.pause();  // a client that never reads: the server must not care
    });
    ws.on('message', (data, isBinary) => {
      // A light watcher parses only status messages: fifty of them share one node process.
      const text = isBinary ? null : data.toString();
      const message = isBinary || (light && !text.includes('"type":"status"')) ? null : JSON.parse(text);
      const kind = isBinary ? 'frame' : message?.type ?? /"type":"(\w+)"/.exec(text)[1];
      got.firstAt[kind] ??= Date.now();
      got.order.push(kind);
      if (isBinary) got.frames.push(light ? { size: data.length } : decodeFrame(data));
      else if (light && kind !== 'status') got[kind].push(null);
      else got[kind].push(message);
    });
    ws.on('close', (code) => { clearTimeout(timer); got.closeCode = code; resolve(got); });
    ws.on('error', (e) => { clearTimeout(timer); reject(e); });
  });
  return { ws, done, got };
}
