// Cart-pole for the page: the classic equations (Barto, Sutton & Anderson 1983, as in
// bench/bench_shapes.hpp), Euler steps of 0.01 s, and an agent step every 0.05 s with the thesis's
// settings for figure 39 (docs/experiments.md). No DOM here: the page draws it, and Node can run it.
const G = 9.81;
const CART_MASS = 1.0;
const POLE_MASS = 0.1;
const HALF_LENGTH = 0.5;
const TOTAL = CART_MASS + POLE_MASS;
const TRACK = 2.4;                    // m either side
const ANGLE_LIMIT = (12 * Math.PI) / 180;
const SPIN_SCALE = (100 * Math.PI) / 180;
const FORCES = [-10, 10, 0];          // N per action
export const AGENT_DT = 0.05;         // s between agent steps (5 physics steps)
export const GOAL_SECONDS = 1800;     // a trial that balances this long ends as a success

export const CART_POLE_AGENT = Object.freeze({
  continuous: 4,   // x, x', angle, angle', each scaled to [-1, 1] at its limit
  actions: 3,
  resolution: 8,
  tauValue: 0.001,
  policyMultiplier: 50,
  adaptation: 0,   // the thesis's fixed horizon, as samples/scenes/cart_pole_scene.cpp runs it
});

export class CartPole {
  constructor(agent) {
    this.agent = agent;
    this.obs = { continuous: new Float32Array(4) };
    this.trial = 0;
    this.steps = 0;             // agent steps in this trial
    this.history = [];          // seconds balanced, per finished trial
    this.restart();
  }

  observe() {
    const c = this.obs.continuous;
    c[0] = this.x / TRACK;
    c[1] = this.v / TRACK;
    c[2] = this.theta / ANGLE_LIMIT;
    c[3] = this.omega / SPIN_SCALE;
    return this.obs;
  }

  restart() {
    this.x = 0;
    this.v = 0;
    this.theta = 0.01 * ((this.trial % 7) - 3);
    this.omega = 0;
    this.steps = 0;
    this.action = this.agent.update(0, this.observe(), AGENT_DT);
  }

  physics(force) {
    const c = Math.cos(this.theta);
    const s = Math.sin(this.theta);
    const tmp = (force + POLE_MASS * HALF_LENGTH * this.omega * this.omega * s) / TOTAL;
    const alpha = (G * s - c * tmp) / (HALF_LENGTH * (4 / 3 - (POLE_MASS * c * c) / TOTAL));
    const a = tmp - (POLE_MASS * HALF_LENGTH * alpha * c) / TOTAL;
    this.x += 0.01 * this.v;
    this.v += 0.01 * a;
    this.theta += 0.01 * this.omega;
    this.omega += 0.01 * alpha;
  }

  failed() {
    return Math.abs(this.x) > TRACK || Math.abs(this.theta) > ANGLE_LIMIT;
  }

  /** One agent step (0.05 s); returns true when it ended a trial. */
  step() {
    for (let k = 0; k < 5; ++k) this.physics(FORCES[this.action]);
    ++this.steps;
    const seconds = this.steps * AGENT_DT;
    if (this.failed() || seconds >= GOAL_SECONDS) {
      if (this.failed()) this.agent.endEpisode(-1);
      else this.agent.truncateEpisode(1);
      this.history.push(seconds);
      ++this.trial;
      this.restart();
      return true;
    }
    this.action = this.agent.update(1, this.observe(), AGENT_DT);
    return false;
  }

  /** Seconds balanced so far in the current trial. */
  get seconds() { return this.steps * AGENT_DT; }
}
