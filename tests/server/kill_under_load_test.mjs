// kill -9 of the server while two runs are running and streaming to WebSocket watchers, again
// and again: after every restart the runs are `interrupted` and resumable, no stored sample is
// lost (every row seen before the kill is still there, unchanged) or duplicated (steps strictly
// increase); resumed until they complete, both runs' series are byte-identical to the same
// scene run once without interruption. Every kill must hit live work: each run is `running`
// right before the SIGKILL and `interrupted` (resumable) after it, each has written a checkpoint
// since it last (re)started (waiting longer than 30 s for one fails the test), and the server is
// killed exactly KILLS times.
//
// usage: node kill_under_load_test.mjs [KILLS=3] [WATCHERS_PER_RUN=10]   (prints the figures)
import { execFileSync } from 'node:child_process';
import { existsSync, statSync } from 'node:fs';
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
const referenceStart = Date.now();
const { body: created } = await postJson(`${reference.base}/api/runs`, scene);
await waitFor(reference.base, created.id, 'completed', 300);
// Each kill lands at most this long after a checkpoint, so that all KILLS of them fit well
// inside one run's time (a run resumes from its checkpoint, so each kill moves it on by at most
// about this much) and the last one still finds the runs going.
const latestKillMs = Math.min(1500, 0.6 * (Date.now() - referenceStart) / KILLS);
console.log(`the uninterrupted run took ${Date.now() - referenceStart} ms: each kill within ${latestKillMs.toFixed(0)} ms of a checkpoint`);
const referenceCsv = await csv(reference.base, created.id);
await reference.stop();

const db = join(TMP, 'kill-under-load', 'grainlab.db');
let server = await startServer(['--db', db, '--max-concurrent', '2']);
const ids = [];
for (let k = 0; k < 2; k++) ids.push((await postJson(`${server.base}/api/runs`, scene)).body.id);

const checkpointPath = (id) => `${db}.checkpoints/run-${id}.bin`;
// Identifies the checkpoint file now on disk (a new one is written aside and renamed over it).
const checkpointStamp = (id) => {
  if (!existsSync(checkpointPath(id))) return '';
  const st = statSync(checkpointPath(id));
  return `${st.ino}:${st.mtimeMs}`;
};
let lostRows = 0;
let changedRows = 0;
let duplicatedRows = 0;
let notResumable = 0;
let noCheckpoint = 0;
let notRunningAtKill = 0;
let kills = 0;
const stampAtStart = Object.fromEntries(ids.map((id) => [id, '']));
for (let k = 1; k <= KILLS; k++) {
  const live = [];
  for (const id of ids) {
    const run = await getJson(`${server.base}/api/runs/${id}`);
    if (['queued', 'running'].includes(run.status)) live.push(id);
  }
  if (live.length === 0) break;
  const watchers = live.flatMap((id) => Array.from({ length: WATCHERS }, () => watch(server.wsBase, id, { light: true })));
  for (const w of watchers) w.done.catch(() => {});  // the kill ends them with an error
  // Kill once every live run has written a checkpoint since it (re)started, at a random moment
  // up to latestKillMs later.
  const fresh = (id) => checkpointStamp(id) !== stampAtStart[id];
  for (let t = 0; t < 600 && !live.every(fresh); t++) await sleep(50);
  for (const id of live) {
    if (fresh(id)) continue;
    noCheckpoint++;
    console.log(`run ${id} before kill ${k}: no new checkpoint within 30 s`);
  }
  await sleep(Math.random() * latestKillMs);
  const seen = {};
  for (const id of live) seen[id] = lines(await csv(server.base, id));
  const runningAtKill = [];
  for (const id of live) if ((await getJson(`${server.base}/api/runs/${id}`)).status === 'running') runningAtKill.push(id);
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
    // A kill of live work finds the run running and leaves it interrupted.
    if (!runningAtKill.includes(id) || run.status !== 'interrupted') {
      notRunningAtKill++;
      console.log(`run ${id} at kill ${k}: ${runningAtKill.includes(id) ? 'running' : 'not running'} before, ${run.status} after`);
    }
    if (run.status === 'completed') continue;
    if (run.status !== 'interrupted' || !run.resumable) {
      notResumable++;
      console.log(`run ${id} after kill ${k}: ${run.status}, resumable ${run.resumable}`);
      continue;
    }
    stampAtStart[id] = checkpointStamp(id);
    const resumed = await postJson(`${server.base}/api/runs/${id}/resume`, {});
    if (resumed.status !== 202) notResumable++;
  }
  console.log(`kill ${k}: ${runningAtKill.length} runs running under ${watchers.length} watchers; rows stored at the kill ` +
    live.map((id) => seen[id].length - 1).join(', '));
}
for (const id of ids) await waitFor(server.base, id, 'completed', 300);
const identical = [];
for (const id of ids) identical.push((await csv(server.base, id)) === referenceCsv);
await server.stop();

console.log(`${kills} kills: ${lostRows} rows lost, ${changedRows} changed, ${duplicatedRows} duplicated; ` +
  `${notResumable} runs not resumable; ${identical.filter(Boolean).length} of ${ids.length} runs identical to the uninterrupted one`);
const allWell = kills === KILLS && notRunningAtKill === 0 && noCheckpoint === 0 && lostRows === 0 && changedRows === 0 && duplicatedRows === 0 && notResumable === 0 && identical.every(Boolean);
// For scripts/reliability's table.
console.log(`figure ${JSON.stringify({
  section: 'server kill', name: `kill -9 of the server, 2 runs x ${WATCHERS} watchers, ${kills} times`,
  value: `${lostRows} lost, ${changedRows} changed, ${duplicatedRows} duplicated; ` +
    `${identical.filter(Boolean).length}/${ids.length} identical after resuming`,
  unit: '', target: '0 lost or duplicated, all identical', ok: allWell })}`);
check(`the server was killed ${kills} times (${KILLS} asked for)`, kills === KILLS);
check('every kill found every unfinished run running and left it interrupted', notRunningAtKill === 0, `${notRunningAtKill}`);
check('every run wrote a checkpoint before each kill', noCheckpoint === 0, `${noCheckpoint}`);
check('no stored row was lost', lostRows === 0, `${lostRows}`);
check('none changed', changedRows === 0, `${changedRows}`);
check('none duplicated', duplicatedRows === 0, `${duplicatedRows}`);
check('every killed run came back interrupted and resumable', notResumable === 0, `${notResumable}`);
check('both runs, resumed to the end, match the uninterrupted run byte for byte', identical.every(Boolean), JSON.stringify(identical));
finish();
