// The paper from the dashboard: "Launch the paper" with 1 seed of the quick presets queues the
// six assemblies; a refusal (0 seeds) is shown naming its field with nothing stored; once the
// runs have ended the study's page shows the findings table, one row per check with its
// estimate and verdict as GET /api/studies/NAME/findings has them, and the CSV download is
// the server's findings.csv (which tests/server/study_paper_test.sh compares with grainlab
// paper's). Delete study then removes it with its runs. No console errors but the refusal
// provoked on purpose.
import { check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const NAME = 'paper-from-form';

await runBrowserTest(['--max-concurrent', '2'], async ({ server, browser }) => {
  const { base } = server;
  const json = async (path) => (await fetch(`${base}${path}`)).json();
  const page = await browser.newPage({ viewport: { width: 1300, height: 1100 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  await page.goto(`${base}/#/studies`);

  await page.locator('#paper-seeds').fill('0');
  consoleWatch.expect('400');
  await page.getByRole('button', { name: 'Launch the paper' }).click();
  const paperError = page.locator('.paper-form .form-error');
  await waitUntil(async () => await paperError.isVisible(), 15);
  check('0 seeds is refused, naming paper.seeds', /^paper\.seeds: /.test(await paperError.textContent()), await paperError.textContent());
  check('...and nothing is stored', (await json('/api/studies')).studies.length === 0);

  await page.locator('#paper-name').fill(NAME);
  await page.locator('#paper-seeds').fill('1');
  await page.getByRole('button', { name: 'Launch the paper' }).click();
  const row = page.locator(`tr[data-study="${NAME}"]`);
  await waitUntil(async () => (await row.count()) === 1, 15);
  const study = await json(`/api/studies/${NAME}`);
  check('the paper with 1 seed is six runs of the quick presets', study.runs === 6
    && study.run_parameters.every((r) => r.parameters.seed === 1 && r.parameters.preset.endsWith('-quick')), JSON.stringify(study.spec));
  const finished = await waitUntil(async () => /completed/.test(await row.locator('.status').textContent()), 240);
  check('it runs to completed', Boolean(finished), await row.textContent());

  await row.getByRole('link', { name: NAME }).click();
  const rows = page.locator('table.findings tbody tr');
  await waitUntil(async () => (await rows.count()) > 0, 60);
  const findings = await json(`/api/studies/${NAME}/findings`);
  const checks = findings.findings.flatMap((f) => f.checks.map((c) => ({ f, c })));
  check(`the findings table has a row per check (${checks.length})`, (await rows.count()) === checks.length, `${await rows.count()} rows`);
  const verdicts = await page.$$eval('td.finding-verdict', (cells) => cells.map((c) => c.textContent).filter(Boolean));
  check('...each finding\'s verdict as the server judged it', verdicts.join('|') === findings.findings.map((f) => f.verdict).join('|'), verdicts.join('|'));
  const values = await page.$$eval('td.finding-value', (cells) => cells.map((c) => c.dataset.value));
  check('...each check\'s estimate', values.join('|') === checks.map(({ c }) => String(c.value)).join('|'));
  const csv = await page.evaluate(async () => (await fetch(document.querySelector('.study-findings a[download]').href)).text());
  const served = await (await fetch(`${base}/api/studies/${NAME}/findings?format=csv`)).text();
  check('the CSV download is the server\'s findings.csv', csv === served && csv.startsWith('number,claim,criterion,verdict'), csv.slice(0, 80));
  await screenshot(page, 'paper-study');

  // Delete from its page (confirmed): the study, its runs and their series go.
  page.once('dialog', (dialog) => dialog.accept());
  await page.getByRole('button', { name: 'Delete study' }).click();
  await waitUntil(async () => page.url().endsWith('#/studies'), 30);
  const runsLeft = (await json(`/api/runs?study=${NAME}`)).total;
  const seriesGone = (await fetch(`${base}/api/runs/${study.run_parameters[0].id}/series`)).status;
  check('Delete study removes it with its runs and series', (await json('/api/studies')).studies.length === 0
    && runsLeft === 0 && seriesGone === 404, `${runsLeft} runs left, series ${seriesGone}`);
  check('no console errors', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
