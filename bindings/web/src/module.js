// Loading the wasm module: in a browser (or a worker) the .wasm is fetched from beside
// dist/verve_wasm.mjs, or from options.wasmUrl; in Node.js it is read from the package's dist/.
import createVerveModule from '../dist/verve_wasm.mjs';

const isNode = typeof process === 'object' && process.versions != null && process.versions.node != null;

/**
 * Instantiates the module. options.wasmBinary (bytes) or options.wasmUrl override where the
 * .wasm comes from; options.factory replaces the Emscripten factory (tests use a variant).
 */
export async function instantiate(options = {}) {
  const factory = options.factory ?? createVerveModule;
  const moduleOptions = {};
  if (options.wasmBinary) {
    moduleOptions.wasmBinary = options.wasmBinary;
  } else if (options.wasmUrl) {
    moduleOptions.locateFile = () => String(options.wasmUrl);
  } else if (isNode) {
    const { readFile } = await import('node:fs/promises');
    const url = options.wasmFile ?? new URL('../dist/verve_wasm.wasm', import.meta.url);
    moduleOptions.wasmBinary = await readFile(url);
  }
  moduleOptions.print = () => {};
  moduleOptions.printErr = () => {};
  return factory(moduleOptions);
}
