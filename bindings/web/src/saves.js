// Saves to and from memory: XML (a string or its UTF-8 bytes) or the compact binary format, both
// read by the same loads (told apart by their first bytes). Nothing touches a file system.
import { invalidArgument, VerveError, OUT_OF_MEMORY } from './errors.js';

/** The largest save a load accepts: as the library's own limit on save files (1 GiB). */
export const MAX_SAVE_BYTES = 2 ** 30;

/** A save given as a string, Uint8Array, ArrayBuffer or other view, as bytes. */
export function saveBytes(data) {
  let bytes;
  if (typeof data === 'string') {
    if (data.length > MAX_SAVE_BYTES) throw invalidArgument(`the save has ${data.length} characters, at most ${MAX_SAVE_BYTES} bytes are read`);
    bytes = new TextEncoder().encode(data);
  } else if (data instanceof Uint8Array) {
    bytes = data;
  } else if (data instanceof ArrayBuffer) {
    bytes = new Uint8Array(data);
  } else if (ArrayBuffer.isView(data)) {
    bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  } else {
    throw invalidArgument(`a save must be a string, Uint8Array or ArrayBuffer (got ${data === null ? 'null' : typeof data})`);
  }
  if (bytes.length > MAX_SAVE_BYTES) throw invalidArgument(`the save has ${bytes.length} bytes, at most ${MAX_SAVE_BYTES} are read`);
  return bytes;
}

/** Loads through fn(data, size, out) and returns the new handle. */
export function load(rt, fn, data) {
  const bytes = saveBytes(data);
  const [outPtr] = rt.carve([4]);
  const dataPtr = rt.copyIn(bytes);
  try {
    rt.check(rt.m[fn](dataPtr, bytes.length, outPtr));
    return rt.heap.u32[outPtr >> 2];
  } finally {
    rt.m._free(dataPtr);
  }
}

/** A save through fn(handle, buffer, size*), the C ABI's two-call pattern, as a new Uint8Array. */
export function save(rt, fn, handle) {
  const [sizePtr] = rt.carve([4]);
  rt.heap.u32[sizePtr >> 2] = 0;
  rt.check(rt.m[fn](handle, 0, sizePtr));
  const size = rt.heap.u32[sizePtr >> 2];
  const buffer = rt.m._malloc(Math.max(size, 1));
  if (buffer === 0) throw new VerveError(`verve: out of memory for a save of ${size} bytes`, OUT_OF_MEMORY);
  try {
    rt.check(rt.m[fn](handle, buffer, sizePtr));
    const written = rt.heap.u32[sizePtr >> 2];
    return rt.heap.u8.slice(buffer, buffer + written);
  } finally {
    rt.m._free(buffer);
  }
}
