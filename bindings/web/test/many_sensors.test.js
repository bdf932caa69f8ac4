// 32 sensors of each kind (up to 64; issue 30): the descriptor round trip through the struct's V8
// arrays, saves that act the same, a batch that acts as each agent alone, and the lattice limit.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { verve } from './helpers.js';

const N = 32;
const desc = (extra = {}) => ({
  discrete: Array.from({ length: N }, (_, i) => (i % 8 === 0 ? 2 : 1)),
  continuous: Array.from({ length: N }, (_, i) => ({ circular: i % 5 === 0 })),
  actions: 4,
  seed: 5,
  ...extra,
});
const obs = (step) => ({
  discrete: Array.from({ length: N }, (_, i) => (i % 8 === 0 ? (Math.floor(step / 3) + i) % 2 : 0)),
  continuous: Array.from({ length: N }, (_, i) => 0.9 * Math.sin(0.1 * step * (0.3 + 0.17 * i) + i)),
});

test('32 sensors of each kind come back, and saves act the same', () => {
  const agent = verve.createAgent(desc());
  const d = agent.descriptor();
  assert.deepEqual(d.discrete, desc().discrete);
  assert.deepEqual(d.continuous, desc().continuous);
  for (let step = 0; step < 200; ++step) agent.update(Math.sin(0.05 * step), obs(step), 0.1);
  assert.ok(agent.rbfCount() >= 63, `${agent.rbfCount()} RBFs`);  // auto: 32 singles + 31 pairs
  let step = 200;
  for (const save of ['saveString', 'saveBinaryBytes']) {
    const copy = verve.loadAgent(agent[save]());
    assert.deepEqual(copy.descriptor().continuous, desc().continuous);
    for (let k = 0; k < 60; ++k, ++step) assert.equal(copy.update(0, obs(step), 0.1), agent.update(0, obs(step), 0.1));
    copy.dispose();
  }
  agent.dispose();
});

test('a batch of 32-sensor agents acts as each alone', () => {
  const solo = verve.createAgent(desc());
  const agents = [verve.createAgent(desc()), verve.createAgent(desc())];
  const batch = verve.createBatch();
  for (let step = 0; step < 100; ++step) {
    const expected = solo.update(0.1, obs(step), 0.1);
    assert.deepEqual(Array.from(batch.update(agents, [0.1, 0.1], [obs(step), obs(step)], 0.1)), [expected, expected]);
  }
  for (const x of [solo, ...agents, batch]) x.dispose();
});

test('over 64 sensors, or one lattice over more than 16, is refused', () => {
  assert.throws(() => verve.createAgent({ continuous: 65 }), (e) => e instanceof VerveError && /continuous/.test(e.message));
  assert.throws(() => verve.createAgent(desc({ grouping: 'joint' })),
    (e) => e instanceof VerveError && /which spans at most 16/.test(e.message));
  const groups = [0, 1, 2, 3].map((g) => Array.from({ length: 16 }, (_, k) => 16 * g + k));
  const agent = verve.createAgent({ continuous: 64, actions: 2, sensorGroups: groups });
  agent.update(0, { continuous: new Array(64).fill(0.5) }, 0.1);
  assert.deepEqual(agent.descriptor().sensorGroups, groups);
  agent.dispose();
});
