// Shared by the browser tests: the real `grainlab serve` on a free loopback port with a
// throw-away database, Debian's Chromium driven by playwright-core (never a downloaded
// browser), console-error capture, screenshots, and bounded waits. Paths come from ctest's
// environment (tests/web/CMakeLists.txt) with defaults for running by hand from the repo root.
import { spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
export const CLI = process.env.GRAINLAB_CLI ?? join(repo, 'build/grainlab');
export const WEB = process.env.GRAINLAB_WEB ?? join(repo, 'web');
export const OUTPUT = process.env.GRAINLAB_TEST_OUTPUT ?? join(repo, 'build/test-output/web');
export const CHROMIUM = process.env.GRAINLAB_CHROMIUM ?? '/usr/bin/chromium';
mkdirSync(OUTPUT, { recursive: true });

const require = createRequire(join(WEB, 'package.json'));
const { chromium } = require('playwright-core');

// ---- checks, counted and printed as "N passed, N failed" for ctest's log ----
let passed = 0;
let failed = 0;
export function check(what, ok, detail = '') {
  if (ok) {
    passed++;
    console.log(`ok   - ${what}${detail ? ` (${detail})` : ''}`);
  } else {
    failed++;
    console.log(`FAIL - ${what}${detail ? ` (${detail})` : ''}`);
  }
  return ok;
}
export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  return failed === 0 ? 0 : 1;
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** Polls `probe` (async, truthy when done) every 100 ms for at most `seconds`; returns its last value. */
export async function waitUntil(probe, seconds) {
  const deadline = Date.now() + seconds * 1000;
  let value;
  do {
    value = await probe();
    if (value) return value;
    await sleep(100);
  } while (Date.now() < deadline);
  return value;
}

// ---- the server ----
/** Starts `grainlab serve` (with `extraArgs`); resolves to {base, stop()}. */
export async function startServer(extraArgs = []) {
  const scratch = mkdtempSync(join(tmpdir(), 'grainlab-web-test-'));
  const server = spawn(CLI, ['serve', '--host', '127.0.0.1', '--port', '0', '--db', join(scratch, 'grainlab.db'), '--web', WEB,
    ...extraArgs],
    { stdio: ['ignore', 'ignore', 'pipe'] });
  let log = '';
  // Killed by a signal, node gives a null code and the signal's name: report the name.
  const exited = new Promise((r) => server.on('exit', (code, signal) => r(code ?? signal)));
  const port = await new Promise((resolvePort, reject) => {
    const timer = setTimeout(() => reject(new Error(`the server did not start in 30 s: ${log}`)), 30000);
    server.stderr.on('data', (chunk) => {
      log += chunk;
      const match = /listening on http:\/\/127\.0\.0\.1:(\d+)/.exec(log);
      if (match) {
        clearTimeout(timer);
        resolvePort(Number(match[1]));
      }
    });
    server.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`the server exited (${code}) before listening: ${log}`));
    });
  });
  process.on('exit', () => server.kill('SIGKILL'));
  return {
    base: `http://127.0.0.1:${port}`,
    log: () => log,
    async stop() {
      server.kill('SIGTERM');
      const code = await Promise.race([exited, sleep(15000).then(() => 'timeout')]);
      if (code === 'timeout') {
        server.kill('SIGKILL');
        await exited;
      }
      rmSync(scratch, { recursive: true, force: true });
      return code;
    },
  };
}

// ---- the browser ----
export const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'];

export async function launchBrowser() {
  return chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true, timeout: 60000 });
}

/**
 * Records the page's console errors, uncaught exceptions and failed requests. `expect(text)`
 * allows one console error containing `text` (a 400 the test provokes on purpose).
 */
export function watchConsole(page) {
  const errors = [];
  const expected = [];
  page.on('console', (message) => {
    if (message.type() !== 'error') return;
    const text = `${message.text()} [${message.location()?.url ?? ''}]`;
    const allowed = expected.findIndex((e) => !e.used && text.includes(e.text));
    if (allowed >= 0) expected[allowed].used = true;
    else errors.push(`console: ${text}`);
  });
  page.on('pageerror', (error) => errors.push(`exception: ${error.message}`));
  page.on('requestfailed', (request) => {
    // Navigating away aborts what is still loading; that is not an error of the page.
    if (request.failure()?.errorText === 'net::ERR_ABORTED') return;
    errors.push(`request failed: ${request.url()} ${request.failure()?.errorText}`);
  });
  return {
    errors,
    expect(text) {
      expected.push({ text, used: false });
    },
  };
}

export async function screenshot(page, name) {
  const path = join(OUTPUT, `${name}.png`);
  await page.screenshot({ path, fullPage: true });
  console.log(`     screenshot ${path}`);
  return path;
}

/** Fraction of the canvas's pixels that differ from its top-left pixel (its background). */
export async function canvasInk(page, selector) {
  return page.$eval(selector, (canvas) => {
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(canvas, 0, 0);
    const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
    let differing = 0;
    for (let p = 0; p < data.length; p += 4) {
      if (Math.abs(data[p] - data[0]) + Math.abs(data[p + 1] - data[1]) + Math.abs(data[p + 2] - data[2]) > 24) differing++;
    }
    return differing / (data.length / 4);
  });
}

/** A small hash of the canvas's pixels: different when the drawing changed. */
export async function canvasHash(page, selector) {
  return page.$eval(selector, (canvas) => {
    const ctx = canvas.getContext('2d');
    const { data } = ctx.getImageData(0, 0, canvas.width, canvas.height);
    let hash = 2166136261;
    for (let p = 0; p < data.length; p += 7) hash = Math.imul(hash ^ data[p], 16777619) >>> 0;
    return hash;
  });
}

// ---- a whole browser test ----
/**
 * Starts `grainlab serve` (with `serverArgs`) and Chromium, runs `body({server, browser})`,
 * counts a throw as a failed check, always closes both, and exits with the checks' verdict.
 * The server must exit 0 when stopped: one that crashed during the test (or failed to stop
 * cleanly) fails it, with its log.
 */
export async function runBrowserTest(serverArgs, body) {
  const server = await startServer(serverArgs);
  const browser = await launchBrowser();
  try {
    await body({ server, browser });
  } catch (error) {
    check('the test runs to its end', false, error.stack);
  } finally {
    await browser.close();
    const code = await server.stop();
    if (!check('the server ran to the end of the test and stopped cleanly', code === 0, `exit ${code}`)) {
      console.log(server.log());
    }
  }
  process.exit(finish());
}
