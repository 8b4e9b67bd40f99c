// The runs list at the scale of a study: with 120 runs stored it shows page 1 of 3 with 50
// rows, asks the server only for the page it shows (never the whole list), pages on, and its
// filters and sort are the server's (the request carries them; the rows are what it answered).
// The state is kept in the address, so a reload shows the same page. An imported sweep's
// runs show their study, and the study filter lists them. No console errors.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { CLI, check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const RUNS = 120;
const SWEPT = 3;    // the first three come from a sweep, imported: the study "tinysweep"
const ALPHAS = 40;  // named alpha-K; the others beta-K
const TINY = (name) => ({ name, particles: [{ shape: 'disc', radius: 0.002, position: [0, 0] }],
                          stages: [{ type: 'free', duration: 0.001 }] });

const importRoot = mkdtempSync(join(tmpdir(), 'grainlab-runs-pages-'));
process.on('exit', () => rmSync(importRoot, { recursive: true, force: true }));
writeFileSync(join(importRoot, 'spec.json'), JSON.stringify({
  name: 'tinysweep', base: TINY('tiny'), vary: { 'stages.0.duration': [0.001, 0.002, 0.003] } }));
const swept = spawnSync(CLI, ['sweep', join(importRoot, 'spec.json'), '--out', join(importRoot, 'tinysweep'), '--jobs', '1'],
  { encoding: 'utf8' });
check('a three-run sweep to import', swept.status === 0, swept.stderr.slice(-300));

