// A recording: demonstrated steps kept for replay (docs/teaching.md, "Recordings"). Every entry is
// checked as the agent would check it when it is added; a refused one is not recorded.
import { invalidArgument, invalidState } from './errors.js';
import { checkContinuousValues, checkNumber, checkObservation, writeObservation } from './observation.js';
import { save } from './saves.js';

export class Recording {
  /** @internal Made by Verve.createRecording and Verve.loadRecording. */
  constructor(rt, handle) {
    this.rt = rt;
    this.handle = handle;
    rt.track(this, '_verve_recording_destroy', handle);
  }

  get disposed() { return this.handle === 0; }

  live() {
    if (this.handle === 0) throw invalidState('the recording is disposed');
    return this.handle;
  }

  dispose() {
    if (this.handle === 0) return;
    this.rt.untrack(this);
    this.rt.m._verve_recording_destroy(this.handle);
    this.handle = 0;
  }

  /** One demonstrated step, as Agent.updateDemonstrated takes it (no mask). */
  addStep(reward, observation, dt, action) {
    const h = this.live();
    checkNumber('reward', reward);
    const obs = checkObservation('observation', observation);
    checkNumber('dt', dt);
    if (!Number.isInteger(action) || action < 0 || action > 0xffffffff) {
      throw invalidArgument(`action must be an integer from 0, got ${String(action)}`);
    }
    const rt = this.rt;
    const [d, c] = rt.carve([4 * obs.discrete.length, 4 * obs.continuous.length]);
    writeObservation(rt.heap, obs, d, c);
    rt.check(rt.m._verve_recording_add_step(h, reward, d, obs.discrete.length, c, obs.continuous.length, dt, action));
  }

  /** One demonstrated step with the host's continuous actions, as Agent.updateDemonstratedContinuous takes it (no mask). */
  addStepContinuous(reward, observation, dt, action, continuousAction) {
    const h = this.live();
    checkNumber('reward', reward);
    const obs = checkObservation('observation', observation);
    checkNumber('dt', dt);
    if (!Number.isInteger(action) || action < 0 || action > 0xffffffff) {
      throw invalidArgument(`action must be an integer from 0, got ${String(action)}`);
    }
    const values = checkContinuousValues('continuousAction', continuousAction);
    const rt = this.rt;
    const [d, c, v] = rt.carve([4 * obs.discrete.length, 4 * obs.continuous.length, 4 * values.length]);
    writeObservation(rt.heap, obs, d, c);
    rt.heap.f32.set(values, v >> 2);
    rt.check(rt.m._verve_recording_add_step_continuous(h, reward, d, obs.discrete.length, c, obs.continuous.length, dt, action,
      values.length ? v : 0, values.length));
  }

  addEndEpisode(finalReward) {
    const h = this.live();
    this.rt.check(this.rt.m._verve_recording_add_end_episode(h, checkNumber('finalReward', finalReward)));
  }

  addTruncation(reward) {
    const h = this.live();
    this.rt.check(this.rt.m._verve_recording_add_truncation(h, checkNumber('reward', reward)));
  }

  /** Entries so far (steps and trial ends). */
  size() {
    const h = this.live();
    const [out] = this.rt.carve([8]);
    this.rt.check(this.rt.m._verve_recording_get_size(h, out));
    return Number(this.rt.heap.u32[out >> 2]) + 2 ** 32 * this.rt.heap.u32[(out >> 2) + 1];
  }

  /** The recording's file as bytes. */
  saveBytes() { return save(this.rt, '_verve_recording_save_memory', this.live()); }
}

if (typeof Symbol.dispose === 'symbol') Recording.prototype[Symbol.dispose] = Recording.prototype.dispose;
