// A brain: one learner (RBFs, weights, model) shared by many bodies, each an Agent with its own
// short-term memory. A body keeps its brain alive in the library, so either may be disposed first.
import { invalidState } from './errors.js';
import { Agent } from './agent.js';
import { save } from './saves.js';

export class Brain {
  /** @internal Made by Verve.createBrain and Verve.loadBrain. */
  constructor(rt, handle) {
    this.rt = rt;
    this.handle = handle;
    rt.track(this, '_verve_brain_destroy', handle);
  }

  get disposed() { return this.handle === 0; }

  live() {
    if (this.handle === 0) throw invalidState('the brain is disposed');
    return this.handle;
  }

  dispose() {
    if (this.handle === 0) return;
    this.rt.untrack(this);
    this.rt.m._verve_brain_destroy(this.handle);
    this.handle = 0;
  }

  /** A new body: an Agent that learns into this brain. Body k draws from the random stream (seed, k). */
  createBody() {
    const h = this.live();
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m._verve_brain_create_body(h, out));
    return new Agent(this.rt, this.rt.heap.u32[out >> 2], this);
  }

  rbfCount() {
    const h = this.live();
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m._verve_brain_get_rbf_count(h, out));
    return this.rt.heap.u32[out >> 2];
  }

  saveString() { return new TextDecoder().decode(this.saveBytes()); }
  saveBytes() { return save(this.rt, '_verve_brain_save_memory', this.live()); }
  saveBinaryBytes() { return save(this.rt, '_verve_brain_save_memory_binary', this.live()); }
}

if (typeof Symbol.dispose === 'symbol') Brain.prototype[Symbol.dispose] = Brain.prototype.dispose;
