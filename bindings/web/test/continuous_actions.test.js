// Continuous actions (continuousActions: 2): values in [-1, 1] chosen on every update beside the
// discrete action, read with continuousAction() (a fresh Float32Array, or into the caller's);
// `actions` left out means 1; greedy plays the mean; saves keep the values and their exploration
// noise; brains' bodies and batches have them; refusals change nothing; and a 1-D reach is learned.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { refused, verve } from './helpers.js';
import { Reach, greedyAt, reachDescriptor } from './reach.js';

const driver = (extra = {}) => ({ continuous: [{ circular: true }, {}], continuousActions: 2, seed: 7, ...extra });
const obs = (step) => ({ continuous: [Math.sin(step * 0.37), Math.cos(step * 0.21) * 0.9] });
const bounded = (values, n) => values instanceof Float32Array && values.length === n && values.every((v) => v >= -1 && v <= 1);

test('no continuous actions is the default', () => {
  assert.equal(verve.defaults().continuousActions, 0);
  const plain = verve.createAgent({ actions: 3 });
  assert.equal(plain.numContinuousActions, 0);
  plain.update(0, null, 0.1);
  const none = plain.continuousAction();
  assert.ok(none instanceof Float32Array && none.length === 0);
  plain.dispose();
});

test('continuousActions without actions: the one discrete action; read back and created again', () => {
  const agent = verve.createAgent(driver());
  const back = agent.descriptor();
  assert.equal(back.continuousActions, 2);
  assert.equal(back.actions, 1);
  assert.equal(agent.numContinuousActions, 2);
  const twin = verve.createAgent(back);
  assert.deepEqual(twin.descriptor(), back);
  const both = verve.createAgent(driver({ actions: 3 }));
  assert.equal(both.descriptor().actions, 3);
  const branched = verve.createAgent(driver({ actionBranches: [3, 2] }));
  assert.equal(branched.numActions, 6);
  assert.equal(branched.numChoices, 5);
  assert.equal(branched.numContinuousActions, 2);
  const most = verve.createAgent(driver({ continuousActions: 8 }));
  assert.equal(most.continuousAction().length, 8);
  for (const a of [agent, twin, both, branched, most]) a.dispose();
});

test('0s before the first update, then values in [-1, 1] after every update', () => {
  const agent = verve.createAgent(driver());
  assert.deepEqual(Array.from(agent.continuousAction()), [0, 0]);
  const out = new Float32Array([5, 5, 5]);  // longer than needed: the rest is left alone
  const seen = new Set();
  for (let step = 0; step < 200; ++step) {
    assert.equal(agent.update(step % 9 === 0 ? 0.1 : 0, obs(step), 0.1), 0);  // the one discrete action
    const values = agent.continuousAction();
    assert.ok(bounded(values, 2), `step ${step}: ${values}`);
    assert.equal(agent.continuousAction(out), out);
    assert.deepEqual(Array.from(out), [values[0], values[1], 5]);
    seen.add(values[0]);
  }
  assert.ok(seen.size > 50, `sampled values vary from step to step (${seen.size} distinct of 200)`);
  agent.dispose();
});

test('greedy: the mean, the same at the same observation, in a loaded copy too', () => {
  const agent = verve.createAgent(driver());
  for (let step = 0; step < 200; ++step) agent.update(step % 4 === 0 ? 0.5 : -0.1, obs(step), 0.1);
  agent.setActionSelection('greedy');
  agent.setLearning(false);  // so that the weights, hence the mean, stay as they are
  agent.update(0, obs(3), 0.1);
  const first = agent.continuousAction();
  agent.update(0, obs(50), 0.1);
  const elsewhere = agent.continuousAction();
  agent.update(0, obs(3), 0.1);
  assert.ok(bounded(first, 2));
  assert.deepEqual(agent.continuousAction(), first);
  assert.notDeepEqual(elsewhere, first);
  const copy = verve.loadAgent(agent.saveBinaryBytes());
  copy.setActionSelection('greedy');
  copy.setLearning(false);
  copy.update(0, obs(3), 0.1);
  assert.deepEqual(copy.continuousAction(), first);
  agent.dispose();
  copy.dispose();
});

test('saves (XML and binary) keep the values and the noise: the next values are the same', () => {
  const agent = verve.createAgent(driver());
  for (let step = 0; step < 100; ++step) agent.update(step % 7 === 0 ? 1 : 0, obs(step), 0.1);
  const copies = [verve.loadAgent(agent.saveBytes()), verve.loadAgent(agent.saveBinaryBytes())];
  for (const copy of copies) {
    assert.equal(copy.descriptor().continuousActions, 2);
    assert.deepEqual(copy.continuousAction(), agent.continuousAction());
  }
  for (let step = 100; step < 140; ++step) {
    agent.update(0, obs(step), 0.1);
    const values = agent.continuousAction();
    for (const copy of copies) {
      copy.update(0, obs(step), 0.1);
      assert.deepEqual(copy.continuousAction(), values, `step ${step}`);
    }
  }
  for (const a of [agent, ...copies]) a.dispose();
});

