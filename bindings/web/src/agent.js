// An agent (or a brain's body): one handle, freed by dispose() or, failing that, when the object
// is garbage collected. Every method checks its input first; a refused call changes nothing.
import { invalidArgument, invalidState } from './errors.js';
import { L, readDescriptor } from './descriptor.js';
import { checkContinuousValues, checkMask, checkNumber, checkObservation, writeObservation } from './observation.js';
import { save } from './saves.js';

const SELECTIONS = ['sample', 'greedy'];
const AXIS_KINDS = ['discrete', 'continuous'];
/** The most values sampleValues returns (as the Lua binding's limit). */
export const MAX_SAMPLES = 2 ** 24;

export class Agent {
  /** @internal Made by Verve.createAgent, Verve.loadAgent and Brain.createBody. */
  constructor(rt, handle, brain = null) {
    this.rt = rt;
    this.handle = handle;
    this.brain = brain;  // keeps the wrapper alive with its body (the library keeps the brain itself)
    rt.track(this, '_verve_agent_destroy', handle);
    const desc = this.descriptor();
    this.numActions = desc.actions;  // combined actions (with branches, their product)
    this.actionBranches = desc.actionBranches;
    // Mask flags and probabilities: one per action, or one per choice of each branch.
    this.numChoices = desc.actionBranches.length === 0 ? desc.actions : desc.actionBranches.reduce((a, b) => a + b, 0);
    this.numContinuousActions = desc.continuousActions;
    this.numDiscrete = desc.discrete.length;
    this.numContinuous = desc.continuous.length;
  }

  get disposed() { return this.handle === 0; }

  live() {
    if (this.handle === 0) throw invalidState('the agent is disposed');
    return this.handle;
  }

  /** Frees the agent now; later calls throw. Idempotent. */
  dispose() {
    if (this.handle === 0) return;
    this.rt.untrack(this);
    this.rt.m._verve_agent_destroy(this.handle);
    this.handle = 0;
  }

  /** One step: the reward the previous action earned, what the sensors read, the seconds since the previous step. */
  update(reward, observation, dt, mask) {
    const h = this.live();
    checkNumber('reward', reward);
    const obs = checkObservation('observation', observation);
    checkNumber('dt', dt);
    const rt = this.rt;
    if (mask === undefined) {
      const [d, c, out] = rt.carve([4 * obs.discrete.length, 4 * obs.continuous.length, 4]);
      writeObservation(rt.heap, obs, d, c);
      rt.check(rt.m._verve_agent_update(h, reward, d, obs.discrete.length, c, obs.continuous.length, dt, out));
      return rt.heap.u32[out >> 2];
    }
    checkMask(mask, this.numChoices, this.actionBranches);
    const [d, c, m, out] = rt.carve([4 * obs.discrete.length, 4 * obs.continuous.length, mask.length, 4]);
    const heap = rt.heap;
    writeObservation(heap, obs, d, c);
    for (let i = 0; i < mask.length; ++i) heap.u8[m + i] = mask[i] ? 1 : 0;
    rt.check(rt.m._verve_agent_update_masked(h, reward, d, obs.discrete.length, c, obs.continuous.length, dt, m,
      mask.length, out));
    return rt.heap.u32[out >> 2];
  }

  /**
   * A demonstrated step (docs/teaching.md): as update, but the player or a scripted AI took `action`
   * (0 .. actions - 1, one the mask allows); the agent learns from it and is pulled towards it.
   */
  updateDemonstrated(reward, observation, dt, action, mask) {
    const h = this.live();
    checkNumber('reward', reward);
    const obs = checkObservation('observation', observation);
    checkNumber('dt', dt);
    if (!Number.isInteger(action) || action < 0 || action >= this.numActions) {
      throw invalidArgument(`action must be an integer in 0..${this.numActions - 1}, got ${String(action)}`);
    }
    if (mask !== undefined) checkMask(mask, this.numChoices, this.actionBranches);
    const flags = mask === undefined ? 0 : mask.length;
    const rt = this.rt;
    const [d, c, m] = rt.carve([4 * obs.discrete.length, 4 * obs.continuous.length, Math.max(flags, 1)]);
    writeObservation(rt.heap, obs, d, c);
    for (let i = 0; i < flags; ++i) rt.heap.u8[m + i] = mask[i] ? 1 : 0;
    rt.check(rt.m._verve_agent_update_demonstrated(h, reward, d, obs.discrete.length, c, obs.continuous.length, dt,
      flags ? m : 0, flags, action));
  }

