// A 1-D reach with one continuous action: a point at x in [-1, 1] (the one continuous sensor) moves
// by 2 * dt * a for the agent's continuous action a in [-1, 1] (dt 0.05 s: at full speed from one
// end to the other in 1 s), clamped at the ends; every step earns -|x|, so the best policy drives
// to 0 and stays. 100-step episodes from a random x, cut off with truncateEpisode. No Node.js
// imports: test_page.mjs runs it in Chromium too.
export const DT = 0.05;
export const STEPS = 100;

/** The agent's descriptor: one continuous sensor, one continuous action (`actions` left out: 1). */
export function reachDescriptor(seed) {
  return { continuous: 1, continuousActions: 1, seed };
}

export class Reach {
  constructor(seed = 1) {
    this.rng = (seed % 2147483646) + 1;  // Park-Miller, as hot_plate.js
    this.obs = { continuous: new Float32Array(1) };
    this.action = new Float32Array(1);  // continuousAction(out): no allocation per step
  }

  /**
   * One episode. `trace`, when given, collects every continuous action. Returns the mean |x| over
   * the episode's steps.
   */
  runEpisode(agent, trace) {
    let x = 2 * this.uniform() - 1;
    let reward = 0;
    let distance = 0;
    for (let step = 0; step < STEPS; ++step) {
      this.obs.continuous[0] = x;
      agent.update(reward, this.obs, DT);
      const a = agent.continuousAction(this.action)[0];
      trace?.push(a);
      x = Math.max(-1, Math.min(1, x + 2 * DT * a));
      reward = -Math.abs(x);
      distance += Math.abs(x);
    }
    agent.truncateEpisode(reward);
    return distance / STEPS;
  }

  uniform() {
    this.rng = (this.rng * 16807) % 2147483647;
    return (this.rng - 1) / 2147483646;
  }
}

/** The greedy action at x, learning off: the policy's mean there. Leaves the agent greedy, not learning. */
export function greedyAt(agent, x) {
  agent.setLearning(false);
  agent.setActionSelection('greedy');
  agent.resetShortTermMemory();
  agent.update(0, { continuous: [x] }, DT);
  return agent.continuousAction()[0];
}

/**
 * A fixed-seed run for comparing engines: `episodes` episodes, every sampled continuous action as
 * its float32 bits in hex. The same wasm in Node.js and in Chromium must give the same string.
 */
export function reachRun(verve, seed = 3, episodes = 20) {
  const agent = verve.createAgent(reachDescriptor(seed));
  const task = new Reach(seed);
  const trace = [];
  for (let e = 0; e < episodes; ++e) task.runEpisode(agent, trace);
  agent.dispose();
  const bits = new Uint32Array(Float32Array.from(trace).buffer);
  return Array.from(bits, (b) => b.toString(16).padStart(8, '0')).join('');
}
