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
import { fixedRuns, hotPlateActions } from './fixed_runs.js';

const program = process.env.VERVE_NATIVE_PROGRAM;
const skip = !program && 'VERVE_NATIVE_PROGRAM is not set (scripts/test_web.sh sets it)';
const native = (...args) => execFileSync(program, args, { encoding: 'utf8' });

/** Greedy actions of 5 trials from start seed 9, as `hot_plate_actions play` runs them. */
function play(agent) {
  agent.setActionSelection('greedy');
  return hotPlateActions(agent, true, 9, 5);
}

test('the same seed gives the same actions as the native library', { skip }, () => {
  const expected = native().trim().split('\n');
  const wasm = fixedRuns(verve);
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