  /**
   * updateDemonstrated with the continuous actions the host played too (docs/teaching.md): one per
   * continuous action, each in [-1, 1]; the agent learns from them and continuousAction() reads them back.
   */
  updateDemonstratedContinuous(reward, observation, dt, action, continuousAction, mask) {
    const h = this.live();
    checkNumber('reward', reward);
    const obs = checkObservation('observation', observation);
    checkNumber('dt', dt);
    if (!Number.isInteger(action) || action < 0 || action >= this.numActions) {
      throw invalidArgument(`action must be an integer in 0..${this.numActions - 1}, got ${String(action)}`);
    }
    const values = checkContinuousValues('continuousAction', continuousAction);
    if (mask !== undefined) checkMask(mask, this.numChoices, this.actionBranches);
    const flags = mask === undefined ? 0 : mask.length;
    const rt = this.rt;
    const [d, c, m, v] = rt.carve([4 * obs.discrete.length, 4 * obs.continuous.length, Math.max(flags, 1), 4 * values.length]);
    writeObservation(rt.heap, obs, d, c);
    for (let i = 0; i < flags; ++i) rt.heap.u8[m + i] = mask[i] ? 1 : 0;
    rt.heap.f32.set(values, v >> 2);
    rt.check(rt.m._verve_agent_update_demonstrated_continuous(h, reward, d, obs.discrete.length, c, obs.continuous.length,
      dt, flags ? m : 0, flags, action, values.length ? v : 0, values.length));
  }

  /** Every entry of a Recording into this agent, as demonstrated steps and trial ends (docs/teaching.md). */
  replay(recording) {
    const h = this.live();
    if (recording === null || typeof recording !== 'object' || typeof recording.live !== 'function' || !('handle' in recording)) {
      throw invalidArgument('replay takes a Recording');
    }
    this.rt.check(this.rt.m._verve_agent_replay(h, recording.live()));
  }

  /** A teacher's judgement in [-1, 1] of what the agent did over the last 2.5 s (docs/teaching.md); not a reward. */
  teach(praise) {
    const h = this.live();
    this.rt.check(this.rt.m._verve_agent_teach(h, checkNumber('praise', praise)));
  }

  /** The trial really ended (goal, death): a terminal reward. */
  endEpisode(finalReward) {
    const h = this.live();
    this.rt.check(this.rt.m._verve_agent_end_episode(h, checkNumber('finalReward', finalReward)));
  }

  /** The trial was cut off (a time limit) where the world would have gone on. */
  truncateEpisode(reward) {
    const h = this.live();
    this.rt.check(this.rt.m._verve_agent_truncate_episode(h, checkNumber('reward', reward)));
  }

  /**
   * Action branches: the choice of each branch (from 0) within a combined action (branch 0 varies
   * fastest); one choice, the action itself, without branches.
   */
  splitAction(action) {
    const h = this.live();
    if (!Number.isInteger(action) || action < 0 || action >= this.numActions) {
      throw invalidArgument(`action must be an integer in 0..${this.numActions - 1}, got ${String(action)}`);
    }
    const n = Math.max(this.actionBranches.length, 1);
    const [out] = this.rt.carve([4 * n]);
    this.rt.check(this.rt.m._verve_agent_split_action(h, action, out, n));
    return Array.from(this.rt.heap.u32.subarray(out >> 2, (out >> 2) + n));
  }

  /** The combined action of one choice per branch (each from 0), as update() returns it. */
  joinAction(choices) {
    const h = this.live();
    if (!Array.isArray(choices) && !ArrayBuffer.isView(choices)) {
      throw invalidArgument(`joinAction takes an array of choices, one per branch (got ${typeof choices})`);
    }
    const n = choices.length;
    for (let b = 0; b < n; ++b) {
      const c = choices[b];
      if (!Number.isInteger(c) || c < 0 || c > 0xffffffff) throw invalidArgument(`choices[${b}] must be an integer from 0, got ${String(c)}`);
    }
    const [p, out] = this.rt.carve([4 * Math.max(n, 1), 4]);
    for (let b = 0; b < n; ++b) this.rt.heap.u32[(p >> 2) + b] = choices[b];
    this.rt.check(this.rt.m._verve_agent_join_action(h, p, n, out));
    return this.rt.heap.u32[out >> 2];
  }

