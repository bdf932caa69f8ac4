// Every bad input gives a clear VerveError and changes nothing: the binding's own checks (types,
// lengths, disposed handles) and the library's (NaN, counts, ranges), whose message it carries.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { verve, refused } from './helpers.js';

function trained() {
  const agent = verve.createAgent({ discrete: [4], continuous: [{ circular: true }, {}], actions: 3, seed: 5 });
  for (let i = 0; i < 30; ++i) agent.update(0.1 * (i % 3), { discrete: [i % 4], continuous: [Math.sin(i), 0.3] }, 0.1);
  return agent;
}

test('updates: NaN, infinities, wrong counts and types, absurd lengths', () => {
  const agent = trained();
  const ok = { discrete: [1], continuous: [0.1, 0.2] };
  refused(agent, () => agent.update(NaN, ok, 0.1), undefined, /reward must be finite/);
  refused(agent, () => agent.update(0, ok, Infinity), undefined, /dt/);
  refused(agent, () => agent.update(0, ok, 0), undefined, /dt/);
  refused(agent, () => agent.update(0, ok, -1), undefined, /dt/);
  refused(agent, () => agent.update(1e39, ok, 0.1), undefined, /reward must be finite/);  // float32 infinity
  refused(agent, () => agent.update(0, { discrete: [1], continuous: [NaN, 0] }, 0.1), undefined, /continuous/);
  refused(agent, () => agent.update(0, { discrete: [4], continuous: [0, 0] }, 0.1), undefined, /valid values are 0..3/);
  refused(agent, () => agent.update(0, { discrete: [-1], continuous: [0, 0] }, 0.1));
  refused(agent, () => agent.update(0, { discrete: [1], continuous: [0] }, 0.1), undefined, /1 continuous values, the agent has 2/);
  refused(agent, () => agent.update(0, { continuous: [0, 0] }, 0.1), undefined, /discrete/);
  refused(agent, () => agent.update(0, { discrete: [1.5], continuous: [0, 0] }, 0.1), undefined, /integer/);
  refused(agent, () => agent.update(0, { discrete: ['1'], continuous: [0, 0] }, 0.1), undefined, /integer/);
  refused(agent, () => agent.update(0, { discrete: [1], continuous: ['0.5', 0] }, 0.1), undefined, /number/);
  refused(agent, () => agent.update('0', ok, 0.1), undefined, /reward must be a number/);
  refused(agent, () => agent.update(0, ok), undefined, /dt must be a number/);
  refused(agent, () => agent.update(0, [1, 2], 0.1), undefined, /object/);
  refused(agent, () => agent.update(0, { discrete: [1], continuous: new Array(1e7).fill(0) }, 0.1), undefined, /at most 64/);
  refused(agent, () => agent.update(0, { discrete: { length: 2 ** 32 - 1 } }, 0.1), undefined, /array/);
  refused(agent, () => agent.update(0, ok, 0.1, [true, false]), undefined, /mask has 2 entries/);
  refused(agent, () => agent.update(0, ok, 0.1, new Uint8Array(2 ** 28)), undefined, /mask has/);
  refused(agent, () => agent.update(0, ok, 0.1, [false, false, false]), undefined, /mask/);
  refused(agent, () => agent.update(0, ok, 0.1, [1, 2, 0]), undefined, /mask\[1\]/);
  refused(agent, () => agent.endEpisode(NaN));
  refused(agent, () => agent.truncateEpisode(undefined), undefined, /number/);
  refused(agent, () => agent.setLearning(1), undefined, /boolean/);
  refused(agent, () => agent.setActionSelection('best'), undefined, /sample/);
  refused(agent, () => agent.actionProbabilities(new Float32Array(2)), undefined, /at least 3/);
  agent.dispose();
});

test('masks: a masked action is never chosen', () => {
  const agent = verve.createAgent({ actions: 4, seed: 9 });
  for (let i = 0; i < 200; ++i) assert.equal(agent.update(0, null, 0.1, [false, false, true, false]), 2);
  const p = agent.actionProbabilities();
  assert.deepEqual(Array.from(p), [0, 0, 1, 0]);
  agent.dispose();
});

test('sampleValues: bad axes and absurd sizes', () => {
  const agent = trained();
  refused(agent, () => agent.sampleValues([]), undefined, /1 or 2 axes/);
  refused(agent, () => agent.sampleValues([{ kind: 'x', index: 0, samples: 3 }]), undefined, /kind/);
  refused(agent, () => agent.sampleValues([{ kind: 'continuous', index: 0, samples: 2 ** 30 }]), undefined, /samples/);
  refused(agent, () => agent.sampleValues([{ kind: 'continuous', index: 0, samples: 2 ** 13 }, { kind: 'continuous', index: 1, samples: 2 ** 13 }]), undefined, /at most/);
  refused(agent, () => agent.sampleValues([{ kind: 'continuous', index: 5, samples: 3 }]));
  refused(agent, () => agent.sampleValues([{ kind: 'discrete', index: 0, samples: 5 }]));
  const v = agent.sampleValues([{ kind: 'continuous', index: 0, samples: 9 }, { kind: 'discrete', index: 0, samples: 4 }]);
  assert.equal(v.length, 36);
  assert.ok(v.every(Number.isFinite));
  agent.dispose();
});

