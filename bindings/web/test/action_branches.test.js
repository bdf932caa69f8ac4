// Action branches (actionBranches: [3, 2]): several choices per step, one combined action (from 0,
// branch 0 fastest). Masks and actionProbabilities() hold one entry per choice of each branch,
// branch after branch; splitAction/joinAction convert; saves keep the branches; refusals change nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { refused, verve } from './helpers.js';

const npc = (extra = {}) => ({ continuous: 2, actionBranches: [3, 2], seed: 5, ...extra });
const obs = (step) => ({ continuous: [Math.sin(step * 0.37), Math.cos(step * 0.21) * 0.9] });

test('one action set is the default: no branches', () => {
  assert.deepEqual(verve.defaults().actionBranches, []);
  const plain = verve.createAgent({ actions: 4 });
  assert.equal(plain.numChoices, 4);
  assert.deepEqual(plain.splitAction(3), [3]);
  assert.equal(plain.joinAction([3]), 3);
  plain.dispose();
});

test('branches without actions: the library sets actions to their product', () => {
  const agent = verve.createAgent(npc());
  const back = agent.descriptor();
  assert.equal(back.actions, 6);
  assert.deepEqual(back.actionBranches, [3, 2]);
  assert.equal(agent.numActions, 6);
  assert.equal(agent.numChoices, 5);
  const twin = verve.createAgent(back);
  assert.deepEqual(twin.descriptor(), back);
  const explicit = verve.createAgent(npc({ actions: 6, actionBranches: new Uint32Array([3, 2]) }));
  assert.deepEqual(explicit.descriptor().actionBranches, [3, 2]);
  for (const a of [agent, twin, explicit]) a.dispose();
});

test('a per-branch mask holds every step; probabilities per branch sum to 1', () => {
  const agent = verve.createAgent(npc());
  const mask = [true, false, true, false, true];  // branch 0: choices 0 and 2; branch 1: choice 1 only
  for (let step = 0; step < 200; ++step) {
    const a = agent.update(step % 5 === 0 ? 1 : 0, obs(step), 0.1, mask);
    const [c0, c1] = agent.splitAction(a);
    assert.ok((c0 === 0 || c0 === 2) && c1 === 1, `action ${a} is [${c0}, ${c1}]`);
  }
  const p = agent.actionProbabilities();
  assert.equal(p.length, 5);
  assert.ok(Math.abs(p[0] + p[1] + p[2] - 1) < 1e-5 && Math.abs(p[3] + p[4] - 1) < 1e-5, String(p));
  assert.equal(p[1], 0);
  assert.equal(p[3], 0);
  const out = new Float32Array(5);
  assert.equal(agent.actionProbabilities(out), out);
  agent.dispose();
});

test('split and join round trip, branch 0 fastest', () => {
  const agent = verve.createAgent(npc());
  for (let a = 0; a < 6; ++a) assert.equal(agent.joinAction(agent.splitAction(a)), a);
  assert.deepEqual(agent.splitAction(1), [1, 0]);
  assert.deepEqual(agent.splitAction(3), [0, 1]);
  assert.equal(agent.joinAction([2, 1]), 5);
  // a demonstrated action is a combined one, within the mask
  agent.updateDemonstrated(0, obs(0), 0.1, agent.joinAction([2, 1]), [true, false, true, false, true]);
  agent.dispose();
});

test('saves (XML and binary) keep the branches; loaded copies act the same', () => {
  const agent = verve.createAgent(npc());
  for (let step = 0; step < 100; ++step) agent.update(step % 7 === 0 ? 1 : 0, obs(step), 0.1);
  const copies = [verve.loadAgent(agent.saveBytes()), verve.loadAgent(agent.saveBinaryBytes())];
  for (const copy of copies) {
    assert.deepEqual(copy.descriptor().actionBranches, [3, 2]);
    assert.equal(copy.numChoices, 5);
  }
  for (let step = 100; step < 140; ++step) {
    const action = agent.update(0, obs(step), 0.1);
    for (const copy of copies) assert.equal(copy.update(0, obs(step), 0.1), action);
  }
  for (const a of [agent, ...copies]) a.dispose();
});

test("a brain's bodies take branches too", () => {
  const brain = verve.createBrain(npc());
  const body = brain.createBody();
  const [c0] = body.splitAction(body.update(0, obs(0), 0.1, [0, 1, 0, 1, 1]));
  assert.equal(c0, 1);
  body.dispose();
  brain.dispose();
});

test("docs/web.md's branched NPC, as written there", () => {
  const reward = 0, dt = 0.1, readings = [0.2, -0.5];
  // move: 0 left, 1 stay, 2 right; turn: 0 left, 1 none, 2 right; use: 0 no, 1 yes
  const npc = verve.createAgent({ continuous: 2, actionBranches: [3, 3, 2] });  // actions: 18
  const allowed = [1, 1, 1,  1, 1, 1,  1, 0];                                  // 'use' is not ready yet
  const action = npc.update(reward, { continuous: readings }, dt, allowed);
  const [move, turn, use] = npc.splitAction(action);
  assert.ok(use === 0 && move < 3 && turn < 3);
  assert.equal(npc.joinAction([move, turn, use]), action);
  assert.equal(npc.actionProbabilities().length, 3 + 3 + 2);
  npc.dispose();
});

test('refusals: bad branches, a wrong product, bad masks, bad choices', () => {
  const bad = [
    [{ actionBranches: 3 }, /actionBranches must be an array of choice counts/],
    [{ actionBranches: [3, 0] }, /actionBranches\[1\] must be a number of choices, at least 1 \(got number 0\)/],
    [{ actionBranches: [3, 1.5] }, /actionBranches\[1\] must be a number of choices/],
    [{ actionBranches: [2, 2, 2, 2, 2, 2, 2, 2, 2] }, /actionBranches has 9 branches, at most 8/],
    [{ actions: 5 }, /product/],
    [{ planning: true }, /planning/],
  ];
  for (const [extra, pattern] of bad) {
    assert.throws(() => verve.createAgent(npc(extra)), (e) => e instanceof VerveError && pattern.test(e.message), JSON.stringify(extra));
  }
  const agent = verve.createAgent(npc());
  agent.update(0, obs(0), 0.1);
  refused(agent, () => agent.update(0, obs(1), 0.1, [1, 1, 1, 1, 1, 1]), 'VERVE_ERROR_INVALID_ARGUMENT',
    /the action mask has 6 entries, the agent's action branches \[3, 2\] have 5 choices/);
  refused(agent, () => agent.update(0, obs(1), 0.1, [1, 1, 1, 0, 0]));  // branch 1 allows nothing
  refused(agent, () => agent.updateDemonstrated(0, obs(1), 0.1, agent.joinAction([1, 1]), [1, 0, 1, 0, 1]));
  refused(agent, () => agent.splitAction(6), 'VERVE_ERROR_INVALID_ARGUMENT', /action must be an integer in 0\.\.5/);
  refused(agent, () => agent.joinAction([3, 0]), 'VERVE_ERROR_INVALID_ARGUMENT', /out of range/);
  refused(agent, () => agent.joinAction([1, 1, 1]), 'VERVE_ERROR_INVALID_ARGUMENT', /one per branch/);
  refused(agent, () => agent.joinAction([1, -1]), 'VERVE_ERROR_INVALID_ARGUMENT', /choices\[1\] must be an integer from 0/);
  assert.ok(agent.update(0, obs(2), 0.1) < 6);
  agent.dispose();
});
