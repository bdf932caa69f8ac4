// The fixed-seed runs that test/native/hot_plate_actions.c makes natively, through the JS API: the
// hot plate with a discrete and with a continuous sensor (30 trials, seed 1), and a cart-pole-shaped
// agent with planning on a fixed sensor sequence (2,000 steps, seed 11). One string of action
// digits per run. No Node.js imports: test_page.mjs runs it in Chromium too.
import { HotPlate } from './hot_plate.js';

export function hotPlateActions(agent, continuous, seed, trials) {
  const task = new HotPlate({ continuous, seed });
  const actions = [];
  for (let t = 0; t < trials; ++t) task.runTrial(agent, 0.1, 1000, actions);
  return actions.join('');
}

export function fixedRuns(verve) {
  const lines = [];
  for (const continuous of [false, true]) {
    const agent = verve.createAgent(new HotPlate({ continuous }).descriptor({ seed: 1 }));
    lines.push(hotPlateActions(agent, continuous, 1, 30));
    agent.dispose();
  }
  const agent = verve.createAgent({ continuous: [{}, {}, { circular: true }, {}], actions: 3, planning: true, seed: 11 });
  const actions = [];
  const c = new Float32Array(4);
  let reward = 0;
  for (let i = 0; i < 2000; ++i) {
    for (let k = 0; k < 4; ++k) c[k] = Math.fround(Math.fround(((i * (13 + 7 * k)) % 201) / 100) - 1);
    const action = agent.update(reward, { continuous: c }, 0.02);
    actions.push(action);
    reward = action === 1 ? 0.5 : -0.25;
  }
  lines.push(actions.join(''));
  agent.dispose();
  return lines;
}
