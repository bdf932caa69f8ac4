// A seed gives the same actions in wasm as in the native library: the fixed-seed runs of
// test/native/hot_plate_actions.c (hot plate, discrete and continuous; a cart-pole-shaped agent with
// planning), replayed through the JS API. scripts/test_web.sh builds and runs the native program
// and points VERVE_NATIVE_ACTIONS at its output; without it this test is skipped.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { verve } from './helpers.js';
import { HotPlate } from './hot_plate.js';

export function wasmActions() {
  const lines = [];
  for (const continuous of [false, true]) {
    const task = new HotPlate({ continuous, seed: 1 });
    const agent = verve.createAgent(task.descriptor({ seed: 1 }));
    const actions = [];
    for (let t = 0; t < 30; ++t) task.runTrial(agent, 0.1, 1000, actions);
    lines.push(actions.join(''));
    agent.dispose();
  }
  const agent = verve.createAgent({ continuous: [{}, {}, { circular: true }, {}], actions: 3, planning: true, seed: 11 });
  const actions = [];
  const c = new Float32Array(4);
  let reward = 0;
  for (let i = 0; i < 2000; ++i) {
    for (let k = 0; k < 4; ++k) c[k] = Math.fround(Math.fround(((i * (13 + 7 * k)) % 201) / 100) - 1);
    const action = agent.update(reward, { continuous: c }, 0.02);
    actions.push(action);
    reward = action === 1 ? 0.5 : -0.25;
  }
  lines.push(actions.join(''));
  agent.dispose();
  return lines;
}

const nativeFile = process.env.VERVE_NATIVE_ACTIONS;

test('the same seed gives the same actions as the native library', { skip: !nativeFile && 'VERVE_NATIVE_ACTIONS is not set (scripts/test_web.sh sets it)' }, () => {
  const native = readFileSync(nativeFile, 'utf8').trim().split('\n');
  const wasm = wasmActions();
  assert.equal(native.length, 3);
  ['hot plate, discrete', 'hot plate, continuous', '4 continuous sensors with planning'].forEach((name, i) => {
    const at = [...native[i]].findIndex((ch, k) => ch !== wasm[i][k]);
    assert.equal(wasm[i], native[i], `${name}: ${native[i].length} native actions, first difference at ${at}`);
  });
});
