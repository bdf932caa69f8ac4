// The cost of one update through the JS API: update_cost.c's measurement (cart-pole shape; a
// recorded learning run's observation stream replayed to a fresh agent, the replay timed) in
// JavaScript over the wasm module. `node bench/update_cost.mjs [updates]` prints the same three
// numbers: <microseconds per update> <updates> <rbfs>.
import { loadVerve } from '../src/index.js';

const updates = Number(process.argv[2] ?? 200000);
const total = updates + updates / 4;  // the first quarter warms up
const verve = await loadVerve();
const desc = { continuous: 4, resolution: 8, actions: 3, tauValue: 0.001, policyMultiplier: 50 };
const limit = (12 * 3.14159265358979) / 180;
const spin = (100 * 3.14159265358979) / 180;
const obs = new Float32Array(4 * total);
const rewards = new Float32Array(total);
const fell = new Uint8Array(total);

// 1. A learning run with the physics in the loop, recorded.
let agent = verve.createAgent(desc);
let x = 0, v = 0, theta = 0, omega = 0, action = 2, trial = 0;
for (let i = 0; i < total; ++i) {
  const force = action === 0 ? -10 : action === 1 ? 10 : 0;
  for (let k = 0; k < 5; ++k) {
    const co = Math.cos(theta), s = Math.sin(theta);
    const tmp = (force + 0.1 * 0.5 * omega * omega * s) / 1.1;
    const alpha = (9.81 * s - co * tmp) / (0.5 * (4 / 3 - (0.1 * co * co) / 1.1));
    const a = tmp - (0.1 * 0.5 * alpha * co) / 1.1;
    x += 0.01 * v; v += 0.01 * a; theta += 0.01 * omega; omega += 0.01 * alpha;
  }
  rewards[i] = 1;
  fell[i] = Math.abs(x) > 2.4 || Math.abs(theta) > limit ? 1 : 0;
  if (fell[i]) {
    agent.endEpisode(-1);
    x = 0; v = 0; theta = 0.01 * ((trial++ % 7) - 3); omega = 0;
    rewards[i] = 0;
  }
  obs[4 * i] = x / 2.4; obs[4 * i + 1] = v / 2.4; obs[4 * i + 2] = theta / limit; obs[4 * i + 3] = omega / spin;
  action = agent.update(rewards[i], { continuous: obs.subarray(4 * i, 4 * i + 4) }, 0.05);
}
agent.dispose();

// 2. A fresh agent given the same stream, timed.
agent = verve.createAgent(desc);
const o = { continuous: null };
let start = 0;
for (let i = 0; i < total; ++i) {
  if (i === updates / 4) start = performance.now();
  if (fell[i]) agent.endEpisode(-1);
  o.continuous = obs.subarray(4 * i, 4 * i + 4);
  agent.update(rewards[i], o, 0.05);
}
const seconds = (performance.now() - start) / 1000;
console.log(`${((seconds * 1e6) / updates).toFixed(3)} ${updates} ${agent.rbfCount()}`);
agent.dispose();
