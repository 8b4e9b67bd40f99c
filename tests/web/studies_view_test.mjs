// The Studies view: a 4-run quick sweep (circular-quick sheared to 5 % axial strain, friction
// 0.3 and 0.5, seeds 1 and 2) launched from the form, which shows the run count first and a
// refusal beside the row it names (with nothing stored); the list follows the study to its
// end by polling; the study's page shows one band per friction, each of 2 runs, and its mean
// of φ_mob at the last common strain is the mean of the runs' own series there, and of the
// series `grainlab sweep` writes for the same spec; the page computes none of it (the server's
// bands) and reads no run to draw it. The CSV download holds the same numbers.
// No console errors but the refusal provoked on purpose.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { CLI, canvasInk, check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const NAME = 'quick-friction';

await runBrowserTest([], async ({ server, browser }) => {
  const { base } = server;
  const json = async (path) => (await fetch(`${base}${path}`)).json();
  const page = await browser.newPage({ viewport: { width: 1300, height: 1100 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);

  await page.goto(`${base}/#/studies`);
  await waitUntil(async () => (await page.locator('#study-preset option').count()) > 0, 30);
  await page.locator('#study-preset').selectOption('circular-quick');
  await page.locator('#study-name').fill(NAME);
  const paths = page.locator('.study-path');
  const values = page.locator('.study-values');
  // A misspelt path first: refused by the server, shown on its row, nothing stored.
  await paths.nth(0).fill('material.frction');
  await values.nth(0).fill('0.3, 0.5');
  await page.locator('#study-seeds').fill('1, 2');
  consoleWatch.expect('400');
  await page.getByRole('button', { name: 'Launch study' }).click();
  const rowError = page.locator('.study-row .field-error').nth(0);
  await waitUntil(async () => /unknown key/.test(await rowError.textContent()), 15);
  check('a misspelt path is refused on its own row', /material\.frction: unknown key/.test(await rowError.textContent()),
    await rowError.textContent());
  check('...and nothing is stored', (await json('/api/studies')).studies.length === 0);

  await paths.nth(0).fill('material.friction');
  await page.getByRole('button', { name: 'Add a path' }).click();
  await paths.nth(1).fill('stages.2.target_axial_strain');
  await values.nth(1).fill('0.05');
  const count = await page.locator('.study-count').textContent();
  check('the form shows the run count before launching: 2 x 1 x 2 = 4', count === '4 runs', count);
  await page.getByRole('button', { name: 'Launch study' }).click();
  const row = page.locator(`tr[data-study="${NAME}"]`);
  await waitUntil(async () => (await row.count()) === 1, 15);
  check('the launched study is listed', (await row.count()) === 1);
  const finished = await waitUntil(async () => /completed/.test(await row.locator('.status').textContent()), 120);
  check('the list follows it to completed by itself (polling)', Boolean(finished), await row.textContent());
  check('...4 done of 4', /4 done · 0 running · 0 failed · 0 queued of 4/.test(await row.textContent()), await row.textContent());
  await screenshot(page, 'studies-list');

  // The study page draws the server's bands (GET /api/studies/NAME/bands): it reads no run.
  const runReads = [];
  page.on('request', (request) => {
    if (/\/api\/runs\/\d+(\/series)?(\?|$)/.test(new URL(request.url()).pathname)) runReads.push(request.url());
  });
  await row.getByRole('link', { name: NAME }).click();
  const bandRows = page.locator('table.study-bands tbody tr');
  await waitUntil(async () => (await bandRows.count()) === 2 && (await page.locator('.band-mean').first().textContent()) !== '–', 30);
  check('one band per friction', (await bandRows.count()) === 2, `${await bandRows.count()} rows`);
  const runsCells = await page.$$eval('td.band-runs', (cells) => cells.map((c) => c.textContent));
  check('...each the mean of 2 runs', runsCells.join(',') === '2,2', runsCells.join(','));

  // The mean at friction 0.3 from the runs' own series: φ_mob at the strain the table names,
  // each run interpolated linearly between its two samples around it.
  const shown = page.locator('tr[data-value="0.3"]');
  const strain = Number(await shown.locator('.band-strain').getAttribute('data-strain'));
  const mean = Number(await shown.locator('.band-mean').getAttribute('data-mean'));
  const study = await json(`/api/studies/${NAME}`);
  const ids = study.run_parameters.filter((r) => r.parameters['material.friction'] === 0.3).map((r) => r.id);
  // φ_mob at `strain` from one run's rows (columns named by `columns`).
  const phiAt = (columns, rows) => {
    const c = (name) => columns.indexOf(name);
    const shearing = rows.filter((r) => r[c('stage')] === 'shearing');
    const xs = shearing.map((r) => r[c('axial_strain')] * 100);
    const k = xs.findIndex((x) => x >= strain - 1e-9 * Math.abs(strain));
    const y = (row) => shearing[row][c('phi_mob_deg')];
    return xs[k] === strain || k === 0 ? y(k) : y(k - 1) + (strain - xs[k - 1]) / (xs[k] - xs[k - 1]) * (y(k) - y(k - 1));
  };
  const meanOf = (ys) => ys.reduce((a, b) => a + b, 0) / ys.length;
  const ys = [];
  for (const id of ids) {
    const series = await json(`/api/runs/${id}/series`);
    ys.push(phiAt(series.columns, series.rows));
  }
  const expected = meanOf(ys);
  check(`the table's mean of φ_mob at ${strain.toPrecision(4)} % (${mean.toPrecision(6)}°) is the runs' own (${expected.toPrecision(6)}°)`,
    ids.length === 2 && Math.abs(mean - expected) <= 1e-9 * Math.abs(expected), `runs ${ids}, values ${ys}`);

  // The same spec through grainlab sweep (about 2 s of CPU): the same runs, the same mean.
  const scratch = mkdtempSync(join(tmpdir(), 'grainlab-studies-view-'));
  try {
    writeFileSync(join(scratch, 'spec.json'), JSON.stringify(study.spec));
    const swept = spawnSync(CLI, ['sweep', join(scratch, 'spec.json'), '--out', join(scratch, 'out'), '--jobs', '1'], { encoding: 'utf8' });
    check('grainlab sweep runs the study\'s spec', swept.status === 0, swept.stderr.slice(-300));
    const sweptYs = study.run_parameters.filter((r) => r.parameters['material.friction'] === 0.3).map((r) => {
      const folder = r.name.slice(NAME.length + 1);  // the study's runs are named STUDY/<sweep run id>
      const [header, ...lines] = readFileSync(join(scratch, 'out', 'runs', folder, 'series.csv'), 'utf8').trim().split('\n');
      const columns = header.split(',');
      const rows = lines.map((line) => line.split(',').map((cell, k) => (columns[k] === 'stage' ? cell : Number(cell))));
      return phiAt(columns, rows);
    });
    check(`...whose series give the table's mean too (${meanOf(sweptYs).toPrecision(6)}°)`,
      sweptYs.length === 2 && Math.abs(meanOf(sweptYs) - mean) <= 1e-9 * Math.abs(mean), `values ${sweptYs}`);
  } finally {
    rmSync(scratch, { recursive: true, force: true });
  }
  check('the study page drew its bands without reading a run or its series', runReads.length === 0, runReads.join(' '));
  const ink = await canvasInk(page, '.study-chart canvas');
  check(`the ensemble chart is drawn (${(100 * ink).toFixed(1)} % of its pixels inked)`, ink > 0.01);
  check('the two frictions give different means', (await page.$$eval('.band-mean', (c) => new Set(c.map((x) => x.dataset.mean)).size)) === 2);

  const csv = await page.evaluate(async () => (await fetch(document.querySelector('.view-title ~ .panel a[download]').href)).text());
  const lines = csv.trim().split('\n');
  check('the CSV download has the strain and each friction\'s mean, band and n',
    lines[1].startsWith('axial_strain_percent,material.friction=0.3 mean,material.friction=0.3 low95'), lines[1]);
  const atStrain = lines.slice(2).map((l) => l.split(',')).find((cells) => Number(cells[0]) === strain);
  check('...with the table\'s mean at that strain', atStrain && Number(atStrain[1]) === mean, atStrain?.join(','));
  await screenshot(page, 'study-view');

  // Cancel from the list: three seeds of the full `circular` preset (tens of seconds each, so
  // the cancel lands while the first runs and the others wait on any machine; the quick
  // preset's runs took under a second, and a fast machine finished two before the click).
  await page.getByRole('link', { name: 'All studies' }).click();
  await waitUntil(async () => (await page.locator('#study-preset option').count()) > 0, 30);
  await page.locator('#study-preset').selectOption('circular');
  await page.locator('#study-name').fill('to-cancel');
  await page.locator('.study-row .study-remove').first().click();
  await page.locator('#study-seeds').fill('1, 2, 3');
  await page.getByRole('button', { name: 'Launch study' }).click();
  const cancelRow = page.locator('tr[data-study="to-cancel"]');
  await waitUntil(async () => (await cancelRow.count()) === 1 && /running/.test(await cancelRow.locator('.status').textContent()), 30);
  const left = cancelRow.locator('.time-left');
  check('a running study shows its time left in the list', (await left.count()) === 1
    && /^(about|at least) \d+ (s|min \d+ s|h \d+ min) left$/.test(await left.textContent()),
    (await left.count()) ? await left.textContent() : 'none');
  await cancelRow.getByRole('button', { name: 'Cancel' }).click();
  const cancelled = await waitUntil(async () => /cancelled/.test(await cancelRow.locator('.status').textContent()), 60);
  const after = await json('/api/studies/to-cancel');
  check('Cancel on the list cancels the study, shown there', Boolean(cancelled) && after.cancelled === true && after.status === 'cancelled',
    JSON.stringify(after.by_status));
  check('...its queued runs never ran', (after.by_status.cancelled ?? 0) >= 2, JSON.stringify(after.by_status));
  // Resume from the list: the cancelled study's runs queued again.
  await cancelRow.getByRole('button', { name: 'Resume' }).click();
  const resumed = await waitUntil(async () => /running|queued/.test(await cancelRow.locator('.status').textContent()), 30);
  const again = await json('/api/studies/to-cancel');
  check('Resume on the list queues the cancelled study again', Boolean(resumed) && again.cancelled === false
    && (again.by_status.running ?? 0) + (again.by_status.queued ?? 0) === 3, JSON.stringify(again.by_status));
  await cancelRow.getByRole('button', { name: 'Cancel' }).click();
  await waitUntil(async () => /cancelled/.test(await cancelRow.locator('.status').textContent()), 60);
  check('no console errors', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
