// The binding's view of one wasm instance: typed views of its memory, a scratch area for the
// arguments of one call, checked calls that turn a failed verve_result into a VerveError, and the
// FinalizationRegistry that frees handles a program forgot to dispose().
import { VerveError, OK, OUT_OF_MEMORY } from './errors.js';
import { LAYOUT_LENGTH } from './descriptor.js';

export class Runtime {
  constructor(module) {
    this.m = module;
    this.scratchPtr = 0;
    this.scratchSize = 0;
    const countPtr = this.carve([4])[0];
    const tablePtr = module._verve_web_layout(countPtr);
    const count = this.heap.u32[countPtr >> 2];
    if (count !== LAYOUT_LENGTH) throw new VerveError(`verve: the wasm module's layout table has ${count} entries, the binding expects ${LAYOUT_LENGTH}`, 8);
    this.layout = Array.from(this.heap.u32.subarray(tablePtr >> 2, (tablePtr >> 2) + count));
    // Frees what the program dropped without dispose(); a handle is freed once either way.
    this.registry = typeof FinalizationRegistry === 'function'
      ? new FinalizationRegistry(({ destroy, handle }) => { this.m[destroy](handle); })
      : null;
  }

  /** Views of the memory, fresh after every call that may have grown it. */
  get heap() {
    const buffer = this.m.HEAPU8.buffer;
    if (this.views?.buffer !== buffer) {
      this.views = {
        buffer,
        u8: new Uint8Array(buffer),
        i32: new Int32Array(buffer),
        u32: new Uint32Array(buffer),
        f32: new Float32Array(buffer),
      };
    }
    return this.views;
  }

  /**
   * Room for one call's arguments: one pointer per size (8-byte aligned), valid until the next
   * carve. The area grows as needed and is kept; running out of memory here changes nothing.
   */
  carve(sizes) {
    let total = 0;
    const offsets = sizes.map((size) => {
      const at = total;
      total += (size + 7) & ~7;
      return at;
    });
    if (total > this.scratchSize) {
      const size = Math.max(total, 256, this.scratchSize * 2);
      const ptr = this.m._malloc(size);
      if (ptr === 0) throw new VerveError(`verve: out of memory for a call's arguments (${total} bytes)`, OUT_OF_MEMORY);
      if (this.scratchPtr) this.m._free(this.scratchPtr);
      this.scratchPtr = ptr;
      this.scratchSize = size;
    }
    return offsets.map((at) => this.scratchPtr + at);
  }

  /**
   * carve() for a single block, without the arrays carve() makes: read-outs a game calls every
   * frame into its own buffer (Agent.continuousAction(out)) then allocate nothing.
   */
  carveOne(size) {
    if (size > this.scratchSize) this.carve([size]);
    return this.scratchPtr;
  }

  /** Bytes copied into a fresh malloc'ed block (the caller frees it). */
  copyIn(bytes) {
    const ptr = this.m._malloc(Math.max(bytes.length, 1));
    if (ptr === 0) throw new VerveError(`verve: out of memory for ${bytes.length} bytes of input`, OUT_OF_MEMORY);
    this.heap.u8.set(bytes, ptr);
    return ptr;
  }

  lastError() {
    return this.m.UTF8ToString(this.m._verve_last_error());
  }

  /** Throws the library's message when rc is not VERVE_OK. */
  check(rc) {
    if (rc !== OK) throw new VerveError(this.lastError() || `verve: failed`, rc);
  }

  track(owner, destroy, handle) {
    this.registry?.register(owner, { destroy, handle }, owner);
  }

  untrack(owner) {
    this.registry?.unregister(owner);
  }
}
