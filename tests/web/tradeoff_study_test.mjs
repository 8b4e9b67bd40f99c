// A speed-accuracy trade-off launched from the Studies view (quick plan, 2 seeds, circular-quick,
// the timestep axis: 6 runs), after an unknown axis is refused naming tradeoff.axes with nothing
// stored. Once its runs have ended its page draws the Pareto plot: one marker per distinct run,
// each at the cost and mean angle difference of the server's table (GET .../tradeoff), its x
// the cpu_s that tradeoff.csv gives every setting of that run, its interval the table's; the
// front's markers filled. The CSV download is the server's tradeoff.csv (which
// tests/server/study_tradeoff_test.sh compares with grainlab tradeoff's). No console errors but
// the refusal provoked on purpose.
import { check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const NAME = 'tradeoff-from-form';

/** RFC 4180 rows of a CSV text (quoted cells may hold commas). */
function csvRows(text) {
  const rows = [];
  let row = [], cell = '', quoted = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { cell += '"'; i++; } else if (c === '"') quoted = false; else cell += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { row.push(cell); cell = ''; } else if (c === '\n') { row.push(cell); rows.push(row); row = []; cell = ''; } else cell += c;
  }
  if (cell || row.length) { row.push(cell); rows.push(row); }
  return rows;
}

await runBrowserTest(['--max-concurrent', '2'], async ({ server, browser }) => {
  const { base } = server;
  const json = async (path) => (await fetch(`${base}${path}`)).json();
  const page = await browser.newPage({ viewport: { width: 1300, height: 1400 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  await page.goto(`${base}/#/studies`);

  await page.locator('#tradeoff-name').fill(NAME);
  await page.locator('#tradeoff-seeds').fill('2');
  await page.locator('#tradeoff-presets').fill('circular-quick');
  await page.locator('#tradeoff-axes').fill('timestep');
  consoleWatch.expect('400');
  await page.getByRole('button', { name: 'Launch the trade-off' }).click();
  const formError = page.locator('.tradeoff-form .form-error');
  await waitUntil(async () => await formError.isVisible(), 15);
  check('an unknown axis is refused, naming tradeoff.axes', /^tradeoff\.axes: unknown axis/.test(await formError.textContent()), await formError.textContent());
  check('...and nothing is stored', (await json('/api/studies')).studies.length === 0);

  await page.locator('#tradeoff-axes').fill('timestep_safety');
  await page.getByRole('button', { name: 'Launch the trade-off' }).click();
  const row = page.locator(`tr[data-study="${NAME}"]`);
  await waitUntil(async () => (await row.count()) === 1, 15);
  const launched = await json(`/api/studies/${NAME}`);
  check('the trade-off starts with its two reference runs (seeds 1 and 2)', launched.runs === 2
    && launched.run_parameters.every((r) => r.parameters.setting.startsWith('reference ')), JSON.stringify(launched.run_parameters));

  await row.getByRole('link', { name: NAME }).click();
  const dots = page.locator('.study-tradeoff svg.pareto-plot circle');
  const drawn = await waitUntil(async () => (await dots.count()) > 0, 240);
  check('its page draws the Pareto plot once its runs have ended', Boolean(drawn), await page.locator('.study-tradeoff').textContent());
  const study = await json(`/api/studies/${NAME}`);
  check('...all six runs completed', study.runs === 6 && study.by_status.completed === 6, JSON.stringify(study.by_status));

  const table = await json(`/api/studies/${NAME}/tradeoff`);
  const points = table.panels[0].points;
  const shown = await dots.evaluateAll((nodes) => nodes.map((n) => ({
    cpu: Number(n.dataset.cpuS), error: Number(n.dataset.errorDeg), label: n.dataset.label, front: n.dataset.onFront === 'true',
  })));
  check('one marker per distinct run: reference, 0.2, 0.4', shown.map((p) => p.label).join(',') === 'reference,0.2,0.4',
    shown.map((p) => p.label).join(','));
  check('...each at the table\'s cost and mean angle difference, the front\'s filled',
    shown.every((p, k) => p.cpu === points[k].cpu_s && p.error === points[k].error_deg && p.front === points[k].on_front),
    JSON.stringify({ shown, points }));
  const bars = await page.locator('.study-tradeoff svg.pareto-plot g.pareto-point line').count();
  check('...with an interval bar on every setting but the reference', bars === 2, `${bars} bars`);

  // The markers' costs are tradeoff.csv's: every setting row of a run carries that run's cpu_s
  // (10 significant digits).
  const csv = csvRows(table.csv);
  const header = csv[0];
  const at = (name) => header.indexOf(name);
  const costOf = (axis, value) => Number(csv.find((r) => r[at('axis')] === axis && (value === null || r[at('value')] === value))[at('cpu_s')]);
  const expected = [costOf('reference', null), costOf('timestep_safety', '0.2'), costOf('timestep_safety', '0.4')];
  check('...and their costs are tradeoff.csv\'s cpu_s (to its 10 digits)',
    shown.every((p, k) => Math.abs(p.cpu - expected[k]) <= 1e-9 * expected[k]), JSON.stringify({ shown, expected }));

  const download = await page.evaluate(async () => (await fetch(document.querySelector('.study-tradeoff a[download]').href)).text());
  const served = await (await fetch(`${base}/api/studies/${NAME}/tradeoff?format=csv`)).text();
  check('the CSV download is the server\'s tradeoff.csv', download === served && download.startsWith('preset,axis,value,paired'), download.slice(0, 80));
  await screenshot(page, 'tradeoff-study');
  check('no console errors', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
