// The dashboard in a real browser against the real server: start circular-quick from the New
// run form, watch the particle view, charts and rose diagrams fill while it runs and after,
// replay it with the strain slider, download its CSV, list and compare it (run by run and as an
// ensemble's mean with its 95 % band), and get the API's
// validation error beside the friction field for a negative friction; the loading paths in the
// form, and a rotation charted against its angle. No console errors.
import { canvasHash, canvasInk, check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const PAPER_PRESETS = ['circular', 'elongated-random', 'elongated-bedding-0', 'elongated-bedding-30',
  'elongated-bedding-60', 'elongated-bedding-90'];

await runBrowserTest([], async ({ server, browser }) => {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  const { base } = server;

  // ---- the runs list, empty ----
  await page.goto(`${base}/`);
  await page.getByRole('heading', { name: 'Runs' }).waitFor();
  await page.locator('.empty-state').filter({ hasText: 'No runs yet' }).waitFor({ state: 'visible' });
  check('the runs list opens at / and says there are no runs', true);
  check('the top bar shows the server\'s health',
    Boolean(await waitUntil(async () => /server .* running/.test(await page.locator('#server-state').textContent()), 10)));
  await screenshot(page, '01-runs-empty');

  // ---- New run: presets and the circular-quick scene ----
  await page.getByRole('link', { name: 'New run' }).first().click();
  await page.waitForFunction(() => document.querySelectorAll('#preset option').length > 0);
  const presets = await page.$$eval('#preset option', (options) => options.map((o) => o.value));
  check('the preset list has the paper\'s six assemblies and their -quick variants',
    PAPER_PRESETS.every((p) => presets.includes(p) && presets.includes(`${p}-quick`)), presets.join(' '));
  await page.selectOption('#preset', 'circular-quick');
  await page.waitForFunction(() => document.querySelector('#field-name')?.value === 'circular-quick');
  check('the form shows the preset\'s friction', (await page.inputValue('#field-friction')) === '0.5');
  check('the form shows the confining stress in kPa', (await page.inputValue('#field-confining')) === '300');
  check('a disc preset hides the bedding angle', !(await page.locator('#field-bedding_angle').isVisible()));
  check('the form shows the preset\'s engine', (await page.inputValue('#field-engine')) === 'dem');
  check('the preset\'s own settings are no named fidelity', (await page.inputValue('#field-fidelity')) === 'custom');
  // A fidelity sets timestep safety, sampling and the shearing rate together (docs/speed-accuracy.md).
  await page.selectOption('#field-fidelity', 'reference');
  check('the reference fidelity sets the timestep safety', (await page.inputValue('#field-timestep_safety')) === '0.05');
  check('the reference fidelity sets the shearing rate for discs (I = 1e-4)', (await page.inputValue('#field-strain_rate')) === '0.266');
  const edited = JSON.parse(await page.inputValue('textarea.scene-json'));
  check('the reference fidelity samples every 0.001 of strain', edited.output?.sample_strain === 0.001, JSON.stringify(edited.output));
  // The draft shears at I = 3e-4, the fastest rate at which the servo holds σ11 (docs/speed-accuracy.md).
  await page.selectOption('#field-fidelity', 'draft');
  check('the draft fidelity shears discs at I = 3e-4, inside the servo\'s bound', (await page.inputValue('#field-strain_rate')) === '0.798');
  await page.selectOption('#field-fidelity', 'reference');
  // The loading paths (docs/loading-paths.md): the form offers each as the shearing stage,
  // with its own fields.
  const pathOptions = await page.$$eval('#field-path option', (options) => options.map((o) => o.value));
  check('the form offers the loading paths', ['biaxial', 'constant_volume', 'rotation', 'cyclic', 'simple_shear']
    .every((p) => pathOptions.includes(p)), pathOptions.join(' '));
  check('a paper preset\'s path is the biaxial stage', (await page.inputValue('#field-path')) === 'biaxial');
  check('a biaxial preset hides the rotation fields', !(await page.locator('#field-deviatoric_strain_rate').isVisible()));
  const stageOf = async () => JSON.parse(await page.inputValue('textarea.scene-json')).stages[2];
  await page.selectOption('#field-path', 'rotation');
  check('choosing rotation puts a rotation stage in the scene', (await stageOf()).type === 'rotation', JSON.stringify(await stageOf()));
  const rotationFields = ['deviatoric_strain_rate', 'total_rotation_deg', 'rotation_duration', 'mean_stress', 'initial_direction_deg'];
  const rotationShown = await Promise.all(rotationFields.map((k) => page.locator(`#field-${k}`).isVisible()));
  check('the rotation stage shows its fields', rotationShown.every(Boolean), rotationFields.join(' ') + ' ' + rotationShown.join(' '));
  check('the mean stress shows in kPa', (await page.inputValue('#field-mean_stress')) === '300');
  check('the final axial strain is hidden for a rotation', !(await page.locator('#field-target_axial_strain').isVisible()));
  await page.fill('#field-total_rotation_deg', '180');
  check('editing the total rotation writes it into the stage', (await stageOf()).total_rotation_deg === 180);
  // Switching keeps the confining stress and the shearing rate that were set.
  await page.fill('#field-confining', '200');
  await page.selectOption('#field-path', 'simple_shear');
  await page.selectOption('#field-path', 'rotation');
  check('a new path holds the consolidation pressure', (await page.inputValue('#field-mean_stress')) === '200');
  await page.fill('#field-confining', '300');
  await page.selectOption('#field-path', 'cyclic');
  check('choosing cyclic shows its amplitude (in %) and cycles', (await page.inputValue('#field-strain_amplitude')) === '1'
    && (await page.inputValue('#field-cycles')) === '3' && (await stageOf()).type === 'cyclic');
  check('an amplitude-limited cyclic stage hides the q/p limits', !(await page.locator('#field-q_over_p_upper').isVisible()));
  const json = JSON.parse(await page.inputValue('textarea.scene-json'));
  delete json.stages[2].strain_amplitude;
  json.stages[2].q_over_p_limits = [-0.1, 0.2];
  await page.fill('textarea.scene-json', JSON.stringify(json, null, 2));
  check('a stress-ratio-limited cyclic stage shows its limits', (await page.inputValue('#field-q_over_p_upper')) === '0.2'
    && (await page.inputValue('#field-q_over_p_lower')) === '-0.1');
  await page.fill('#field-q_over_p_upper', '0.3');
  check('editing a q/p limit writes it into the array', JSON.stringify((await stageOf()).q_over_p_limits) === '[-0.1,0.3]',
    JSON.stringify((await stageOf()).q_over_p_limits));
  await page.selectOption('#field-path', 'simple_shear');
  check('choosing simple shear shows its shear rate and normal stress', await page.locator('#field-shear_rate').isVisible()
    && (await page.inputValue('#field-normal_stress')) === '300' && (await stageOf()).type === 'simple_shear');
  await page.selectOption('#field-path', 'constant_volume');
  check('choosing constant volume sets the biaxial stage\'s lateral boundary', (await stageOf()).lateral === 'constant_volume'
    && (await page.inputValue('#field-lateral')) === 'constant_volume');
  // Back to the preset as it is, for the run below.
  await page.selectOption('#preset', 'circular');
  await page.waitForFunction(() => document.querySelector('#field-name')?.value === 'circular');
  await page.selectOption('#preset', 'circular-quick');
  await page.waitForFunction(() => document.querySelector('#field-name')?.value === 'circular-quick');
  check('choosing the preset again restores its settings', (await page.inputValue('#field-fidelity')) === 'custom');
  await page.getByRole('button', { name: 'Start run' }).click();
  await page.waitForURL(/#\/run\/\d+$/);
  const runId = Number(/#\/run\/(\d+)$/.exec(page.url())[1]);
  check('starting the preset opens its run view', runId > 0, `run ${runId}`);

  // ---- the run view, live and then completed ----
  const drew = await waitUntil(() => page.$eval('canvas.particle-canvas', (c) => c.dataset.step !== undefined), 60);
  check('the particle view receives a frame', Boolean(drew));
  const liveInk = await canvasInk(page, 'canvas.particle-canvas');
  check('the particle view is drawn (its canvas is not blank)', liveInk > 0.05, `${(100 * liveInk).toFixed(1)} % of pixels inked`);
  await screenshot(page, '02-run-live');

  const completed = await waitUntil(async () => (await page.locator('.run-header .status').getAttribute('data-status')) === 'completed', 180);
  check('the run completes and the header says so', Boolean(completed));
  const facts = await page.locator('.run-header .facts').textContent();
  check('the header shows the estimate the run was queued with', /estimated ≥ \S+/.test(facts), facts);
  check('a preset inside the validity envelope shows no warnings', await page.locator('.run-header .warnings').isHidden());
  const replayReady = await waitUntil(() => page.$eval('.replay-bar input[type=range]', (s) => !s.disabled), 30);
  check('the replay slider is enabled once the run has ended', Boolean(replayReady));

  const chartPoints = await page.$$eval('.chart-panel', (panels) => panels.map((p) => [p.dataset.chart, Number(p.dataset.points ?? 0)]));
  check('all seven charts are there', chartPoints.length === 7, JSON.stringify(chartPoints));
  check('every chart has points of the shearing stage', chartPoints.every(([, n]) => n >= 10), JSON.stringify(chartPoints));
  for (const [key] of chartPoints) {
    const ink = await canvasInk(page, `.chart-panel[data-chart="${key}"] canvas`);
    check(`chart "${key}" draws lines`, ink > 0.005, `${(100 * ink).toFixed(2)} % inked`);
  }
  const roseSeq = await page.$eval('.rose-panel', (p) => p.dataset.seq);
  check('the rose diagrams show a histogram', roseSeq !== undefined, `sample ${roseSeq}`);
  for (const key of ['density', 'fn', 'ft', 'ln', 'lt']) {
    const ink = await canvasInk(page, `canvas[data-rose="${key}"]`);
    check(`rose diagram "${key}" is drawn`, ink > 0.02, `${(100 * ink).toFixed(1)} % inked`);
  }
  const captions = await page.$$eval('.rose .caption', (c) => c.map((e) => e.textContent));
  check('the rose captions give a_k and θ_k', captions.every((t) => /a_\w+ = .*θ_\w+ = /.test(t)), captions.join(' | '));
  await screenshot(page, '03-run-completed');

  // ---- replay with the slider: every view follows ----
  const slider = page.locator('.replay-bar input[type=range]');
  const last = Number(await slider.getAttribute('max'));
  const before = {
    step: await page.$eval('canvas.particle-canvas', (c) => c.dataset.step),
    particles: await canvasHash(page, 'canvas.particle-canvas'),
    rose: await page.$eval('.rose-panel', (p) => p.dataset.seq),
    where: await page.locator('.replay-bar .where').textContent(),
    chart: await canvasHash(page, '.chart-panel[data-chart="strength"] canvas'),
  };
  // A sample early in the shearing stage: the first row whose label says "shearing".
  const series = await page.evaluate(async (id) => (await fetch(`/api/runs/${id}/series`)).json(), runId);
  const stageColumn = series.columns.indexOf('stage');
  const firstShearing = series.rows.findIndex((row) => row[stageColumn] === 'shearing');
  const target = Math.min(last, firstShearing + 3);
  await slider.fill(String(target));
  const moved = await waitUntil(async () => {
    const step = await page.$eval('canvas.particle-canvas', (c) => c.dataset.step);
    return step !== before.step ? step : null;
  }, 20);
  check('moving the slider loads an earlier stored frame', Boolean(moved), `step ${before.step} → ${moved}`);
  await page.waitForTimeout(300);  // the frame is drawn at the next animation frame
  check('the particle view redraws for it', (await canvasHash(page, 'canvas.particle-canvas')) !== before.particles);
  const roseAfter = await page.$eval('.rose-panel', (p) => p.dataset.seq);
  check('the rose diagrams follow the slider', roseAfter !== before.rose && Number(roseAfter) <= target,
    `sample ${before.rose} → ${roseAfter}`);
  const whereAfter = await page.locator('.replay-bar .where').textContent();
  check('the slider label names the sample, stage and axial strain', whereAfter !== before.where && /shearing · ε₂₂ = /.test(whereAfter), whereAfter);
  check('the charts move their marker to the slider\'s sample',
    (await canvasHash(page, '.chart-panel[data-chart="strength"] canvas')) !== before.chart);
  await screenshot(page, '04-replay');

  // ---- the particle view's controls ----
  const canvas = page.locator('canvas.particle-canvas');
  let shown = await canvasHash(page, 'canvas.particle-canvas');
  await canvas.hover();
  await page.mouse.wheel(0, -500);
  await page.waitForTimeout(300);
  let now = await canvasHash(page, 'canvas.particle-canvas');
  check('the wheel zooms the particle view', now !== shown);
  shown = now;
  const box = await canvas.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 40, { steps: 4 });
  await page.mouse.up();
  await page.waitForTimeout(300);
  now = await canvasHash(page, 'canvas.particle-canvas');
  check('dragging pans the particle view', now !== shown);
  shown = now;
  await page.selectOption('select[aria-label="Colour particles by"]', 'orientation');
  await page.waitForTimeout(300);
  now = await canvasHash(page, 'canvas.particle-canvas');
  check('colouring by orientation redraws the particles', now !== shown
    && /long-axis direction/.test(await page.locator('.particle-panel .legend').textContent()));
  shown = now;
  await page.getByLabel('force chains (width ∝ fₙ)').uncheck();
  await page.waitForTimeout(300);
  now = await canvasHash(page, 'canvas.particle-canvas');
  check('the force chains can be hidden', now !== shown);
  await page.getByRole('button', { name: 'Fit view' }).click();
  await page.waitForTimeout(300);
  await screenshot(page, '05-orientation-no-chains');

  // ---- CSV download ----
  const csvHref = await page.getByRole('link', { name: 'Download CSV' }).getAttribute('href');
  const csv = await page.evaluate(async (href) => (await fetch(href)).text(), csvHref);
  const csvLines = csv.trim().split('\n');
  check('the CSV link serves series.csv with the contract\'s header', csvLines[0].startsWith('step,time,stage,axial_strain'), csvHref);
  check('the CSV has one line per sample', csvLines.length - 1 === last + 1, `${csvLines.length - 1} rows, slider has ${last + 1}`);
  // Ink alone would pass a chart of the wrong column: the strength chart must plot, against
  // ε22 in %, series.csv's φ_mob and 2q (σ1 − σ3 in kPa) of the shearing rows.
  const header = csvLines[0].split(',');
  const cell = (line, name) => line.split(',')[header.indexOf(name)];
  const shearingRows = csvLines.slice(1).filter((line) => cell(line, 'stage') === 'shearing');
  const expected = [
    shearingRows.map((line) => 100 * Number(cell(line, 'axial_strain'))),
    shearingRows.map((line) => Number(cell(line, 'phi_mob_deg'))),
    shearingRows.map((line) => 2e-3 * Number(cell(line, 'q'))),
  ];
  const plotted = await page.$eval('.chart-panel[data-chart="strength"]', (p) => p.uplot.data.map((s) => Array.from(s)));
  const mismatch = ['x (ε22 %)', 'φ_mob', 'σ1 − σ3'].flatMap((name, k) => {
    if (plotted[k]?.length !== expected[k].length) return [`${name}: ${plotted[k]?.length} points plotted, ${expected[k].length} shearing rows`];
    const bad = expected[k].findIndex((v, i) => !(Math.abs(plotted[k][i] - v) <= 1e-9 * Math.max(1, Math.abs(v))));
    return bad < 0 ? [] : [`${name} at row ${bad}: plotted ${plotted[k][bad]}, series.csv gives ${expected[k][bad]}`];
  });
  check('the strength chart plots series.csv\'s φ_mob and σ1 − σ3 of every shearing row', mismatch.length === 0 && shearingRows.length >= 10,
    mismatch.join('; ') || `${shearingRows.length} rows`);

  // ---- the runs list shows the run ----
  await page.getByRole('link', { name: 'Runs' }).first().click();
  const row = page.locator(`tr[data-run-id="${runId}"]`);
  await row.waitFor();
  const rowText = await row.textContent();
  check('the runs list shows the run with its preset and status', /circular-quick/.test(rowText) && /completed/.test(rowText) && /100 %/.test(rowText), rowText);
  await screenshot(page, '06-runs-list');

  // ---- a validation error beside its field ----
  await page.goto(`${base}/#/new?preset=circular-quick`);
  await page.waitForFunction(() => document.querySelector('#field-name')?.value === 'circular-quick');
  await page.fill('#field-friction', '-0.5');
  consoleWatch.expect('status of 400');  // Chromium logs the refused POST; the page handles it
  await page.getByRole('button', { name: 'Start run' }).click();
  const fieldError = page.locator('[data-error-for="friction"]');
  const message = await waitUntil(async () => (await fieldError.textContent()) || null, 15);
  check('a negative friction gets the API\'s error beside the friction field', /must be >= 0/.test(message ?? ''), message);
  check('the form stays open', /#\/new/.test(page.url()));
  const runs = await page.evaluate(async () => (await (await fetch('/api/runs')).json()).runs.length);
  check('no run was created for the bad scene', runs === 1, `${runs} runs`);
  await screenshot(page, '07-validation-error');

  // ---- polygons watched live, then cancelled and deleted ----
  // The full preset (minutes), so the run is still going when Cancel is clicked on any machine:
  // the quick one takes under 5 s here.
  const liveId = await page.evaluate(async () => {
    const response = await fetch('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify({ preset: 'elongated-random' }) });
    return (await response.json()).id;
  });
  // A run sheared faster than the lateral servo can follow: its header lists the warning.
  const warnedId = await page.evaluate(async () => {
    const scene = await (await fetch('/api/presets/circular-quick')).json();
    scene.stages[2].strain_rate = 4;
    return (await (await fetch('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(scene) })).json()).id;
  });
  await page.goto(`${base}/#/run/${warnedId}`);
  const warned = await waitUntil(async () => {
    const list = page.locator('.run-header .warnings');
    return (await list.isVisible()) ? list.textContent() : null;
  }, 30);
  check('a warned run lists its warnings in the header', /stages\[2\]\.strain_rate: lateral_servo_inertial_number/.test(warned ?? ''),
    warned);
  await page.goto(`${base}/#/run/${liveId}`);
  const firstStep = await waitUntil(() => page.$eval('canvas.particle-canvas', (c) => c.dataset.step), 60);
  const laterStep = await waitUntil(async () => {
    const step = await page.$eval('canvas.particle-canvas', (c) => c.dataset.step);
    return step !== firstStep ? step : null;
  }, 30);
  check('frames stream in live', Boolean(firstStep && laterStep), `step ${firstStep} → ${laterStep}`);
  check('the live view says Live and holds the slider', (await page.locator('.replay-bar strong').textContent()) === 'Live'
    && await page.$eval('.replay-bar input[type=range]', (s) => s.disabled));
  const livePoints = await waitUntil(() => page.$eval('.chart-panel[data-chart="volumetric"]', (p) => Number(p.dataset.points) >= 3), 30);
  check('the charts fill while the run goes on (against time before shearing)', Boolean(livePoints),
    await page.locator('select[aria-label="x axis"]').inputValue());
  const polygonInk = await canvasInk(page, 'canvas.particle-canvas');
  check('the polygons are drawn', polygonInk > 0.05, `${(100 * polygonInk).toFixed(1)} % inked`);
  await screenshot(page, '08-live-polygons');
  await page.getByRole('button', { name: 'Cancel run' }).click();
  const cancelled = await waitUntil(async () => (await page.locator('.run-header .status').getAttribute('data-status')) === 'cancelled', 60);
  check('Cancel run stops it and the header says cancelled', Boolean(cancelled));
  const cancelledReplay = await waitUntil(() => page.$eval('.replay-bar input[type=range]', (s) => !s.disabled), 30);
  check('a cancelled run replays what it stored', Boolean(cancelledReplay));
  await page.getByRole('link', { name: 'Runs' }).first().click();
  const liveRow = page.locator(`tr[data-run-id="${liveId}"]`);
  await liveRow.waitFor();
  await liveRow.getByRole('button', { name: 'Delete' }).click();
  await liveRow.getByRole('button', { name: 'Confirm delete' }).click();
  await liveRow.waitFor({ state: 'detached', timeout: 10000 });
  const remaining = await page.evaluate(async () => (await (await fetch('/api/runs')).json()).runs.map((r) => r.id));
  check('Delete, confirmed, removes the run', !remaining.includes(liveId), `runs left: ${remaining.join(',')}`);

  // ---- compare: a second run (friction 0.3) overlaid on the first ----
  const secondId = await page.evaluate(async () => {
    const scene = await (await fetch('/api/presets/circular-quick')).json();
    scene.name = 'circular-quick, μ = 0.3';
    scene.material.friction = 0.3;
    const response = await fetch('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(scene) });
    return (await response.json()).id;
  });
  const secondDone = await waitUntil(() => page.evaluate(async (id) =>
    (await (await fetch(`/api/runs/${id}`)).json()).status === 'completed', secondId), 180);
  check('a second run (μ = 0.3) completes', Boolean(secondDone), `run ${secondId}`);
  await page.goto(`${base}/#/compare?ids=${runId},${secondId}`);
  const compared = await waitUntil(() => page.$$eval('.compare-grid .chart-panel',
    (p) => p.length > 0 && p.every((e) => Number(e.dataset.points) > 0)), 20);
  check('the compare view draws every chart', Boolean(compared));
  const linesPerChart = await page.$$eval('.compare-grid .chart-panel', (panels) =>
    panels.map((p) => p.querySelectorAll('.u-legend .u-series').length - 1));
  check('each compare chart overlays both runs', linesPerChart.length > 0 && linesPerChart.every((n) => n === 2), linesPerChart.join(','));
  const ticked = await page.$$eval('.compare-picker input:checked', (inputs) => inputs.map((i) => Number(i.dataset.runId)));
  check('the picker ticks the compared runs', ticked.length === 2 && ticked.includes(runId) && ticked.includes(secondId), ticked.join(','));
  await screenshot(page, '09-compare');

  // ---- compare as an ensemble: the two runs' mean with its 95 % band ----
  await page.check('#compare-ensemble');
  const ensemble = await waitUntil(() => page.$$eval('.compare-grid .chart-panel',
    (p) => p.length > 0 && p.every((e) => e.dataset.ensemble === '2' && Number(e.dataset.points) > 0)), 20);
  check('ensemble mode draws every chart as the mean of the ticked runs', Boolean(ensemble));
  const ensembleSeries = await page.$$eval('.compare-grid .chart-panel', (panels) =>
    panels.map((p) => p.querySelectorAll('.u-legend .u-series').length - 1));
  check('each ensemble chart has both runs faint, the band\'s two edges and the mean',
    ensembleSeries.every((n) => n === 5), ensembleSeries.join(','));
  check('ensemble mode is kept in the link', /mode=ensemble/.test(page.url()), page.url());
  await screenshot(page, '10-compare-ensemble');
  // The statistics themselves, in the browser: a t-interval by hand, none for one run, zero
  // width for identical runs, axial means across the wrap.
  const stats = await page.evaluate(async () => {
    const m = await import('/js/ensemble_stats.js');
    const three = m.meanInterval([1, 2, 3, null]);
    const same = m.ensembleBand([[[0, 1, 2], [5, 6, 7]], [[0, 1, 2], [5, 6, 7]], [[0, 0.5, 2], [5, 5.5, 7]]]);
    return {
      half: three.high - three.mean,
      one: m.meanInterval([4]).low,
      sameWidth: Math.max(...same.high.map((hi, i) => hi - same.low[i])),
      sameMean: same.mean,
      axial: m.axialMeanInterval([178, 4]).mean,
    };
  });
  check('the Compare view\'s interval is the t-interval (4.303/√3 for 1, 2, 3)', Math.abs(stats.half - 4.303 / Math.sqrt(3)) < 1e-9, String(stats.half));
  check('one run has no interval', stats.one === null, String(stats.one));
  check('identical runs (one sampled at other strains) give a zero-width band', stats.sameWidth < 1e-12
    && stats.sameMean.every((v, i) => Math.abs(v - [5, 6, 7][i]) < 1e-12), `${stats.sameWidth} ${stats.sameMean}`);
  check('directions average across the wrap (178°, 4° → 1°)', Math.abs(stats.axial - 1) < 1e-9, String(stats.axial));
  // A direction below twice its noise floor is a gap, in the run and the Compare charts alike.
  const masked = await page.evaluate(async () => {
    const { direction } = await import('/js/chart_specs.js');
    const columns = { theta_ln_deg: [10, 170, 95], a_ln: [0.001, 0.2, 0.01], contacts: [2500, 2500, 2500] };
    return direction('ln')({ column: (name) => columns[name] ?? null }, [0, 1, 2]);
  });
  check('θ_ln is drawn only where a_ln ≥ 2 × 1.25·√(2/N_c) (0.071 at 2,500 contacts)',
    masked[0] === null && masked[1] === 170 && masked[2] === null, JSON.stringify(masked));

  // ---- a rotation of the principal axes, charted against the rotation angle ----
  const rotationId = await page.evaluate(async () => {
    const response = await fetch('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify({ preset: 'rotation-circular-quick' }) });
    return (await response.json()).id;
  });
  const rotationDone = await waitUntil(() => page.evaluate(async (id) =>
    (await (await fetch(`/api/runs/${id}`)).json()).status === 'completed', rotationId), 180);
  check('the rotation preset completes', Boolean(rotationDone), `run ${rotationId}`);
  await page.goto(`${base}/#/run/${rotationId}`);
  const axesPoints = await waitUntil(() => page.$$eval('.chart-panel[data-chart="principal-axes"]',
    (p) => (p.length && Number(p[0].dataset.points) >= 150 ? Number(p[0].dataset.points) : null)), 30);
  check('the principal-axes chart has the rotation\'s samples', Boolean(axesPoints), String(axesPoints));
  check('a rotation is charted against the rotation angle', (await page.locator('select[aria-label="x axis"]').inputValue()) === 'rotation');
  const axesInk = await canvasInk(page, '.chart-panel[data-chart="principal-axes"] canvas');
  check('the principal-axes chart draws θσ, θ_ε̇ and θ_c', axesInk > 0.005, `${(100 * axesInk).toFixed(2)} % inked`);
  await screenshot(page, '11-rotation');
  const turned = await page.evaluate(async () => {
    const { rotationAngle } = await import('/js/chart_specs.js');
    const columns = { theta_strain_rate_deg: [170, 10, 50, null, 100] };
    return rotationAngle({ column: (name) => columns[name] ?? null }, [0, 1, 2, 3, 4]);
  });
  check('the rotation angle unwraps θ_strain_rate across 180° (170°, 10°, 50°, –, 100° → 0, 20, 60, –, 110)',
    JSON.stringify(turned) === JSON.stringify([0, 20, 60, null, 110]), JSON.stringify(turned));

  check('no console errors, page exceptions or failed requests', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
