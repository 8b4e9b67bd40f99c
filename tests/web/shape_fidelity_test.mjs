// The New run form's Shape fidelity field: for each representation on a hexagon preset (random
// and bedding 30°), the cost ratio and the biases it shows are the numbers of the table
// `grainlab shapes` wrote (docs/shape-fidelity/shapes-quick.csv, read here on its own, not
// through the JSON the dashboard loads), and choosing a representation rewrites the scene's
// assembly. No console errors.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { check, runBrowserTest, watchConsole } from './harness.mjs';

const REPO = join(import.meta.dirname, '../..');

// RFC 4180, as grainlab's CsvTable writes it: quoted cells may hold commas and doubled quotes.
function parseCsv(text) {
  const rows = [];
  let row = [], cell = '', quoted = false;
  for (let k = 0; k < text.length; k++) {
    const c = text[k];
    if (quoted) {
      if (c === '"' && text[k + 1] === '"') { cell += '"'; k++; }
      else if (c === '"') quoted = false;
      else cell += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { row.push(cell); cell = ''; }
    else if (c === '\n') { row.push(cell); rows.push(row); row = []; cell = ''; }
    else if (c !== '\r') cell += c;
  }
  if (cell !== '' || row.length) { row.push(cell); rows.push(row); }
  const [header, ...body] = rows;
  return body.map((r) => Object.fromEntries(header.map((name, i) => [name, r[i]])));
}
const table = parseCsv(readFileSync(join(REPO, 'docs/shape-fidelity/shapes-quick.csv'), 'utf8'));
const calibration = parseCsv(readFileSync(join(REPO, 'docs/shape-fidelity/calibration-quick.csv'), 'utf8'));
const calibrated = Number(calibration.find((r) => r.kind === 'interpolated').rolling_friction);
// The rolling discs shown: the measured μ_r nearest the calibrated one.
const rollingNames = [...new Set(table.map((r) => r.representation).filter((n) => n.startsWith('rolling-')))];
const rolling = rollingNames.sort((a, b) => Math.abs(Number(a.slice(8)) - calibrated) - Math.abs(Number(b.slice(8)) - calibrated))[0];

// The dashboard's rounding: angles to 0.1°, ratios to 0.001, a minus sign (−) and a plus on biases.
const DECIMALS = { peak_phi_mob_deg: 1, void_ratio_consolidated: 3, a_c_5: 3, theta_sigma_5_deg: 1, omega_5_deg: 1 };
const fmt = (v, d, sign) => `${sign && v > 0 ? '+' : ''}${v < 0 ? '−' : ''}${Math.abs(v).toFixed(d)}`;
function expected(assembly, representation, quantity) {
  const r = table.find((x) => x.assembly === assembly && x.representation === representation && x.quantity === quantity);
  const d = DECIMALS[quantity], unit = quantity.endsWith('_deg') ? '°' : '';
  const reference = representation === 'hexagons';
  const [v, lo, hi] = reference ? [r.mean, r.mean_ci_low, r.mean_ci_high] : [r.bias, r.bias_ci_low, r.bias_ci_high];
  return { text: `${fmt(Number(v), d, !reference)}${unit} (${fmt(Number(lo), d)} to ${fmt(Number(hi), d)})`, cost: Number(r.cost_ratio) };
}

await runBrowserTest([], async ({ server, browser }) => {
  const page = await browser.newPage({ viewport: { width: 1200, height: 1400 } });
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  for (const [preset, assembly] of [['elongated-random-quick', 'random'], ['elongated-bedding-30-quick', 'bedding-30']]) {
    await page.goto(`${server.base}/#/new?preset=${preset}`);
    await page.waitForFunction((name) => document.querySelector('#field-name')?.value === name, preset);
    const figures = page.locator('[data-figures-for="representation"]');
    await figures.locator('[data-quantity="peak_phi_mob_deg"]').waitFor({ state: 'visible' });
    check(`${preset} shows as hexagons`, (await page.inputValue('#field-representation')) === 'hexagons');
    for (const [option, representation] of [['hexagons', 'hexagons'], ['clumps-2', 'clumps-2'], ['clumps-3', 'clumps-3'],
      ['clumps-5', 'clumps-5'], ['rolling', rolling], ['discs', 'discs']]) {
      await page.selectOption('#field-representation', option);
      const scene = JSON.parse(await page.inputValue('textarea.scene-json'));
      const a = scene.assembly;
      const shapeOk = {
        hexagons: a.shape === 'elongated' && a.vertices === 6,
        'clumps-2': a.shape === 'clump' && a.clump_discs === 2, 'clumps-3': a.shape === 'clump' && a.clump_discs === 3,
        'clumps-5': a.shape === 'clump' && a.clump_discs === 5,
        rolling: a.shape === 'disc' && scene.material.rolling_friction === Number(rolling.slice(8)),
        discs: a.shape === 'disc' && scene.material.rolling_friction === undefined,
      }[option];
      check(`${assembly}: choosing ${option} rewrites the assembly`, shapeOk, JSON.stringify({ a, m: scene.material }));
      if (option.startsWith('clumps-') && assembly === 'bedding-30') {
        check(`${option} keeps the bedding angle`, a.orientation === 'bedding' && a.bedding_angle_deg === 30, JSON.stringify(a));
      }
      // Discs carry no fabric: their figures are against the random assembly's hexagons.
      const against = option === 'rolling' || option === 'discs' ? 'random' : assembly;
      const heading = await figures.locator('div').first().textContent();
      const costShown = /cost ([\d.]+)×/.exec(heading)?.[1];
      const want = expected(against, representation, 'peak_phi_mob_deg');
      if (option === 'hexagons') check(`${assembly}: the hexagons are the reference`, heading.includes('the reference\'s means'), heading);
      else check(`${against} ${representation}: the cost ratio shown is the table's`, costShown === want.cost.toFixed(2), `${costShown} vs ${want.cost}`);
      for (const quantity of Object.keys(DECIMALS)) {
        const shown = await figures.locator(`[data-quantity="${quantity}"] .figure`).textContent();
        const w = expected(against, representation, quantity).text;
        check(`${against} ${representation} ${quantity}: ${shown} is the table's`, shown === w, `want ${w}`);
      }
    }
  }
  // The rolling preset (μ_r = 0.1) shows the ensemble at its own μ_r.
  await page.goto(`${server.base}/#/new?preset=circular-rolling-quick`);
  await page.waitForFunction(() => document.querySelector('#field-name')?.value === 'circular-rolling-quick');
  const figures = page.locator('[data-figures-for="representation"]');
  await figures.locator('[data-quantity="peak_phi_mob_deg"]').waitFor({ state: 'visible' });
  check('circular-rolling-quick shows as rolling discs', (await page.inputValue('#field-representation')) === 'rolling');
  const shown = await figures.locator('[data-quantity="peak_phi_mob_deg"] .figure').textContent();
  check(`circular-rolling-quick shows rolling-0.1's peak φ_mob bias (${shown})`, shown === expected('random', 'rolling-0.1', 'peak_phi_mob_deg').text);
  check('no console errors, page exceptions or failed requests', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
});
