// Learning through the binding, as the C and Lua suites test it: the 1D hot plate (thesis chapter
// 5), where the best policy needs 5 steps on average and a random one about 50.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { verve } from './helpers.js';
import { HotPlate } from './hot_plate.js';

const RUNS = 5;
const TRIALS = 40;

function mean(list, first, last) {
  let sum = 0;
  for (let i = first; i <= last; ++i) sum += list[i];
  return sum / (last - first + 1);
}

for (const continuous of [false, true]) {
  test(`hot plate, ${continuous ? 'continuous' : 'discrete'} sensor: steps to an edge fall`, () => {
    const steps = new Array(TRIALS).fill(0);
    let agent;
    for (let run = 1; run <= RUNS; ++run) {
      agent?.dispose();
      const task = new HotPlate({ continuous, seed: run });
      agent = verve.createAgent(task.descriptor({ seed: run }));
      for (let t = 0; t < TRIALS; ++t) steps[t] += task.runTrial(agent, 0.1, 1000) / RUNS;
    }
    const early = mean(steps, 0, 4);
    const late = mean(steps, TRIALS - 10, TRIALS - 1);
    assert.ok(late < 10, `late trials still take ${late} steps`);
    assert.ok(late < early / 2, `no clear improvement: ${early} -> ${late}`);
    const axis = continuous ? { kind: 'continuous', index: 0, samples: 20 } : { kind: 'discrete', index: 0, samples: 20 };
    const v = agent.sampleValues([axis]);
    assert.ok(v[1] > v[9] && v[18] > v[10], `values ${v[1]} ${v[9]} ${v[10]} ${v[18]}`);
    agent.dispose();
  });
}

test('10-armed bandit: the best lever becomes the most probable', () => {
  const means = [0.1, -0.3, 0.2, 0.9, -0.1, 0.0, 0.3, -0.5, 0.4, 0.2];  // lever 3 is best
  const agent = verve.createAgent({ actions: 10, seed: 7 });
  let state = 12345;
  const noise = () => {
    state = (state * 16807) % 2147483647;
    return (state / 2147483647 - 0.5) * 0.4;
  };
  for (let i = 0; i < 2000; ++i) {
    const lever = agent.update(0, null, 0.1);
    agent.endEpisode(Math.max(-1, Math.min(1, means[lever] + noise())));
  }
  agent.update(0, null, 0.1);
  const p = agent.actionProbabilities();
  const best = p.indexOf(Math.max(...p));
  assert.equal(best, 3, `probabilities ${Array.from(p, (x) => x.toFixed(2))}`);
  agent.setActionSelection('greedy');
  assert.equal(agent.update(0, null, 0.1), 3);
  agent.dispose();
});

// A brain of two continuous sensors and three actions with three bodies, and what body i senses at t.
function brainOfThree() {
  const brain = verve.createBrain({ continuous: 2, actions: 3, seed: 3 });
  return { brain, bodies: [brain.createBody(), brain.createBody(), brain.createBody()] };
}
const obs = (i, t) => ({ continuous: [Math.sin(t * 0.1 + i), Math.cos(t * 0.07 - i)] });

test('a batch does exactly what updates in order do for separate agents', () => {
  const make = () => [0, 1, 2].map((i) => verve.createAgent({ continuous: 2, actions: 3, seed: 3 + i }));
  const a = make();
  const b = make();
  const batch = verve.createBatch();
  for (let t = 0; t < 200; ++t) {
    const rewards = [0.1 * Math.sin(t), -0.2, 0.3];
    const one = a.map((agent, i) => agent.update(rewards[i], obs(i, t), 0.05));
    const many = batch.update(b, rewards, b.map((_, i) => obs(i, t)), 0.05);
    assert.deepEqual(Array.from(many), one, `step ${t}`);
  }
  a.forEach((agent, i) => assert.deepEqual(agent.saveBinaryBytes(), b[i].saveBinaryBytes()));
  for (const agent of [...a, ...b]) agent.dispose();
  batch.dispose();
});

// A brain's bodies in a batch act against the brain as the call found it, their changes applied in
// order (docs/crowds.md, "Bodies in parallel"): the same calls give the same brain, and it learns.
test('brains: bodies learn into one brain in a batch, the same calls the same brain', () => {
  const a = brainOfThree();
  const b = brainOfThree();
  const fresh = a.brain.saveBinaryBytes();
  const batch = verve.createBatch();
  for (let t = 0; t < 200; ++t) {
    const rewards = [0.1 * Math.sin(t), -0.2, 0.3];
    const first = batch.update(a.bodies, rewards, a.bodies.map((_, i) => obs(i, t)), 0.05);
    const second = batch.update(b.bodies, rewards, b.bodies.map((_, i) => obs(i, t)), 0.05);
    assert.deepEqual(Array.from(second), Array.from(first), `step ${t}`);
  }
  assert.ok(a.brain.rbfCount() > 0);
  assert.equal(a.brain.rbfCount(), b.brain.rbfCount());
  assert.notDeepEqual(a.brain.saveBinaryBytes(), fresh);
  assert.deepEqual(a.brain.saveBinaryBytes(), b.brain.saveBinaryBytes());
  const copy = verve.loadBrain(a.brain.saveBytes());
  assert.equal(copy.rbfCount(), a.brain.rbfCount());
  a.brain.dispose();  // the bodies keep it alive in the library
  assert.equal(typeof a.bodies[0].update(0, obs(0, 0), 0.05), 'number');
  for (const x of [a, b]) for (const body of x.bodies) body.dispose();
  b.brain.dispose();
  copy.dispose();
  batch.dispose();
});

test('a batch with demonstrated actions does what updateDemonstrated and update in order do', () => {
  const a = brainOfThree();
  const b = brainOfThree();
  const batch = verve.createBatch();
  for (let t = 0; t < 60; ++t) {
    const rewards = [0.1, -0.2, 0.3];
    const shown = [null, t % 3, null];
    const one = a.bodies.map((body, i) => {
      if (shown[i] === null) return body.update(rewards[i], obs(i, t), 0.05);
      body.updateDemonstrated(rewards[i], obs(i, t), 0.05, shown[i]);
      return shown[i];
    });
    const many = batch.update(b.bodies, rewards, b.bodies.map((_, i) => obs(i, t)), 0.05, undefined, shown);
    assert.deepEqual(Array.from(many), one, `step ${t}`);
  }
  assert.deepEqual(a.brain.saveBinaryBytes(), b.brain.saveBinaryBytes());
  assert.throws(() => batch.update(b.bodies, [0, 0, 0], b.bodies.map((_, i) => obs(i, 0)), 0.05, undefined, [3, null, null]),
    /demonstrated\[0\]/);
  assert.throws(() => batch.update(b.bodies, [0, 0, 0], b.bodies.map((_, i) => obs(i, 0)), 0.05, undefined, [null]), /demonstrated/);
  for (const x of [a, b]) { for (const body of x.bodies) body.dispose(); x.brain.dispose(); }
  batch.dispose();
});
