// kill -9 of the server while two runs are running and streaming to WebSocket watchers, again
// and again: after every restart the runs are `interrupted` and resumable, no stored sample is
// lost (every row seen before the kill is still there, unchanged) or duplicated (steps strictly
// increase); resumed until they complete, both runs' series are byte-identical to the same
// scene run once without interruption.
//
// usage: node kill_under_load_test.mjs [KILLS=3] [WATCHERS_PER_RUN=10]   (prints the figures)
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { TMP, check, finish, getJson, postJson, sleep, startServer, waitFor, watch } from './harness.mjs';

const KILLS = Number(process.argv[2] ?? 3);
const WATCHERS = Number(process.argv[3] ?? 10);

// circular-quick with its shearing 4x slower (about 4 s on a free core), a checkpoint every 0.2 s.
const scene = JSON.parse(execFileSync(process.env.GRAINLAB_CLI, ['preset', 'circular-quick']).toString());
scene.name = 'kill-under-load';
scene.output.checkpoint_every_s = 0.2;
scene.stages[2].strain_rate = 0.25;

const csv = async (base, id) => (await fetch(`${base}/api/runs/${id}/series?format=csv`)).text();
const lines = (text) => text.split('\n').filter(Boolean);

// The reference: the same scene, never interrupted, on a server of its own.
const reference = await startServer();
const { body: created } = await postJson(`${reference.base}/api/runs`, scene);
await waitFor(reference.base, created.id, 'completed', 300);
const referenceCsv = await csv(reference.base, created.id);
await reference.stop();

const db = join(TMP, 'kill-under-load', 'grainlab.db');
let server = await startServer(['--db', db, '--max-concurrent', '2']);
const ids = [];
for (let k = 0; k < 2; k++) ids.push((await postJson(`${server.base}/api/runs`, scene)).body.id);

let lostRows = 0;
let changedRows = 0;
let duplicatedRows = 0;
let notResumable = 0;
let kills = 0;
for (let k = 1; k <= KILLS; k++) {
  const live = [];
  for (const id of ids) {
    const run = await getJson(`${server.base}/api/runs/${id}`);
    if (['queued', 'running'].includes(run.status)) live.push(id);
  }
  if (live.length === 0) break;
  const watchers = live.flatMap((id) => Array.from({ length: WATCHERS }, () => watch(server.wsBase, id, { light: true })));
  for (const w of watchers) w.done.catch(() => {});  // the kill ends them with an error
  // Kill once every live run has a checkpoint, at a random moment up to 1.5 s later.
  for (let t = 0; t < 600 && !live.every((id) => existsSync(`${db}.checkpoints/run-${id}.bin`)); t++) await sleep(50);
  await sleep(Math.random() * 1500);
  const seen = {};
  for (const id of live) seen[id] = lines(await csv(server.base, id));
  const stillLive = [];
  for (const id of live) if (!['completed'].includes((await getJson(`${server.base}/api/runs/${id}`)).status)) stillLive.push(id);
  await server.stop('SIGKILL');
  kills++;

  server = await startServer(['--db', db, '--max-concurrent', '2']);
  for (const id of live) {
    const run = await getJson(`${server.base}/api/runs/${id}`);
    const after = lines(await csv(server.base, id));
    lostRows += Math.max(0, seen[id].length - after.length);
    changedRows += seen[id].filter((row, i) => after[i] !== undefined && after[i] !== row).length;
    const steps = after.slice(1).map((row) => Number(row.split(',')[0]));
    duplicatedRows += steps.filter((s, i) => i > 0 && s <= steps[i - 1]).length;
    if (run.status === 'completed') continue;
    if (run.status !== 'interrupted' || !run.resumable) {
      notResumable++;
      console.log(`run ${id} after kill ${k}: ${run.status}, resumable ${run.resumable}`);
      continue;
    }
    const resumed = await postJson(`${server.base}/api/runs/${id}/resume`, {});
    if (resumed.status !== 202) notResumable++;
  }
  console.log(`kill ${k}: ${stillLive.length} runs live under ${watchers.length} watchers; rows stored at the kill ` +
    live.map((id) => seen[id].length - 1).join(', '));
}
for (const id of ids) await waitFor(server.base, id, 'completed', 300);
const identical = [];
for (const id of ids) identical.push((await csv(server.base, id)) === referenceCsv);
await server.stop();

console.log(`${kills} kills: ${lostRows} rows lost, ${changedRows} changed, ${duplicatedRows} duplicated; ` +
  `${notResumable} runs not resumable; ${identical.filter(Boolean).length} of ${ids.length} runs identical to the uninterrupted one`);
const allWell = lostRows === 0 && changedRows === 0 && duplicatedRows === 0 && notResumable === 0 && identical.every(Boolean);
// For scripts/reliability's table.
console.log(`figure ${JSON.stringify({
  section: 'server kill', name: `kill -9 of the server, 2 runs x ${WATCHERS} watchers, ${kills} times`,
  value: `${lostRows} lost, ${changedRows} changed, ${duplicatedRows} duplicated; ` +
    `${identical.filter(Boolean).length}/${ids.length} identical after resuming`,
  unit: '', target: '0 lost or duplicated, all identical', ok: allWell })}`);
check(`the server was killed ${kills} times with runs going`, kills >= Math.min(KILLS, 1));
check('no stored row was lost', lostRows === 0, `${lostRows}`);
check('none changed', changedRows === 0, `${changedRows}`);
check('none duplicated', duplicatedRows === 0, `${duplicatedRows}`);
check('every killed run came back interrupted and resumable', notResumable === 0, `${notResumable}`);
check('both runs, resumed to the end, match the uninterrupted run byte for byte', identical.every(Boolean), JSON.stringify(identical));
finish();
