// A batch: one step of many agents in one call, exactly as the same updates one by one in array
// order. The web build is single-threaded, so a batch saves the per-call overhead, not time on
// other cores.
import { invalidArgument, invalidState } from './errors.js';
import { Agent } from './agent.js';
import { L } from './descriptor.js';
import { checkContinuousValues, checkNumber, checkObservation } from './observation.js';

/** The most agents one batch.update takes. */
export const MAX_BATCH_AGENTS = 2 ** 20;

export class Batch {
  /** @internal Made by Verve.createBatch. */
  constructor(rt) {
    this.rt = rt;
    const [desc, out] = rt.carve([rt.layout[L.batchDescSize], 4]);
    rt.check(rt.m._verve_batch_desc_default(desc));
    rt.heap.u32[(desc + rt.layout[L.batchWorkerCount]) >> 2] = 1;  // no threads in this build
    rt.check(rt.m._verve_batch_create(desc, out));
    this.handle = rt.heap.u32[out >> 2];
    rt.track(this, '_verve_batch_destroy', this.handle);
  }

  get disposed() { return this.handle === 0; }

  dispose() {
    if (this.handle === 0) return;
    this.rt.untrack(this);
    this.rt.m._verve_batch_destroy(this.handle);
    this.handle = 0;
  }

  /**
   * One step of every agent: agents[i] earns rewards[i] and sees observations[i]. Returns the
   * actions (into `out`, a Uint32Array, when given). `demonstrated`, when given, holds per agent the
   * action the player or a scripted AI took (as Agent.updateDemonstrated takes it), or null for the
   * agent's own choice (docs/teaching.md); `continuousActions`, when given too, per agent shown an
   * action the continuous actions played (as Agent.updateDemonstratedContinuous takes them; unread,
   * may be null, for the agents that choose). On any bad input nothing changes.
   */
  update(agents, rewards, observations, dt, out, demonstrated, continuousActions) {
    if (this.handle === 0) throw invalidState('the batch is disposed');
    if (!Array.isArray(agents)) throw invalidArgument('batch.update: agents must be an array of agents');
    const n = agents.length;
    if (n > MAX_BATCH_AGENTS) throw invalidArgument(`batch.update: ${n} agents, at most ${MAX_BATCH_AGENTS}`);
    if ((!Array.isArray(rewards) && !ArrayBuffer.isView(rewards)) || rewards.length !== n) {
      throw invalidArgument(`batch.update: rewards must be an array of ${n} numbers`);
    }
    if (!Array.isArray(observations) || observations.length !== n) {
      throw invalidArgument(`batch.update: observations must be an array of ${n} observations`);
    }
    checkNumber('dt', dt);
    if (out !== undefined && (!(out instanceof Uint32Array) || out.length < n)) {
      throw invalidArgument(`batch.update: out must be a Uint32Array of at least ${n} entries`);
    }
    if (demonstrated !== undefined && (!Array.isArray(demonstrated) || demonstrated.length !== n)) {
      throw invalidArgument(`batch.update: demonstrated must be an array of ${n} actions or nulls`);
    }
    if (continuousActions !== undefined && (demonstrated === undefined || !Array.isArray(continuousActions) ||
        continuousActions.length !== n)) {
      throw invalidArgument(`batch.update: continuousActions must come after demonstrated, an array of ${n} arrays of values or nulls`);
    }
    let nv = 0;
    let nd = 0;
    let nc = 0;
    const checked = new Array(n);
    for (let i = 0; i < n; ++i) {
      const agent = agents[i];
      if (!(agent instanceof Agent) || agent.rt !== this.rt) throw invalidArgument(`batch.update: agents[${i}] is not an agent of this module`);
      if (agent.disposed) throw invalidState(`batch.update: agents[${i}] is disposed`);
      checkNumber(`rewards[${i}]`, rewards[i]);
      checked[i] = checkObservation(`observations[${i}]`, observations[i]);
      const shown = demonstrated === undefined ? null : demonstrated[i];
      if (shown !== null && (!Number.isInteger(shown) || shown < 0 || shown >= agent.numActions)) {
        throw invalidArgument(`batch.update: demonstrated[${i}] must be an action in 0..${agent.numActions - 1} or null`);
      }
      if (continuousActions !== undefined && shown !== null) {
        const values = checkContinuousValues(`continuousActions[${i}]`, continuousActions[i]);
        if (values.length !== agent.numContinuousActions) {
          throw invalidArgument(`batch.update: continuousActions[${i}] has ${values.length} values, agents[${i}] has ${agent.numContinuousActions} continuous actions`);
        }
      }
      nv += agent.numContinuousActions;
      nd += checked[i].discrete.length;
      nc += checked[i].continuous.length;
    }
    const rt = this.rt;
    const [a, r, d, c, actions, results, shown, v] = rt.carve([4 * n, 4 * n, 4 * nd, 4 * nc, 4 * n, 4 * n, 4 * n, 4 * nv]);
    const { u32, i32, f32 } = rt.heap;
    let di = d >> 2;
    let ci = c >> 2;
    let vi = v >> 2;
    for (let i = 0; i < n; ++i) {
      u32[(a >> 2) + i] = agents[i].handle;
      if (demonstrated !== undefined) u32[(shown >> 2) + i] = demonstrated[i] === null ? 0xffffffff : demonstrated[i];
      f32[(r >> 2) + i] = rewards[i];
      i32.set(checked[i].discrete, di);
      f32.set(checked[i].continuous, ci);
      di += checked[i].discrete.length;
      ci += checked[i].continuous.length;
      if (continuousActions !== undefined) {  // every agent's count, packed; unread where it chooses
        if (demonstrated[i] !== null) f32.set(continuousActions[i], vi);
        vi += agents[i].numContinuousActions;
      }
    }
    rt.check(demonstrated === undefined
      ? rt.m._verve_batch_update(this.handle, a, n, r, d, 0, nd, c, 0, nc, dt, actions, results)
      : continuousActions === undefined
      ? rt.m._verve_batch_update_demonstrated(this.handle, a, n, r, d, 0, nd, c, 0, nc, dt, shown, actions, results)
      : rt.m._verve_batch_update_demonstrated_continuous(this.handle, a, n, r, d, 0, nd, c, 0, nc, dt, shown,
        nv ? v : 0, 0, nv, actions, results));
    const view = rt.heap.u32.subarray(actions >> 2, (actions >> 2) + n);
    if (out) {
      out.set(view);
      return out;
    }
    return view.slice();
  }
}

if (typeof Symbol.dispose === 'symbol') Batch.prototype[Symbol.dispose] = Batch.prototype.dispose;
