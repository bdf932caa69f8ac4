// The cost of one update through the JS API: update_cost.c's loop (cart-pole shape and physics),
// in JavaScript over the wasm module. `node bench/update_cost.mjs [updates]`; prints the same
// three numbers: <microseconds per update> <updates> <rbfs>.
import { loadVerve } from '../src/index.js';

const updates = Number(process.argv[2] ?? 200000);
const verve = await loadVerve();
const agent = verve.createAgent({ continuous: 4, resolution: 8, actions: 3, tauValue: 0.001, policyMultiplier: 50 });
const limit = (12 * 3.14159265358979) / 180;
const spin = (100 * 3.14159265358979) / 180;
let x = 0, v = 0, theta = 0, omega = 0, action = 2, trial = 0, start = 0;
const obs = { continuous: new Float32Array(4) };
for (let i = 0; i < updates + updates / 4; ++i) {
  if (i === updates / 4) start = performance.now();
  const force = action === 0 ? -10 : action === 1 ? 10 : 0;
  for (let k = 0; k < 5; ++k) {
    const co = Math.cos(theta), s = Math.sin(theta);
    const tmp = (force + 0.1 * 0.5 * omega * omega * s) / 1.1;
    const alpha = (9.81 * s - co * tmp) / (0.5 * (4 / 3 - (0.1 * co * co) / 1.1));
    const a = tmp - (0.1 * 0.5 * alpha * co) / 1.1;
    x += 0.01 * v; v += 0.01 * a; theta += 0.01 * omega; omega += 0.01 * alpha;
  }
  let reward = 1;
  if (Math.abs(x) > 2.4 || Math.abs(theta) > limit) {
    agent.endEpisode(-1);
    x = 0; v = 0; theta = 0.01 * ((trial++ % 7) - 3); omega = 0;
    reward = 0;
  }
  obs.continuous[0] = x / 2.4; obs.continuous[1] = v / 2.4; obs.continuous[2] = theta / limit; obs.continuous[3] = omega / spin;
  action = agent.update(reward, obs, 0.05);
}
const seconds = (performance.now() - start) / 1000;
console.log(`${((seconds * 1e6) / updates).toFixed(3)} ${updates} ${agent.rbfCount()}`);
