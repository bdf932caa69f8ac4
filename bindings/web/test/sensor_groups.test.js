// Sensor groups (grouping: 'auto' | 'joint' | 'custom', sensorGroups: [[0, 1], [2]]): what reaches
// the library, what comes back, saves, and the refusals. Full allocation makes the lattices' sizes
// visible: resolution^(sensors in the group) RBFs per group, created with the agent.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { verve } from './helpers.js';

const npc = (n, extra = {}) => ({ continuous: n, actions: 4, seed: 3, ...extra });
const readings = (step, n) => Array.from({ length: n }, (_, i) => Math.sin(step * (0.31 + 0.17 * (i + 1)) + i + 1));

test('auto is the default, with no groups', () => {
  const d = verve.defaults();
  assert.equal(d.grouping, 'auto');
  assert.deepEqual(d.sensorGroups, []);
});

test('auto gives 12 sensors a lattice per sensor and per neighbouring pair', () => {
  const agent = verve.createAgent(npc(12, { allocation: 'full', resolution: 10 }));
  assert.equal(agent.rbfCount(), 12 * 10 + 11 * 10 * 10);
  assert.equal(agent.descriptor().grouping, 'auto');
  assert.deepEqual(agent.descriptor().sensorGroups, []);
  agent.dispose();
});

test('joint over 12 sensors is one lattice: too large to allocate in full', () => {
  assert.throws(() => verve.createAgent(npc(12, { grouping: 'joint', allocation: 'full' })),
    (e) => e instanceof VerveError && /full rbf_allocation/.test(e.message));
  const agent = verve.createAgent(npc(12, { grouping: 'joint' }));
  assert.equal(agent.descriptor().grouping, 'joint');
  agent.dispose();
});

test('auto keeps memory bounded where one joint lattice keeps growing', () => {
  const rbfsAfter = (grouping) => {
    const agent = verve.createAgent(npc(12, { grouping }));
    for (let step = 0; step < 3000; ++step) agent.update(0, { continuous: readings(step, 12) }, 0.1);
    const n = agent.rbfCount();
    agent.dispose();
    return n;
  };
  const auto = rbfsAfter('auto');
  const joint = rbfsAfter('joint');
  assert.ok(auto <= 12 * 10 + 11 * 10 * 10, `auto: ${auto}`);
  assert.ok(joint > 2 * auto, `joint: ${joint}, auto: ${auto}`);
});

test('custom groups (indices from 0) reach the library and come back', () => {
  const groups = Array.from({ length: 12 }, (_, i) => [i]);
  groups.push([1, 0]);  // any order
  const agent = verve.createAgent(npc(12, { allocation: 'full', resolution: 10, sensorGroups: groups }));
  assert.equal(agent.rbfCount(), 12 * 10 + 10 * 10);
  const back = agent.descriptor();
  assert.equal(back.grouping, 'custom', "sensorGroups alone mean grouping 'custom'");
  assert.deepEqual(back.sensorGroups, [...groups.slice(0, 12), [0, 1]]);
  const twin = verve.createAgent(back);
  assert.deepEqual(twin.descriptor(), back);
  assert.equal(twin.rbfCount(), agent.rbfCount());
  const explicit = verve.createAgent(npc(2, { grouping: 'custom', sensorGroups: [new Uint8Array([0, 1])] }));
  assert.deepEqual(explicit.descriptor().sensorGroups, [[0, 1]]);
  for (const a of [agent, twin, explicit]) a.dispose();
});

test('saves (XML and binary) keep the groups; loaded copies act the same', () => {
  const groups = [[0, 1], [2, 3, 4], [5], [0, 5]];
  const agent = verve.createAgent(npc(6, { seed: 11, sensorGroups: groups }));
  for (let step = 0; step < 200; ++step) agent.update(step % 7 === 0 ? 1 : 0, { continuous: readings(step, 6) }, 0.1);
  const copies = [verve.loadAgent(agent.saveBytes()), verve.loadAgent(agent.saveBinaryBytes())];
  for (const copy of copies) {
    assert.equal(copy.descriptor().grouping, 'custom');
    assert.deepEqual(copy.descriptor().sensorGroups, groups);
    assert.equal(copy.rbfCount(), agent.rbfCount());
  }
  for (let step = 200; step < 260; ++step) {
    const obs = { continuous: readings(step, 6) };
    const action = agent.update(0, obs, 0.1);
    for (const copy of copies) assert.equal(copy.update(0, obs, 0.1), action);
  }
  for (const a of [agent, ...copies]) a.dispose();
});

