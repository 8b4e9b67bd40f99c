// The dashboard's Resume button: a run the server stopped at its wall-time limit (a clean
// stop, with a checkpoint) shows "Resume run"; clicking it continues the run from where it
// stopped (the server says at which step; the stored series grows from the same first rows), and
// the button is gone while the run is live. No console errors.
import { check, runBrowserTest, waitUntil, watchConsole } from './harness.mjs';

// Three discs on two threads: estimated at about 1.8 s, it runs some 30 times longer (the
// pool's synchronisation at every step), so a 2 s limit always stops it.
const OVERTIME = {
  name: 'overtime',
  particles: [
    { shape: 'disc', radius: 0.002, position: [0, 0.003] },
    { shape: 'disc', radius: 0.002, position: [0.0041, 0.003] },
    { shape: 'disc', radius: 0.002, position: [0.002, 0.008] },
  ],
  walls: [{ point: [0, 0], normal: [0, 1] }],
  gravity: [0, -9.81],
  solver: { threads: 2 },
  stages: [{ type: 'free', duration: 50 }],
  output: { sample_interval: 0.002 },
};

await runBrowserTest(['--max-run-seconds', '2'], async ({ server, browser }) => {
  const { base } = server;
  const json = async (path, init) => (await fetch(`${base}${path}`, init)).json();
  const { id } = await json('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(OVERTIME) });
  const stopped = await waitUntil(async () => {
    const run = await json(`/api/runs/${id}`);
    return run.status === 'failed' ? run : null;
  }, 60);
  check('the run stops at the wall-time limit, failed and resumable', stopped?.resumable === true, JSON.stringify(stopped));
  const rowsAtStop = (await json(`/api/runs/${id}/series`)).rows;

  const page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  await page.goto(`${base}/#/run/${id}`);
  const button = page.getByRole('button', { name: 'Resume run' });
  await button.waitFor({ state: 'visible' });
  check('the run view offers Resume run', true);
  check('and no Cancel run', !(await page.getByRole('button', { name: 'Cancel run' }).isVisible()));
  await button.click();
  const live = await waitUntil(async () => ['queued', 'running'].includes(
    await page.locator('.run-header .status').getAttribute('data-status')), 30);
  check('clicking it makes the run live again', Boolean(live));
  check('the button is hidden while it runs', !(await button.isVisible()));
  const stoppedAgain = await waitUntil(async () => {
    const run = await json(`/api/runs/${id}`);
    return run.status === 'failed' ? run : null;
  }, 60);
  check('the resumed run went on from its checkpoint, at the step where it stopped',
    server.log().includes(`run ${id} resumes at step ${stopped.steps} `), server.log());
  check('and further', stoppedAgain && stoppedAgain.steps > stopped.steps, `${stoppedAgain?.steps} vs ${stopped?.steps} steps`);
  const rows = (await json(`/api/runs/${id}/series`)).rows;
  check('its series grew and keeps the rows stored before the stop',
    rows.length > rowsAtStop.length && JSON.stringify(rows.slice(0, rowsAtStop.length)) === JSON.stringify(rowsAtStop),
    `${rowsAtStop.length} -> ${rows.length} rows`);
  check('no console errors, page exceptions or failed requests', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