test("a brain's bodies and a batch: each agent's values after a batch update", () => {
  const brain = verve.createBrain(driver());
  const bodies = [brain.createBody(), brain.createBody()];
  const batch = verve.createBatch();
  assert.deepEqual(Array.from(batch.update(bodies, [0, 0], [obs(0), obs(1)], 0.1)), [0, 0]);
  for (const body of bodies) assert.ok(bounded(body.continuousAction(), 2));
  const binary = verve.loadBrain(brain.saveBinaryBytes());
  const loadedBody = binary.createBody();
  assert.equal(loadedBody.descriptor().continuousActions, 2);
  for (const x of [...bodies, loadedBody, batch, brain, binary]) x.dispose();
});

test('a batch shows agents their continuous actions: the steps of updateDemonstratedContinuous', () => {
  const batched = [verve.createAgent(driver({ seed: 1 })), verve.createAgent(driver({ seed: 2 }))];
  const alone = [verve.createAgent(driver({ seed: 1 })), verve.createAgent(driver({ seed: 2 }))];
  const batch = verve.createBatch();
  for (let step = 0; step < 40; ++step) {
    const values = [0.5, -0.25 * (step % 4)];
    const shown = step % 2 === 0 ? 0 : null;  // agent 0 shown every other step, agent 1 chooses
    batch.update(batched, [0.1, -0.1], [obs(step), obs(step + 50)], 0.1, undefined, [shown, null], [values, null]);
    if (shown === null) alone[0].update(0.1, obs(step), 0.1);
    else {
      alone[0].updateDemonstratedContinuous(0.1, obs(step), 0.1, 0, values);
      assert.deepEqual(Array.from(batched[0].continuousAction()), values);
    }
    alone[1].update(-0.1, obs(step + 50), 0.1);
  }
  for (let i = 0; i < 2; ++i) assert.deepEqual(batched[i].saveBytes(), alone[i].saveBytes());
  const before = batched[0].saveBytes();
  const inputs = [batched, [0, 0], [obs(0), obs(1)], 0.1, undefined, [0, null]];
  assert.throws(() => batch.update(...inputs, [[0.5], null]), /continuousActions\[0\] has 1 values, agents\[0\] has 2/);
  assert.throws(() => batch.update(...inputs, [[1.5, 0], null]), /within \[-1, 1\]/);
  assert.throws(() => batch.update(batched, [0, 0], [obs(0), obs(1)], 0.1, undefined, undefined, [null, null]),
    /continuousActions must come after demonstrated/);
  assert.deepEqual(batched[0].saveBytes(), before);
  for (const x of [...batched, ...alone, batch]) x.dispose();
});

test("docs/web.md's driver, as written there", () => {
  const reward = 0, dt = 0.1, readings = [0.3, -0.8];  // bearing to the target (wraps), distance
  const maxSteer = 0.6, maxForce = 40;
  // steer and throttle, each in [-1, 1]; no discrete choice (`actions` left out: 1)
  const car = verve.createAgent({ continuous: [{ circular: true }, {}], continuousActions: 2 });
  const controls = new Float32Array(2);                  // reused every frame
  car.update(reward, { continuous: readings }, dt);      // the one discrete action, 0
  car.continuousAction(controls);                        // [steer, throttle]
  const steering = controls[0] * maxSteer, engineForce = controls[1] * maxForce;
  assert.ok(Math.abs(steering) <= maxSteer && Math.abs(engineForce) <= maxForce);
  car.dispose();
});

test('refusals: bad counts, planning, a short or wrong buffer, a disposed agent', () => {
  const bad = [
    [{ continuousActions: 9 }, /descriptor\.continuousActions must be an integer from 0 to 8 \(got number 9\)/],
    [{ continuousActions: -1 }, /continuousActions must be an integer from 0 to 8 \(got number -1\)/],
    [{ continuousActions: 1.5 }, /continuousActions must be an integer from 0 to 8 \(got number 1\.5\)/],
    [{ continuousActions: '2' }, /continuousActions must be an integer from 0 to 8 \(got string\)/],
    [{ continuousActions: 2n }, /continuousActions must be an integer from 0 to 8/],
    [{ planning: true }, /planning needs discrete actions only/],
  ];
  for (const [extra, pattern] of bad) {
    for (const create of [(d) => verve.createAgent(d), (d) => verve.createBrain(d)]) {
      assert.throws(() => create(driver(extra)), (e) => e instanceof VerveError && pattern.test(e.message), String(extra.continuousActions));
    }
  }
  const agent = verve.createAgent(driver());
  agent.update(0, obs(0), 0.1);
  refused(agent, () => agent.continuousAction(new Float32Array(1)), 'VERVE_ERROR_INVALID_ARGUMENT', /at least 2 entries/);
  refused(agent, () => agent.continuousAction([0, 0]), 'VERVE_ERROR_INVALID_ARGUMENT', /Float32Array/);
  refused(agent, () => agent.continuousAction(new Float64Array(2)), 'VERVE_ERROR_INVALID_ARGUMENT', /Float32Array/);
  assert.ok(bounded(agent.continuousAction(), 2));
  agent.dispose();
  assert.throws(() => agent.continuousAction(), (e) => e instanceof VerveError && e.code === 'VERVE_ERROR_INVALID_STATE');
});

