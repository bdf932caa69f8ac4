// The thesis's 1D hot plate (chapter 5), as samples/lua/hot_plate.lua and the C suites have it: a
// robot on 20 positions, the two edges safe (+1, the trial ends), every step elsewhere -1. Actions:
// 0 left, 1 stay, 2 right. Start positions from the Park-Miller generator, so the native program
// in test/native/hot_plate_actions.c draws the same ones.
const MODULUS = 2147483647;
const MOVES = [-1, 0, 1];

export class HotPlate {
  constructor({ size = 20, continuous = false, seed = 1 } = {}) {
    this.size = size;
    this.continuous = continuous;
    this.rng = (seed % (MODULUS - 1)) + 1;
    this.position = 0;
    this.obs = continuous ? { continuous: new Float32Array(1) } : { discrete: [0] };
  }

  descriptor(extra = {}) {
    const d = { actions: 3, policyMultiplier: 10 };
    if (this.continuous) {
      d.continuous = 1;
      d.resolution = 10;
    } else {
      d.discrete = [this.size];
    }
    return { ...d, ...extra };
  }

  observe() {
    // In float arithmetic, as the C program computes it (fround after each operation is exact).
    if (this.continuous) this.obs.continuous[0] = Math.fround(-1 + Math.fround((this.position * 2) / (this.size - 1)));
    else this.obs.discrete[0] = this.position;
    return this.obs;
  }

  reset() {
    this.rng = (this.rng * 16807) % MODULUS;
    this.position = 1 + (this.rng % (this.size - 2));
    return this.observe();
  }

  step(action) {
    this.position = Math.max(0, Math.min(this.size - 1, this.position + MOVES[action]));
    if (this.position === 0 || this.position === this.size - 1) return [1, true];
    return [-1, false];
  }

  /** One trial; returns the steps it took. `actions`, when given, collects every action. */
  runTrial(agent, dt, maxSteps, actions) {
    let obs = this.reset();
    let reward = 0;
    for (let step = 1; step <= maxSteps; ++step) {
      const action = agent.update(reward, obs, dt);
      actions?.push(action);
      const [r, done] = this.step(action);
      if (done) {
        agent.endEpisode(r);
        return step;
      }
      reward = r;
      obs = this.observe();
    }
    agent.truncateEpisode(reward);
    return maxSteps;
  }
}