await runBrowserTest(['--max-queued', String(RUNS), '--import-root', importRoot], async ({ server, browser }) => {
  const { base } = server;
  const json = async (path, init) => (await fetch(`${base}${path}`, init)).json();
  const imported = await json('/api/sweeps/import', { method: 'POST', headers: { 'content-type': 'application/json' },
    body: JSON.stringify({ dir: join(importRoot, 'tinysweep') }) });
  check('the sweep is imported as runs 1 to 3', JSON.stringify(imported.ids) === '[1,2,3]', JSON.stringify(imported));
  for (let k = 0; k < RUNS - SWEPT; k++) {
    const name = k < ALPHAS ? `alpha-${k}` : `beta-${k}`;
    const response = await fetch(`${base}/api/runs`, { method: 'POST', headers: { 'content-type': 'application/json' },
      body: JSON.stringify(TINY(name)) });
    if (response.status !== 201) throw new Error(`POST ${name}: ${response.status} ${await response.text()}`);
  }
  const done = await waitUntil(async () => (await json('/api/runs?status=completed&limit=1')).total === RUNS, 120);
  check(`${RUNS} runs stored and completed`, Boolean(done));

  const page = await browser.newPage({ viewport: { width: 1300, height: 1000 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  const listRequests = [];
  page.on('request', (request) => {
    const url = new URL(request.url());
    if (url.pathname === '/api/runs' && request.method() === 'GET') listRequests.push(url.searchParams);
  });
  const rowCount = () => page.locator('table.runs tbody tr').count();
  const label = () => page.locator('.pager-label').textContent();
  const names = () => page.$$eval('table.runs tbody tr td:nth-child(3) a', (links) => links.map((a) => a.textContent));
  const ids = () => page.$$eval('table.runs tbody tr', (rows) => rows.map((r) => Number(r.dataset.runId)));

  await page.goto(`${base}/#/runs`);
  await waitUntil(async () => (await rowCount()) === 50, 30);
  check('page 1 shows 50 rows', (await rowCount()) === 50, `${await rowCount()} rows`);
  check('and says page 1 of 3 of 120 runs', /Page 1 of 3 · 120 runs/.test(await label()), await label());
  const firstIds = await ids();
  check('newest first: runs 120 down to 71', firstIds[0] === 120 && firstIds[49] === 71, `${firstIds[0]}..${firstIds[49]}`);
  check('the page asked the server for 50 runs from the first',
    listRequests.length > 0 && listRequests[0].get('limit') === '50' && (listRequests[0].get('offset') ?? '0') === '0',
    listRequests.map(String).join(' | '));
  await screenshot(page, 'runs-pages-1');

  await page.locator('.pager-next').click();
  await page.locator('.pager-next').click();
  await waitUntil(async () => /Page 3 of 3/.test(await label()) && (await rowCount()) === 20, 15);
  check('Next twice: page 3 of 3 holds the last 20 runs', (await rowCount()) === 20 && (await ids())[19] === 1,
    `${await label()}, ${await rowCount()} rows`);
  check('its request asked for offset 100', listRequests.some((q) => q.get('offset') === '100' && q.get('limit') === '50'));
  check('Next is disabled on the last page', await page.locator('.pager-next').isDisabled());

  // The name filter: the server narrows, the page shows its answer from page 1.
  const before = listRequests.length;
  await page.locator('.filter-name').fill('alpha');
  await waitUntil(async () => /Page 1 of 1 · 40 runs/.test(await label()) && (await rowCount()) === ALPHAS, 15);
  const filtered = await names();
  check('typing "alpha" shows the 40 alpha runs on one page', filtered.length === ALPHAS && filtered.every((n) => n.startsWith('alpha-')),
    `${await label()}; ${filtered.length} rows`);
  const asked = listRequests.slice(before).filter((q) => q.get('q') === 'alpha');
  check('the request carried the filter to the server (q=alpha, limit=50, from offset 0)',
    asked.length > 0 && asked.every((q) => q.get('limit') === '50' && (q.get('offset') ?? '0') === '0'),
    listRequests.slice(before).map(String).join(' | '));
  check('no request ever asked for the whole list', listRequests.every((q) => q.get('limit') === '50'));

  // Sorted by name on the server: alpha-0, alpha-1, alpha-10, ... (text order).
  await page.locator('th button.sort[data-sort="name"]').click();
  await waitUntil(async () => (await names())[0] === 'alpha-0' && (await names())[1] === 'alpha-1', 15);
  const byName = await names();
  check('the Name header sorts on the server, a to z', byName[0] === 'alpha-0' && byName[2] === 'alpha-10' &&
    listRequests.some((q) => q.get('sort') === 'name' && q.get('q') === 'alpha'), byName.slice(0, 4).join(','));

  await page.locator('.filter-status').selectOption('failed');
  await page.locator('.empty-state').filter({ hasText: 'No runs match these filters' }).waitFor({ state: 'visible' });
  check('status=failed narrows to nothing, said so', listRequests.some((q) => q.get('status') === 'failed' && q.get('q') === 'alpha'));
  await page.locator('.filter-status').selectOption('');

  await waitUntil(async () => (await rowCount()) === ALPHAS, 15);
  await page.reload();
  await waitUntil(async () => (await rowCount()) === ALPHAS, 30);
  check('a reload keeps the filter and the order (they live in the address)',
    (await page.locator('.filter-name').inputValue()) === 'alpha' && (await names())[0] === 'alpha-0', page.url());

  // A study: its runs carry a tag linking to the list of them, and the study filter asks the
  // server for them alone.
  await page.goto(`${base}/#/runs`);
  await waitUntil(async () => (await rowCount()) === 50, 30);
  await page.locator('.pager-next').click();
  await page.locator('.pager-next').click();
  const tag = page.locator('tr[data-run-id="1"] a.study-tag');
  await tag.waitFor({ state: 'visible' });
  check('an imported run shows its study', (await tag.textContent()) === 'tinysweep');
  const studyOption = await waitUntil(async () => (await page.locator('.filter-study option').allTextContents())
    .find((t) => t.startsWith('tinysweep')), 15);
  check('the study filter offers the study with its runs and status', studyOption === 'tinysweep (3 runs, completed)', studyOption);
  const beforeStudy = listRequests.length;
  await page.locator('.filter-study').selectOption('tinysweep');
  await waitUntil(async () => /Page 1 of 1 · 3 runs/.test(await label()), 15);
  check('choosing it lists its 3 runs, asked of the server',
    (await rowCount()) === SWEPT && listRequests.slice(beforeStudy).some((q) => q.get('study') === 'tinysweep'),
    `${await label()}; ${listRequests.slice(beforeStudy).map(String).join(' | ')}`);
  await screenshot(page, 'runs-pages-study');

  // Compare's picker: the 100 newest runs and a ticked older one, never the whole list.
  const beforeCompare = listRequests.length;
  await page.goto(`${base}/#/compare?ids=1`);
  await page.locator('.compare-picker input[data-run-id="1"]').waitFor({ state: 'attached' });
  const picked = await page.$$eval('.compare-picker input', (inputs) => inputs.map((i) => [Number(i.dataset.runId), i.checked]));
  check('compare offers the 100 newest runs and the ticked run 1, older than them',
    picked.length === 101 && picked.some(([id, on]) => id === 1 && on) && picked.filter(([, on]) => on).length === 1,
    `${picked.length} offered`);
  check('...asking the server for 100 runs', listRequests.slice(beforeCompare).every((q) => q.get('limit') === '100')
    && listRequests.length > beforeCompare);

  check('no console errors', consoleWatch.errors.length === 0, consoleWatch.errors.join('; '));
});
