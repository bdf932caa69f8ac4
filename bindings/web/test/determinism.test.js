// The wasm module against the native library, through test/native/hot_plate_actions.c, which
// scripts/test_web.sh builds and names in VERVE_NATIVE_PROGRAM (without it these tests are skipped):
// a seed gives the same actions (the hot plate, discrete and continuous; a cart-pole-shaped agent
// with planning), and saves move both ways in both formats.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { verve } from './helpers.js';
import { HotPlate } from './hot_plate.js';

const program = process.env.VERVE_NATIVE_PROGRAM;
const skip = !program && 'VERVE_NATIVE_PROGRAM is not set (scripts/test_web.sh sets it)';
const native = (...args) => execFileSync(program, args, { encoding: 'utf8' });

function hotPlateActions(agent, continuous, seed, trials) {
  const task = new HotPlate({ continuous, seed });
  const actions = [];
  for (let t = 0; t < trials; ++t) task.runTrial(agent, 0.1, 1000, actions);
  return actions.join('');
}

function wasmActions() {
  const lines = [];
  for (const continuous of [false, true]) {
    const agent = verve.createAgent(new HotPlate({ continuous }).descriptor({ seed: 1 }));
    lines.push(hotPlateActions(agent, continuous, 1, 30));
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

/** Greedy actions of 5 trials from start seed 9, as `hot_plate_actions play` runs them. */
function play(agent) {
  agent.setActionSelection('greedy');
  return hotPlateActions(agent, true, 9, 5);
}

test('the same seed gives the same actions as the native library', { skip }, () => {
  const expected = native().trim().split('\n');
  const wasm = wasmActions();
  assert.equal(expected.length, 3);
  ['hot plate, discrete', 'hot plate, continuous', '4 continuous sensors with planning'].forEach((name, i) => {
    const at = [...expected[i]].findIndex((ch, k) => ch !== wasm[i][k]);
    assert.equal(wasm[i], expected[i], `${name}: ${expected[i].length} native actions, first difference at ${at}`);
  });
});

test('saves move between the native library and wasm, XML and binary, both ways', { skip }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'verve-web-'));
  try {
    native('save', dir);
    for (const name of ['native.xml', 'native.bin']) {
      const agent = verve.loadAgent(readFileSync(join(dir, name)));
      assert.equal(play(agent), native('play', join(dir, name)).trim(), name);
      agent.dispose();
    }
    const agent = verve.createAgent(new HotPlate({ continuous: true }).descriptor({ seed: 2 }));
    hotPlateActions(agent, true, 2, 10);
    writeFileSync(join(dir, 'wasm.xml'), agent.saveString());
    writeFileSync(join(dir, 'wasm.bin'), agent.saveBinaryBytes());
    const greedy = play(agent);
    for (const name of ['wasm.xml', 'wasm.bin']) assert.equal(native('play', join(dir, name)).trim(), greedy, name);
    agent.dispose();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