  resetShortTermMemory() {
    this.rt.check(this.rt.m._verve_agent_reset_short_term_memory(this.live()));
  }

  setLearning(enabled) {
    const h = this.live();
    if (typeof enabled !== 'boolean') throw invalidArgument('setLearning takes a boolean');
    this.rt.check(this.rt.m._verve_agent_set_learning(h, enabled ? 1 : 0));
  }

  learning() {
    const h = this.live();
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m._verve_agent_get_learning(h, out));
    return this.rt.heap.i32[out >> 2] !== 0;
  }

  /** 'sample' (default: explores, learns) or 'greedy' (the most probable action; not saved). */
  setActionSelection(mode) {
    const h = this.live();
    const index = SELECTIONS.indexOf(mode);
    if (index < 0) throw invalidArgument(`the action selection must be 'sample' or 'greedy' (got ${String(mode)})`);
    this.rt.check(this.rt.m._verve_agent_set_action_selection(h, index));
  }

  actionSelection() {
    const h = this.live();
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m._verve_agent_get_action_selection(h, out));
    return SELECTIONS[this.rt.heap.u32[out >> 2]];
  }

  /**
   * Each action's probability at the latest update, into `out` when given (no garbage). With action
   * branches, each branch's choices in turn (the branches' sizes summed), each branch summing to 1.
   */
  actionProbabilities(out) {
    const h = this.live();
    const n = this.numChoices;
    if (out !== undefined && (!(out instanceof Float32Array) || out.length < n)) {
      throw invalidArgument(`actionProbabilities(out) needs a Float32Array of at least ${n} entries`);
    }
    const [p] = this.rt.carve([4 * n]);
    this.rt.check(this.rt.m._verve_agent_get_action_probabilities(h, p, n));
    const values = this.rt.heap.f32.subarray(p >> 2, (p >> 2) + n);
    if (out) {
      out.set(values);
      return out;
    }
    return values.slice();
  }

  /**
   * The continuous actions of the latest update (descriptor.continuousActions values, each in
   * [-1, 1]): drawn around the policy's mean, or the mean itself when greedy; 0s before the first
   * update. Into `out` when given (a Float32Array of at least that many): nothing is allocated, so
   * a game can read them every frame.
   */
  continuousAction(out) {
    const h = this.live();
    const n = this.numContinuousActions;
    if (out !== undefined && (!(out instanceof Float32Array) || out.length < n)) {
      throw invalidArgument(`continuousAction(out) needs a Float32Array of at least ${n} entries`);
    }
    const rt = this.rt;
    const p = rt.carveOne(4 * Math.max(n, 1));  // the library wants a pointer even for 0 values
    rt.check(rt.m._verve_agent_get_continuous_action(h, p, n));
    const values = out ?? new Float32Array(n);
    const f32 = rt.heap.f32;
    for (let i = 0; i < n; ++i) values[i] = f32[(p >> 2) + i];
    return values;
  }

  readFloat(fn) {
    const h = this.live();
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m[fn](h, out));
    return this.rt.heap.f32[out >> 2];
  }

  /** V(s) of the latest observation. */
  value() { return this.readFloat('_verve_agent_get_value'); }
  /** The TD error of the latest real step. */
  tdError() { return this.readFloat('_verve_agent_get_td_error'); }

  rbfCount() {
    const h = this.live();
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m._verve_agent_get_rbf_count(h, out));
    return this.rt.heap.u32[out >> 2];
  }

  stats() {
    const h = this.live();
    const rt = this.rt;
    const [p] = rt.carve([rt.layout[L.statsSize]]);
    rt.heap.u32[p >> 2] = rt.layout[L.statsSize];
    rt.check(rt.m._verve_agent_get_stats(h, p));
    const { u32, f32 } = rt.heap;
    const at = (field) => (p + rt.layout[L[field]]) >> 2;
    const u64 = (field) => u32[at(field)] + u32[at(field) + 1] * 2 ** 32;
    return {
      steps: u64('statsSteps'),
      rbfCount: u32[at('statsRbfCount')],
      liveTraces: u32[at('statsLiveTraces')],
      value: f32[at('statsValue')],
      tdError: f32[at('statsTdError')],
      modelError: f32[at('statsModelError')],
      predictedUncertainty: f32[at('statsPredictedUncertainty')],
      planningSteps: u32[at('statsPlanningSteps')],
      curiosityReward: f32[at('statsCuriosityReward')],
      rbfBudgetHits: u64('statsRbfBudgetHits'),
      clampedRewards: u64('statsClampedRewards'),
    };
  }

  /** The agent's descriptor (valid input for Verve.createAgent). */
  descriptor() {
    const h = this.live();
    const rt = this.rt;
    const [p] = rt.carve([rt.layout[L.descSize]]);
    rt.check(rt.m._verve_agent_desc_init(p, rt.layout[L.descSize]));
    rt.check(rt.m._verve_agent_get_desc(h, p));
    return readDescriptor(rt.heap, rt.layout, p);
  }

  /**
   * V over 1 or 2 swept sensors, the others held at `base`: axes are {kind: 'discrete' |
   * 'continuous', index, samples}, `base` an observation (default: every sensor at 0); returns axes[0].samples (* axes[1].samples) values, axis 0 fastest.
   */
  sampleValues(axes, base) {
    const h = this.live();
    if (!Array.isArray(axes) || axes.length < 1 || axes.length > 2) throw invalidArgument('sampleValues takes 1 or 2 axes');
    let count = 1;
    const checked = axes.map((axis, i) => {
      if (axis === null || typeof axis !== 'object') throw invalidArgument(`axes[${i}] must be an object {kind, index, samples}`);
      const kind = AXIS_KINDS.indexOf(axis.kind);
      if (kind < 0) throw invalidArgument(`axes[${i}].kind must be 'discrete' or 'continuous'`);
      for (const field of ['index', 'samples']) {
        if (!Number.isInteger(axis[field]) || axis[field] < 0 || axis[field] > MAX_SAMPLES) {
          throw invalidArgument(`axes[${i}].${field} must be an integer from 0 to ${MAX_SAMPLES}`);
        }
      }
      count *= axis.samples;
      return [kind, axis.index, axis.samples];
    });
    if (count > MAX_SAMPLES) throw invalidArgument(`sampleValues would return ${count} values, at most ${MAX_SAMPLES}`);
    // No base: every sensor at 0 (the swept ones are overwritten).
    const obs = base === undefined
      ? { discrete: new Int32Array(this.numDiscrete), continuous: new Float32Array(this.numContinuous) }
      : checkObservation('base', base);
    const rt = this.rt;
    const axisSize = rt.layout[L.axisSize];
    const [a, d, c, out] = rt.carve([axisSize * 2, 4 * obs.discrete.length, 4 * obs.continuous.length, 4 * count]);
    const heap = rt.heap;
    checked.forEach((axis, i) => heap.u32.set(axis, (a + i * axisSize) >> 2));
    writeObservation(heap, obs, d, c);
    rt.check(rt.m._verve_agent_sample_values(h, a, checked.length, d, obs.discrete.length, c, obs.continuous.length, out, count));
    return rt.heap.f32.slice(out >> 2, (out >> 2) + count);
  }

  /** An XML save as a string. */
  saveString() { return new TextDecoder().decode(this.saveBytes()); }
  /** An XML save as UTF-8 bytes. */
  saveBytes() { return save(this.rt, '_verve_agent_save_memory', this.live()); }
  /** A save in the compact binary format (checksummed; faster to save and load). */
  saveBinaryBytes() { return save(this.rt, '_verve_agent_save_memory_binary', this.live()); }

  toString() {
    if (this.handle === 0) return 'verve.Agent (disposed)';
    return `verve.Agent (${this.numDiscrete} discrete, ${this.numContinuous} continuous sensors, ${this.numActions} actions)`;
  }
}

if (typeof Symbol.dispose === 'symbol') Agent.prototype[Symbol.dispose] = Agent.prototype.dispose;