// The 1-D reach of test/reach.js: x += 2 * dt * a, reward -|x|. Measured with seed 1 after 400
// episodes: greedy 1.000 at x = -0.6 and -0.999 at +0.6, mean |x| 0.095 over episodes 1-20 and
// 0.041 over 381-400 (seeds 1-16: every one beyond +-0.99; the C++ library alone reaches about
// +1.0 / -0.95). A policy that does not move averages 0.5.
test('a 1-D reach: the greedy action drives towards 0 from either side', () => {
  const agent = verve.createAgent(reachDescriptor(1));
  const task = new Reach(1);
  const distances = [];
  for (let e = 0; e < 400; ++e) distances.push(task.runEpisode(agent));
  const late = distances.slice(380).reduce((a, b) => a + b) / 20;
  assert.ok(late < 0.06, `mean |x| over the last 20 episodes ${late.toFixed(3)}`);
  const left = greedyAt(agent, -0.6);
  const right = greedyAt(agent, 0.6);
  assert.ok(left > 0.9 && right < -0.9, `greedy action at x = -0.6: ${left.toFixed(3)}, at +0.6: ${right.toFixed(3)}`);
  agent.dispose();
});

// A teacher's continuous actions (docs/teaching.md): the reach shown for 10 episodes by a driver that
// steers back to 0 (a = -10 x within [-1, 1]) points the greedy action back at once; the steps
// recorded and replayed train an agent to the same bytes; bad values are refused and change nothing.
test('updateDemonstratedContinuous teaches the reach; addStepContinuous records it', () => {
  const shown = verve.createAgent(reachDescriptor(1));
  const replayed = verve.createAgent(reachDescriptor(1));
  const rec = verve.createRecording(shown);
  let state = 12345;
  const uniform = () => { state = (state * 16807) % 2147483647; return state / 2147483647; };
  const value = new Float32Array(1);
  for (let episode = 0; episode < 10; ++episode) {
    let x = 2 * uniform() - 1;
    let reward = 0;
    for (let t = 0; t < 100; ++t) {
      value[0] = Math.max(-1, Math.min(1, -10 * x));
      shown.updateDemonstratedContinuous(reward, { continuous: [x] }, 0.05, 0, value);
      rec.addStepContinuous(reward, { continuous: [x] }, 0.05, 0, value);
      assert.equal(shown.continuousAction()[0], value[0]);
      x = Math.max(-1, Math.min(1, x + 0.1 * value[0]));
      reward = -Math.abs(x);
    }
    shown.truncateEpisode(reward);
    rec.addTruncation(reward);
  }
  replayed.replay(verve.loadRecording(rec.saveBytes()));
  assert.deepEqual(replayed.saveBinaryBytes(), shown.saveBinaryBytes());

  const o = { continuous: [0] };
  refused(replayed, () => replayed.updateDemonstratedContinuous(0, o, 0.05, 0, [1.5]), undefined, /within \[-1, 1\]/);
  refused(replayed, () => replayed.updateDemonstratedContinuous(0, o, 0.05, 0, [NaN]), undefined, /within \[-1, 1\]/);
  refused(replayed, () => replayed.updateDemonstratedContinuous(0, o, 0.05, 0, [0.1, 0.2]), undefined, /has 2 values/);
  refused(replayed, () => replayed.updateDemonstratedContinuous(0, o, 0.05, 0, 'left'), undefined, /must be an array/);
  refused(replayed, () => replayed.updateDemonstratedContinuous(0, o, 0.05, 0, ['x']), undefined, /must be a number/);
  const before = rec.saveBytes();
  assert.throws(() => rec.addStepContinuous(0, o, 0.05, 0, [-2]), VerveError);
  assert.throws(() => rec.addStepContinuous(0, o, 0.05, 0, []), VerveError);
  assert.deepEqual(rec.saveBytes(), before);

  const left = greedyAt(shown, -0.6), right = greedyAt(shown, 0.6);
  assert.ok(left > 0.5 && right < -0.5, `greedy ${left} at -0.6, ${right} at +0.6`);
  for (const a of [shown, replayed, rec]) a.dispose();
});
