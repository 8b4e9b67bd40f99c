// The New run form offers the periodic cell (web/js/scene_form.js): the boundary select reads
// and writes boundary.type, the rate cap shows for a cell, the cell's width and height only for
// explicit particles (an assembly's cell is placed by the engine) and are written as the list
// boundary.size the engine reads; `grainlab check` passes what the form wrote, and a cell
// without its size is refused at boundary.size, which the form shows beside the width.
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const cli = process.env.GRAINLAB_CLI;
const form = await import(pathToFileURL(join(process.env.GRAINLAB_WEB, 'js', 'scene_form.js')).href);
const dir = mkdtempSync(join(process.env.GRAINLAB_TEST_TMP ?? tmpdir(), 'cell-form-'));
let failures = 0;
const check = (what, ok, detail = '') => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} - ${what}${detail ? ` (${detail})` : ''}`);
  if (!ok) failures++;
};
const grainlabCheck = (label, scene) => {
  const file = join(dir, `${label}.json`);
  writeFileSync(file, JSON.stringify(scene));
  return spawnSync(cli, ['check', file], { encoding: 'utf8' });
};
const field = (key) => form.SCENE_FIELDS.find((f) => f.key === key);

const cellPreset = JSON.parse(execFileSync(cli, ['preset', 'periodic-biaxial-circular-quick']).toString());
check('a cell preset reads as a periodic cell', form.displayValue(field('boundary'), cellPreset) === 'periodic');
check('its rate cap is offered', form.fieldVisible(field('rate_cap'), cellPreset));
check('its size is not (the assembly places the cell)', !form.fieldVisible(field('cell_width'), cellPreset));
const ring = JSON.parse(execFileSync(cli, ['preset', 'circular-quick']).toString());
check('a ring preset reads as the membrane', form.displayValue(field('boundary'), ring) === 'membrane');
check('no rate cap for the ring', !form.fieldVisible(field('rate_cap'), ring));

form.applyValue(field('rate_cap'), cellPreset, '2.5');
check('the rate cap is written', cellPreset.boundary.rate_cap === 2.5);
let r = grainlabCheck('preset-cap', cellPreset);
check('grainlab check passes the edited cell preset', r.status === 0, r.stderr.trim());

// Explicit particles: a free stage of two discs, the boundary switched to the cell in the form.
const explicit = {
  name: 'two discs', particles: [{ position: [0.005, 0.005], radius: 0.001 }, { position: [0.0121, 0.005], radius: 0.001 }],
  stages: [{ type: 'free', duration: 0.001 }],
};
form.applyValue(field('boundary'), explicit, 'periodic');
check('the boundary select writes boundary.type', explicit.boundary?.type === 'periodic');
check('the cell size is offered for explicit particles', form.fieldVisible(field('cell_width'), explicit) && form.fieldVisible(field('cell_height'), explicit));
r = grainlabCheck('no-size', explicit);
const refusal = /^(\S+): /.exec(r.stderr.trim().split('\n').pop() ?? '');
check('without a size the engine refuses at boundary.size', r.status === 2 && r.stderr.includes('boundary.size'), r.stderr.trim());
check('that refusal is shown beside the cell width', form.fieldForPath(explicit, 'boundary.size') === field('cell_width'), refusal?.[1]);
form.applyValue(field('cell_width'), explicit, '20');
form.applyValue(field('cell_height'), explicit, '15');
check('width and height are the list boundary.size in m', JSON.stringify(explicit.boundary.size) === '[0.02,0.015]', JSON.stringify(explicit.boundary));
check('and read back in mm', form.displayValue(field('cell_height'), explicit) === '15');
r = grainlabCheck('sized', explicit);
check('grainlab check passes the cell the form wrote', r.status === 0, r.stderr.trim());

rmSync(dir, { recursive: true, force: true });
process.exit(failures ? 1 : 0);
