// What the docs promise the JavaScript API shows (docs/tuning.md, "Rewards"): clampedRewards and
// rbfBudgetHits in agent.stats(), and libverve's log warnings through verve.takeWarnings().
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { verve } from './helpers.js';

const find = (list, text) => list.find((message) => message.includes(text));

test('takeWarnings() starts empty and stays empty while nothing is wrong', () => {
  assert.deepEqual(verve.takeWarnings(), []);
  const agent = verve.createAgent({ discrete: [3], actions: 2 });
  agent.update(0.5, { discrete: [0] }, 0.1);
  agent.update(-1, { discrete: [1] }, 0.1);
  assert.deepEqual(verve.takeWarnings(), []);
  agent.dispose();
});

test('a reward outside [-1, 1]: counted in clampedRewards, warned once per agent', () => {
  const agent = verve.createAgent({ discrete: [3], actions: 2 });
  agent.update(0, { discrete: [0] }, 0.1);
  agent.update(5, { discrete: [1] }, 0.1);
  agent.update(-7, { discrete: [2] }, 0.1);
  const s = agent.stats();
  assert.equal(s.clampedRewards, 2);
  assert.equal(s.rbfBudgetHits, 0);
  const w = verve.takeWarnings();
  assert.equal(w.length, 1, w.join(' | '));
  assert.ok(find(w, 'a reward of 5 was clamped to [-1, 1]'), w[0]);
  assert.deepEqual(verve.takeWarnings(), [], 'a second read returns what came since the first');
  agent.dispose();
});

test('the RBF budget reached: counted in rbfBudgetHits, warned once per agent', () => {
  const agent = verve.createAgent({ continuous: 1, actions: 2, resolution: 10, maxRbfs: 2 });
  for (let i = 0; i <= 20; ++i) agent.update(0, { continuous: [-1 + i * 0.1] }, 0.1);
  const s = agent.stats();
  assert.ok(s.rbfCount <= 2, `rbfCount = ${s.rbfCount}`);
  assert.ok(s.rbfBudgetHits > 0, `rbfBudgetHits = ${s.rbfBudgetHits}`);
  assert.equal(s.clampedRewards, 0);
  const w = verve.takeWarnings();
  assert.ok(w.length === 1 && find(w, 'the RBF budget (max_rbfs = 2) is reached'), w.join(' | '));
  agent.dispose();
});

test('more warnings than are kept between reads: the rest are counted', () => {
  const agents = [];
  for (let i = 0; i < 70; ++i) {
    agents.push(verve.createAgent({ discrete: [2], actions: 2 }));
    agents[i].update(2, { discrete: [0] }, 0.1);
  }
  const w = verve.takeWarnings();
  assert.equal(w.length, 65);
  assert.equal(w[64], '6 more warnings were dropped (at most 64 are kept between reads)');
  for (const agent of agents) agent.dispose();
});
