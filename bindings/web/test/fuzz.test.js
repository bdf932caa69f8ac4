// A fuzz loop over the JS surface: random calls with random, often hostile, arguments on a few
// agents, a brain's bodies and a batch. Every call either succeeds or throws a VerveError; after a
// VerveError the agent's save is unchanged; nothing else is ever thrown and the module never traps.
// VERVE_WEB_FUZZ_ITERATIONS sets the length (default 3000; the seed is printed on failure).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { verve, random } from './helpers.js';

const ITERATIONS = Number(process.env.VERVE_WEB_FUZZ_ITERATIONS ?? 3000);
const SEED = Number(process.env.VERVE_WEB_FUZZ_SEED ?? 20261205);

test(`fuzz: ${ITERATIONS} random calls (seed ${SEED})`, () => {
  const next = random(SEED);
  const pick = (list) => list[Math.floor(next() * list.length)];
  const numbers = () => pick([0, 0.5, -0.7, 1, -1, 2, -3, NaN, Infinity, -Infinity, 1e39, -0, 5e-324, 0.1 * next()]);
  const ints = () => pick([0, 1, 2, 3, -1, 7, 2 ** 31, -(2 ** 31), 1.5, NaN, Math.floor(next() * 10)]);
  const anything = () => pick([undefined, null, '1', {}, [], true, numbers(), ints(), new Float32Array(3), Symbol('x')]);
  const list = (gen) => {
    const n = pick([0, 1, 2, 3, 4, 17, 100]);
    const a = Array.from({ length: n }, gen);
    return next() < 0.2 ? Float32Array.from(a, (x) => (typeof x === "number" ? x : 0)) : a;
  };
  const observation = () => pick([
    () => ({ discrete: list(ints), continuous: list(numbers) }),
    () => ({ discrete: [Math.floor(next() * 4)], continuous: [next() * 2 - 1, next() * 2 - 1] }),
    () => ({ continuous: [next() * 2 - 1, next() * 2 - 1] }),
    () => anything(),
  ])();

  const brain = verve.createBrain({ continuous: 2, actions: 3, seed: 1 });
  const agents = [
    verve.createAgent({ discrete: [4], continuous: [{ circular: true }, {}], actions: 3, seed: 2 }),
    verve.createAgent({ continuous: 2, actions: 2, planning: true, curiosity: 'novelty', seed: 3 }),
    brain.createBody(),
    brain.createBody(),
    verve.createAgent({ continuous: 1, continuousActions: 2, seed: 4 }),
  ];
  const batch = verve.createBatch();
  const calls = [
    (a) => a.update(numbers(), observation(), pick([0.1, 0.02, 0, -1, NaN, anything()])),
    (a) => a.update(numbers(), observation(), 0.1, pick([[true, false, true], [0, 0, 0], list(anything), new Uint8Array(3).fill(1)])),
    (a) => a.endEpisode(pick([numbers(), anything()])),
    (a) => a.truncateEpisode(pick([numbers(), anything()])),
    (a) => a.resetShortTermMemory(),
    (a) => a.setLearning(pick([true, false, anything()])),
    (a) => a.setActionSelection(pick(['sample', 'greedy', anything()])),
    (a) => a.actionProbabilities(pick([undefined, new Float32Array(3), new Float32Array(1), anything()])),
    (a) => a.continuousAction(pick([undefined, new Float32Array(2), new Float32Array(1), new Float32Array(0), anything()])),
    // Descriptors with continuous actions: created, or refused with a VerveError.
    () => verve.createAgent({ continuous: pick([0, 1, 2]), continuousActions: pick([0, 1, 8, 9, -1, 1.5, NaN, ints(), anything()]),
      actions: pick([undefined, 1, 3, 0]), actionBranches: pick([undefined, [2, 2]]), planning: pick([false, true]) }).dispose(),
    (a) => a.sampleValues(pick([[{ kind: 'continuous', index: ints(), samples: ints() }], [{ kind: pick(['discrete', 'continuous', 'x']), index: 0, samples: 5 }, { kind: 'continuous', index: 1, samples: 3 }], anything()]), pick([undefined, observation()])),
    (a) => a.stats(),
    (a) => a.descriptor(),
    (a) => verve.loadAgent(a.saveBinaryBytes()).dispose(),
    (a) => batch.update(pick([agents, agents.slice(0, 2), [a, a], [a, anything()]]), pick([[0, 0, 0, 0], [0, 0], list(numbers)]), pick([agents.map(observation), [observation(), observation()], anything()]), pick([0.1, NaN])),
    // Demonstrated steps in a batch, with the continuous actions played (agents[4] has 2).
    (a) => batch.update([a, pick(agents)], [numbers(), 0], [observation(), observation()], 0.1, undefined,
      pick([[0, null], [null, 0], [0, 0], [ints(), null], anything()]),
      pick([undefined, [[next() * 2 - 1, next() * 2 - 1], [next() * 2 - 1, next() * 2 - 1]], [list(numbers), null], [[], []], anything()])),
  ];

  let refusals = 0;
  for (let i = 0; i < ITERATIONS; ++i) {
    const agent = pick(agents);
    const call = pick(calls);
    const before = agent.saveBinaryBytes();
    try {
      call(agent);
    } catch (e) {
      if (!(e instanceof VerveError)) assert.fail(`iteration ${i} (seed ${SEED}): not a VerveError: ${e?.stack ?? e}`);
      ++refusals;
      // A refused batch may have updated the agents before the failing one's check: never, since a
      // batch checks everything first; so every refusal leaves every agent as it was.
      assert.deepEqual(agent.saveBinaryBytes(), before, `iteration ${i} (seed ${SEED}): ${e.message}`);
    }
  }
  assert.ok(refusals > ITERATIONS / 10, `only ${refusals} refusals`);
  for (const a of agents) a.dispose();
  brain.dispose();
  batch.dispose();
});
