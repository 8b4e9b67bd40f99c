// The Studies form's spec (web/js/study_spec.js): values typed as text become the JSON values
// `grainlab sweep` varies (numbers as numbers, a list such as gravity whole, words as strings),
// the run count is the grid's product or the zip's length, and what the form cannot send is
// refused naming the field the server would name.
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const { parseValues, runCount, sweepSpec } = await import(pathToFileURL(join(process.env.GRAINLAB_WEB, 'js', 'study_spec.js')).href);

assert.deepEqual(parseValues('0.3, 0.5,0.7'), [0.3, 0.5, 0.7]);
assert.deepEqual(parseValues('[0, -9.81], [0, 0]'), [[0, -9.81], [0, 0]]);  // commas inside a list stay
assert.deepEqual(parseValues('box2d, dem, "x, \\"y\\""'), ['box2d', 'dem', 'x, "y"']);  // a quoted comma stays
assert.deepEqual(parseValues('1e-3, true, null'), [0.001, true, null]);
assert.deepEqual(parseValues(' , '), []);
assert.deepEqual(parseValues('1, "abc'), [1, '"abc']);  // an unclosed quote is text

const form = { name: 's', preset: 'circular-quick', mode: 'grid', seeds: '1, 2, 3',
  rows: [{ path: 'material.friction', values: '0.3, 0.5' }, { path: '', values: '' }] };
const spec = sweepSpec(form);
assert.deepEqual(spec, { name: 's', base: { preset: 'circular-quick' },
  vary: { 'material.friction': [0.3, 0.5], seed: [1, 2, 3] } });
assert.equal(runCount(spec), 6);
assert.equal(runCount(sweepSpec({ ...form, seeds: '1, 2', mode: 'zip' })), 2);
assert.equal(sweepSpec({ ...form, mode: 'zip' }).mode, 'zip');

const refusal = (f) => {
  try {
    f();
  } catch (error) {
    return error.field;
  }
  return null;
};
assert.equal(refusal(() => runCount(sweepSpec({ ...form, mode: 'zip' }))), 'vary');  // 2 and 3 values
assert.equal(refusal(() => sweepSpec({ ...form, rows: [{ path: 'material.friction', values: ' ' }] })), 'vary.material.friction');
assert.equal(refusal(() => sweepSpec({ ...form, rows: [{ path: '', values: '1' }] })), 'vary');
assert.equal(refusal(() => sweepSpec({ ...form, rows: [{ path: 'seed', values: '4' }] })), 'vary.seed');
assert.equal(refusal(() => sweepSpec({ ...form, seeds: '', rows: [] })), 'vary');
console.log('study_spec: ok');
