// Every loading path the dashboard's form offers (web/js/scene_form.js PATH_STAGES) is a stage
// the engine accepts: each replaces circular-quick's shearing stage, as the form does, and
// `grainlab check` must pass the scene. A stage type or field the engine renamed or dropped
// then fails here, not as a 400 when a researcher presses Run. A misspelt type is the control:
// check must refuse it, naming the field.
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const cli = process.env.GRAINLAB_CLI;
const web = process.env.GRAINLAB_WEB;
const form = await import(pathToFileURL(join(web, 'js', 'scene_form.js')).href);
const base = JSON.parse(execFileSync(cli, ['preset', 'circular-quick']).toString());
const dir = mkdtempSync(join(process.env.GRAINLAB_TEST_TMP ?? tmpdir(), 'path-stages-'));
let failures = 0;

// circular-quick with its shearing (last) stage replaced, as the form replaces it.
function withShearing(stage) {
  const scene = structuredClone(base);
  scene.stages[scene.stages.length - 1] = stage;
  return scene;
}

function check(label, scene) {
  const file = join(dir, `${label}.json`);
  writeFileSync(file, JSON.stringify(scene));
  return spawnSync(cli, ['check', file], { encoding: 'utf8' });
}

const paths = Object.entries(form.PATH_STAGES);
for (const [name, stage] of paths) {
  const scene = withShearing(stage);
  if (form.scenePath(scene) !== name) {
    console.log(`FAIL - ${name}: the form reads this scene's path as '${form.scenePath(scene)}'`);
    failures++;
  }
  const r = check(name, scene);
  if (r.status === 0) console.log(`ok   - ${name}: ${r.stdout.trim()}`);
  else {
    console.log(`FAIL - ${name}: grainlab check exited ${r.status}: ${r.stderr.trim()}`);
    failures++;
  }
}
const misspelt = check('misspelt', withShearing({ ...form.PATH_STAGES.biaxial, type: 'biaxal' }));
if (misspelt.status === 2 && misspelt.stderr.includes('.type')) console.log('ok   - a misspelt type is refused by field');
else {
  console.log(`FAIL - a misspelt type: exit ${misspelt.status}, ${misspelt.stderr.trim()}`);
  failures++;
}
rmSync(dir, { recursive: true, force: true });
if (paths.length < 5) {
  console.log(`FAIL - only ${paths.length} paths in PATH_STAGES`);
  failures++;
}
process.exit(failures ? 1 : 0);
