// Verve for JavaScript: the C ABI compiled to WebAssembly, as a thin typed mirror (docs/web.md).
//
//   import { loadVerve } from 'verve-web';
//   const verve = await loadVerve();
//   const agent = verve.createAgent({ continuous: 2, actions: 3 });
//   const action = agent.update(reward, { continuous: [x, v] }, 1 / 60);
import { VerveError, invalidArgument } from './errors.js';
import { L, checkDescriptor, readDescriptor, writeDescriptor } from './descriptor.js';
import { instantiate } from './module.js';
import { Runtime } from './runtime.js';
import { Agent } from './agent.js';
import { Brain } from './brain.js';
import { Batch } from './batch.js';
import { Recording } from './recording.js';
import { load } from './saves.js';

export { VerveError, RESULT_NAMES } from './errors.js';
export { Agent } from './agent.js';
export { Brain } from './brain.js';
export { Batch } from './batch.js';
export { Recording } from './recording.js';

/** The library's major version this binding speaks to. */
export const BINDING_MAJOR_VERSION = 0;

export class Verve {
  /** @internal Use loadVerve(). */
  constructor(module) {
    this.rt = new Runtime(module);
    const v = this.version();
    if (v.major !== BINDING_MAJOR_VERSION) {
      throw new VerveError(`verve: the wasm module is version ${v.text}, this binding speaks to ${BINDING_MAJOR_VERSION}.x`, 5);
    }
    // libverve's log hook, a queue that takeWarnings() empties: installed before any agent exists
    // (libverve refuses hooks while it holds memory; a fresh module holds none).
    if (!this.rt.m._verve_web_install_warnings()) {
      throw new VerveError(`verve: the warning hook could not be installed: ${this.rt.lastError()}`, 2);
    }
  }

  /**
   * libverve's warnings since the previous call, oldest first (usually none): a reward clamped to
   * [-1, 1], an agent's RBF budget reached, each once per agent (also counted in agent.stats() as
   * clampedRewards and rbfBudgetHits). At most 64 are kept between calls; a last entry counts the rest.
   */
  takeWarnings() {
    const text = this.rt.m.UTF8ToString(this.rt.m._verve_web_take_warnings());
    return text === '' ? [] : text.slice(0, -1).split('\n');
  }

  /** The library's version: {major, minor, patch, number, text}. */
  version() {
    const number = this.rt.m._verve_version() >>> 0;
    const major = number >>> 16;
    const minor = (number >>> 8) & 0xff;
    const patch = number & 0xff;
    return { major, minor, patch, number, text: `${major}.${minor}.${patch}` };
  }

  /** Every descriptor field at its default. */
  defaults() {
    const rt = this.rt;
    const [p] = rt.carve([rt.layout[L.descSize]]);
    rt.m._verve_agent_desc_default(p);
    return readDescriptor(rt.heap, rt.layout, p);
  }

  descriptorPointer(desc) {
    const checked = checkDescriptor(desc);
    const rt = this.rt;
    const [p, out] = rt.carve([rt.layout[L.descSize], 4]);
    rt.m._verve_agent_desc_default(p);
    writeDescriptor(rt.heap, rt.layout, p, checked);
    return [p, out];
  }

  createAgent(desc) {
    const [p, out] = this.descriptorPointer(desc);
    this.rt.check(this.rt.m._verve_agent_create(p, out));
    return new Agent(this.rt, this.rt.heap.u32[out >> 2]);
  }

  /** An agent from a save (XML string or bytes, or binary bytes) of an agent or a brain. */
  loadAgent(data) {
    return new Agent(this.rt, load(this.rt, '_verve_agent_load_memory', data));
  }

  createBrain(desc) {
    const [p, out] = this.descriptorPointer(desc);
    this.rt.check(this.rt.m._verve_brain_create(p, out));
    return new Brain(this.rt, this.rt.heap.u32[out >> 2]);
  }

  loadBrain(data) {
    return new Brain(this.rt, load(this.rt, '_verve_brain_load_memory', data));
  }

  /** An empty recording of demonstrated steps with `agent`'s sensors and actions (docs/teaching.md). */
  createRecording(agent) {
    if (!(agent instanceof Agent)) throw invalidArgument('createRecording takes an Agent');
    const [out] = this.rt.carve([4]);
    this.rt.check(this.rt.m._verve_recording_create(agent.live(), out));
    return new Recording(this.rt, this.rt.heap.u32[out >> 2]);
  }

  /** A recording from the bytes Recording.saveBytes made. */
  loadRecording(data) {
    return new Recording(this.rt, load(this.rt, '_verve_recording_load_memory', data));
  }

  /** A batch for many agents per call (single-threaded in this build). */
  createBatch(options) {
    if (options !== undefined && (options === null || typeof options !== 'object' || Object.keys(options).length > 0)) {
      throw invalidArgument('createBatch takes no options in this build (it is single-threaded)');
    }
    return new Batch(this.rt);
  }

  /** The Emscripten module underneath (its FS, its memory): for tests and tools. */
  get module() { return this.rt.m; }
}

/**
 * Loads the wasm module and returns the API over it. options.wasmUrl (browser) or
 * options.wasmBinary (bytes) say where the .wasm comes from, when not beside dist/verve_wasm.mjs.
 */
export async function loadVerve(options = {}) {
  return new Verve(await instantiate(options));
}