test('a brain takes groups too', () => {
  const brain = verve.createBrain(npc(3, { sensorGroups: [[0, 1], [2]] }));
  const body = brain.createBody();
  body.update(0, { continuous: [0.1, 0.2, 0.3] }, 0.1);
  assert.deepEqual(body.descriptor().sensorGroups, [[0, 1], [2]]);
  body.dispose();
  brain.dispose();
});

test("docs/web.md's 12-sensor NPCs, as written there", () => {
  const npc = verve.createAgent({ continuous: 12, actions: 4 });   // 'auto': 12 single lattices, 11 pairs

  const groups = [];
  for (let i = 0; i < 12; ++i) groups.push([i]);          // each sensor alone
  for (let i = 0; i < 7; ++i) groups.push([i, i + 1]);    // neighbouring rays
  groups.push([7, 0], [8, 9]);                            // the ring closes; bearing with distance
  const custom = verve.createAgent({ continuous: 12, actions: 4, sensorGroups: groups });  // 'custom'

  assert.equal(npc.descriptor().grouping, 'auto');
  assert.equal(custom.descriptor().grouping, 'custom');
  assert.equal(custom.descriptor().sensorGroups.length, 12 + 7 + 2);
  for (const a of [npc, custom]) {
    assert.ok(a.update(0, { continuous: readings(1, 12) }, 0.1) < 4);
    a.dispose();
  }
});

test('refusals name the group and the sensor', () => {
  const bad = [
    [{ grouping: 'pairs' }, /grouping must be one of 'auto', 'joint', 'custom'/],
    [{ sensorGroups: 3 }, /sensorGroups must be an array of groups/],
    [{ sensorGroups: [1, 2] }, /sensorGroups\[0\] must be an array of continuous sensor indices/],
    [{ sensorGroups: [[0, 1], []] }, /sensorGroups\[1\] is empty/],
    [{ sensorGroups: [[0, -1]] }, /sensorGroups\[0\]\[1\] must be a continuous sensor index from 0 to 63 \(got number -1\)/],
    [{ sensorGroups: [[64]] }, /from 0 to 63 \(got number 64\)/],
    [{ sensorGroups: [[0.5]] }, /from 0 to 63/],
    [{ sensorGroups: [['0']] }, /from 0 to 63 \(got string\)/],
    [{ sensorGroups: [[0, 1, 0]] }, /sensorGroups\[0\] lists continuous sensor 0 twice/],
    [{ sensorGroups: [[0, 1], [2, 3, 4]] }, /sensorGroups\[1\] lists continuous sensor 4, but the agent has 4/],
    [{ sensorGroups: [[0, 1], [2]] }, /continuous sensor 3 is in none of descriptor.sensorGroups/],
    [{ grouping: 'custom' }, /grouping 'custom' needs sensorGroups/],
    [{ grouping: 'joint', sensorGroups: [[0, 1, 2, 3]] }, /sensorGroups is only used with grouping 'custom' \(got 'joint'\)/],
    [{ sensorGroups: Array.from({ length: 65 }, () => [0]) }, /65 groups, at most 64/],
  ];
  for (const [extra, pattern] of bad) {
    assert.throws(() => verve.createAgent(npc(4, extra)), (e) => e instanceof VerveError && e.code === 'VERVE_ERROR_INVALID_ARGUMENT' && pattern.test(e.message), JSON.stringify(extra));
    assert.throws(() => verve.createBrain(npc(4, extra)), VerveError);
  }
  verve.createAgent(npc(1, { sensorGroups: Array.from({ length: 64 }, () => [0]) })).dispose();  // 64, repeated: allowed
  verve.createAgent({ discrete: [3], grouping: 'custom' }).dispose();  // no continuous sensors: no group needed
});
