// "New test on this specimen": a finished run's view offers it; it opens the New run form on
// that run's scene with "start_from": {"run_id", "stage"} (by default the stage before the
// first shearing stage), without the specimen's own settings, and starts the test. The same
// shearing on the parent's consolidated specimen stores the parent's rows from the end of
// consolidation on, byte for byte; a shearing changed in the form starts from the same
// specimen (the same first row) and stops where the form says. No console errors.
import { check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

await runBrowserTest([], async ({ server, browser }) => {
  const { base } = server;
  const get = async (path) => {
    const response = await fetch(`${base}${path}`);
    return path.includes('format=csv') ? response.text() : response.json();
  };
  const finished = (id) => waitUntil(async () => {
    const run = await get(`/api/runs/${id}`);
    return ['completed', 'failed', 'cancelled'].includes(run.status) ? run : null;
  }, 240);
  // circular-quick sheared to 2 %: a few seconds.
  const scene = await get('/api/presets/circular-quick');
  scene.name = 'specimen';
  scene.stages[2].target_axial_strain = 0.02;
  const { id: parent } = await (await fetch(`${base}/api/runs`, {
    method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(scene),
  })).json();
  check('the parent run completes', (await finished(parent))?.status === 'completed');
  const parentCsv = (await get(`/api/runs/${parent}/series?format=csv`)).split('\n');
  const lastConsolidation = parentCsv.findLastIndex((line) => line.split(',')[2] === 'consolidation');
  const fromConsolidation = [parentCsv[0], ...parentCsv.slice(lastConsolidation)].join('\n');

  const page = await browser.newPage({ viewport: { width: 1280, height: 1000 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);

  // Starts a test from the parent's view; `edit(page)` changes the form. Resolves to the new run's id.
  async function branch(edit) {
    await page.goto(`${base}/#/run/${parent}`);
    const offer = page.getByRole('link', { name: 'New test on this specimen' });
    await offer.waitFor({ state: 'visible' });
    await offer.click();
    await waitUntil(async () => (await page.locator('#specimen-stage option').count()) > 0, 30);
    await edit(page);
    await page.getByRole('button', { name: 'Start run' }).click();
    const match = await waitUntil(async () => /#\/run\/(\d+)$/.exec(page.url()), 30);
    return match ? Number(match[1]) : null;
  }

  // ---- the same shearing: the exact branch ----
  let options = [];
  let formChecks = {};
  const same = await branch(async () => {
    options = await page.locator('#specimen-stage option').allTextContents();
    formChecks = {
      stage: await page.locator('#specimen-stage').inputValue(),
      title: await page.locator('.view-title h2').textContent(),
      friction: await page.locator('#field-friction').isVisible(),
      strain: await page.locator('#field-target_axial_strain').isVisible(),
      json: JSON.parse(await page.locator('textarea.scene-json').inputValue()).start_from,
    };
    await screenshot(page, 'specimen-branch-form');
  });
  check('the form offers the stages whose end the run kept and that have a stage after them',
    options.join() === 'compaction,consolidation', options.join());
  check('by default the end of consolidation', formChecks.stage === 'consolidation', formChecks.stage);
  check('the form says which run it starts from', formChecks.title?.includes(`run #${parent}`), formChecks.title);
  check('the scene JSON starts from that run and stage',
    JSON.stringify(formChecks.json) === JSON.stringify({ run_id: parent, stage: 'consolidation' }), JSON.stringify(formChecks.json));
  check('the specimen\'s material is not offered for editing, the shearing is', !formChecks.friction && formChecks.strain);
  check('starting it opens the new run', same !== null && same !== parent, String(same));
  const sameRun = await finished(same);
  check('the test completes', sameRun?.status === 'completed', JSON.stringify(sameRun?.error));
  check('it records where it started', JSON.stringify(sameRun?.started_from) === JSON.stringify({ run_id: parent, stage: 'consolidation' }),
    JSON.stringify(sameRun?.started_from));
  const sameCsv = await get(`/api/runs/${same}/series?format=csv`);
  check('its series is the parent\'s from the end of consolidation on, byte for byte',
    sameCsv.replace(/\n$/, '') === fromConsolidation.replace(/\n$/, ''),
    `${sameCsv.split('\n').length} and ${fromConsolidation.split('\n').length} lines`);
  await waitUntil(async () => (await page.locator('.run-header .facts').textContent()).includes('from run'), 30);
  const facts = await page.locator('.run-header .facts').textContent();
  check('its view names the run it started from', facts.includes(`from run #${parent}'s consolidation`), facts);

  await page.goto(`${base}/#/runs`);
  const listed = await waitUntil(async () => {
    const text = await page.locator(`tr[data-run-id="${same}"]`).textContent().catch(() => '');
    return text.includes(`on #${parent}'s consolidation`) ? text : null;
  }, 30);
  check('the runs list says which specimen it ran on', Boolean(listed), listed);

  // ---- another shearing, set in the form: to 1 % instead of 2 % ----
  const shorter = await branch(async () => {
    await page.fill('#field-target_axial_strain', '1');
  });
  const shorterRun = await finished(shorter);
  check('a test sheared to 1 % completes', shorterRun?.status === 'completed', JSON.stringify(shorterRun?.error));
  const shorterRows = (await get(`/api/runs/${shorter}/series?format=csv`)).trim().split('\n');
  const parentRows = fromConsolidation.trim().split('\n');
  check('it starts from the parent\'s consolidated specimen (the same first row)', shorterRows[1] === parentRows[1],
    `${shorterRows[1]?.slice(0, 80)} / ${parentRows[1]?.slice(0, 80)}`);
  const strainColumn = shorterRows[0].split(',').indexOf('axial_strain');
  const lastStrain = Number(shorterRows.at(-1).split(',')[strainColumn]);
  const parentLast = Number(parentRows.at(-1).split(',')[strainColumn]);
  // The strain is counted from the start of shearing; the stage ends at the step that reaches
  // its target (a step moves it by about 1e-6) and samples that state.
  check('and stops at 1 % axial strain where the parent went on to 2 %',
    lastStrain >= 0.01 && lastStrain < 0.0101 && parentLast >= 0.02, `${lastStrain} and ${parentLast}`);
  check('no console errors, page exceptions or failed requests', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