test('descriptors: unknown fields, wrong types and values the library refuses', () => {
  const bad = [
    [{ actions: 0 }, /num_actions/],
    [{ action: 3 }, /unknown field 'action'/],
    [{ tauVale: 1 }, /unknown field 'tauVale'/],
    [{ actions: 2.5 }, /integer/],
    [{ actions: -1 }, /integer/],
    [{ tauValue: NaN }, /tau_value/],
    [{ tauValue: '0.1' }, /number/],
    [{ seed: -1 }, /seed/],
    [{ seed: 2 ** 64 }, /seed/],
    [{ discrete: new Array(65).fill(2) }, /at most 64/],
    [{ continuous: 65 }, /continuous/],
    [{ continuous: [{ circular: 1 }] }, /boolean/],
    [{ continuous: [{ wraps: true }] }, /unknown field/],
    [{ allocation: 'all' }, /'dynamic', 'full'/],
    [{ planning: 1 }, /boolean/],
    [{ discrete: [0] }, /discrete/],
    [{ adaptation: -1 }, /adaptation/],
    [{ adaptation: 128 }, /adaptation/],
    [{ continuousActions: 9 }, /continuousActions must be an integer from 0 to 8/],
    [{ continuousActions: 0.5 }, /continuousActions/],
    [{ continuousActions: 1, planning: true }, /planning needs discrete actions only/],
    [null, /object/],
    [[], /object/],
  ];
  for (const [desc, pattern] of bad) {
    assert.throws(() => verve.createAgent(desc), (e) => e instanceof VerveError && pattern.test(e.message), JSON.stringify(desc));
    assert.throws(() => verve.createBrain(desc), VerveError);
  }
  const big = verve.createAgent({ seed: 2n ** 63n + 5n, maxRbfs: 0 });
  assert.equal(big.descriptor().seed, 2n ** 63n + 5n);
  assert.equal(big.descriptor().maxRbfs, 0);
  big.dispose();
});

test('a descriptor read back creates the same agent', () => {
  const desc = { discrete: [3, 5], continuous: [{ circular: true }], actions: 4, resolution: 7, tauValue: 0.25, seed: 99, planning: true, curiosity: 'novelty', policyWeightBound: 2, adaptation: 1, grouping: 'joint' };
  const agent = verve.createAgent(desc);
  const back = agent.descriptor();
  for (const [k, v] of Object.entries(desc)) {
    if (k === 'continuous') assert.deepEqual(back.continuous, [{ circular: true }]);
    else assert.deepEqual(back[k], v, k);
  }
  const twin = verve.createAgent(back);
  assert.deepEqual(twin.descriptor(), back);
  agent.dispose();
  twin.dispose();
});

test('disposed handles: every call is refused, dispose() is idempotent', () => {
  const agent = verve.createAgent({ actions: 2 });
  agent.dispose();
  agent.dispose();
  assert.equal(agent.disposed, true);
  for (const call of [() => agent.update(0, null, 0.1), () => agent.value(), () => agent.saveBytes(), () => agent.stats(), () => agent.descriptor()]) {
    assert.throws(call, (e) => e instanceof VerveError && e.code === 'VERVE_ERROR_INVALID_STATE' && /disposed/.test(e.message));
  }
  const brain = verve.createBrain({ actions: 2 });
  const body = brain.createBody();
  const batch = verve.createBatch();
  assert.throws(() => batch.update([body, agent], [0, 0], [null, null], 0.1), /agents\[1\] is disposed/);
  assert.throws(() => batch.update([body, {}], [0, 0], [null, null], 0.1), /not an agent/);
  assert.throws(() => batch.update([body], [0, 0], [null], 0.1), /rewards must be an array of 1/);
  assert.throws(() => batch.update([body], [NaN], [null], 0.1), /reward/);
  assert.throws(() => verve.createBatch({ workers: 4 }), /single-threaded/);
  brain.dispose();
  assert.throws(() => brain.createBody(), /disposed/);
  assert.equal(typeof batch.update([body], [0], [null], 0.1)[0], 'number');
  body.dispose();
  batch.dispose();
  assert.throws(() => batch.update([], [], [], 0.1), /disposed/);
});

test('errors carry the result name and the library message', () => {
  try {
    verve.createAgent({ actions: 0 });
    assert.fail('created');
  } catch (e) {
    assert.equal(e.name, 'VerveError');
    assert.equal(e.code, 'VERVE_ERROR_INVALID_ARGUMENT');
    assert.equal(e.result, 1);
    assert.match(e.message, /^verve_agent_create: invalid agent descriptor: num_actions must be at least 1/);
  }
});

test('demonstrated steps: the action is checked, a refusal changes nothing, the policy follows', () => {
  const agent = trained();
  const ok = { discrete: [1], continuous: [0.1, 0.2] };
  refused(agent, () => agent.updateDemonstrated(0, ok, 0.1, 3), undefined, /action must be an integer in 0..2/);
  refused(agent, () => agent.updateDemonstrated(0, ok, 0.1, -1), undefined, /action/);
  refused(agent, () => agent.updateDemonstrated(0, ok, 0.1, 1.5), undefined, /action/);
  refused(agent, () => agent.updateDemonstrated(0, ok, 0.1, 0, [false, true, true]), undefined, /forbids/);
  refused(agent, () => agent.updateDemonstrated(NaN, ok, 0.1, 0), undefined, /reward must be finite/);
  for (let i = 0; i < 20; ++i) agent.updateDemonstrated(0, ok, 0.1, 2, [true, true, true]);
  agent.update(0, ok, 0.1);
  assert.ok(agent.actionProbabilities()[2] > 0.6, `p[2] = ${agent.actionProbabilities()[2]}`);
  agent.dispose();
});

test('a teacher\'s judgement: NaN and praise beyond [-1, 1] are refused and change nothing', () => {
  const agent = trained();
  refused(agent, () => agent.teach(NaN), undefined, /praise/);
  refused(agent, () => agent.teach(1.5), undefined, /\[-1, 1\]/);
  refused(agent, () => agent.teach('1'), undefined, /praise/);
  agent.teach(0);
  agent.teach(-1);
  agent.dispose();
});

