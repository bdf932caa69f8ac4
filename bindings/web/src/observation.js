// Observations, masks and other arrays from JavaScript into wasm memory, checked first: a wrong
// type or an absurd length is refused before anything is allocated or written.
import { invalidArgument } from './errors.js';
import { MAX_CONTINUOUS_ACTIONS, MAX_CONTINUOUS_SENSORS, MAX_DISCRETE_SENSORS } from './descriptor.js';

function describe(value) {
  if (value === null) return 'null';
  return typeof value === 'number' ? `number ${value}` : typeof value;
}

function list(what, value, max) {
  if (value === undefined || value === null) return [];
  if (!Array.isArray(value) && !ArrayBuffer.isView(value)) throw invalidArgument(`${what} must be an array or a typed array (got ${describe(value)})`);
  if (value.length > max) throw invalidArgument(`${what} has ${value.length} values, at most ${max}`);
  return value;
}

/** {discrete, continuous} checked: integers and numbers, at most 64 of each. */
export function checkObservation(what, obs) {
  if (obs === undefined || obs === null) return { discrete: [], continuous: [] };
  if (typeof obs !== 'object' || Array.isArray(obs) || ArrayBuffer.isView(obs)) {
    throw invalidArgument(`${what} must be an object {discrete, continuous} (got ${Array.isArray(obs) ? 'array' : describe(obs)})`);
  }
  const discrete = list(`${what}.discrete`, obs.discrete, MAX_DISCRETE_SENSORS);
  const continuous = list(`${what}.continuous`, obs.continuous, MAX_CONTINUOUS_SENSORS);
  for (let i = 0; i < discrete.length; ++i) {
    const v = discrete[i];
    if (!Number.isInteger(v) || v < -0x80000000 || v > 0x7fffffff) {
      throw invalidArgument(`${what}.discrete[${i}] must be an integer (got ${describe(v)})`);
    }
  }
  if (!(continuous instanceof Float32Array) && !(continuous instanceof Float64Array)) {
    for (let i = 0; i < continuous.length; ++i) {
      if (typeof continuous[i] !== 'number') throw invalidArgument(`${what}.continuous[${i}] must be a number (got ${describe(continuous[i])})`);
    }
  }
  return { discrete, continuous };
}

/**
 * A teacher's continuous actions: an array or typed array of numbers, at most MAX_CONTINUOUS_ACTIONS; NaN and values outside [-1, 1] pass on, for the library to refuse with its message.
 */
export function checkContinuousValues(what, values) {
  if (!Array.isArray(values) && !ArrayBuffer.isView(values)) throw invalidArgument(`${what} must be an array or a typed array (got ${describe(values)})`);
  if (values.length > MAX_CONTINUOUS_ACTIONS) throw invalidArgument(`${what} has ${values.length} values, at most ${MAX_CONTINUOUS_ACTIONS}`);
  for (let i = 0; i < values.length; ++i) {
    if (typeof values[i] !== 'number') throw invalidArgument(`${what}[${i}] must be a number (got ${describe(values[i])})`);
  }
  return values;
}

/** A number argument; NaN and infinities pass on, for the library to refuse with its message. */
export function checkNumber(what, value) {
  if (typeof value !== 'number') throw invalidArgument(`${what} must be a number (got ${describe(value)})`);
  return value;
}

/**
 * A mask: one flag per action, or with action branches (`branches`, their sizes) one per choice of
 * each branch, branch after branch (`numFlags` = the sizes summed).
 */
export function checkMask(mask, numFlags, branches = []) {
  if (!Array.isArray(mask) && !ArrayBuffer.isView(mask)) throw invalidArgument(`the action mask must be an array (got ${describe(mask)})`);
  if (mask.length !== numFlags) {
    throw invalidArgument(branches.length === 0
      ? `the action mask has ${mask.length} entries, the agent has ${numFlags} actions`
      : `the action mask has ${mask.length} entries, the agent's action branches [${branches.join(', ')}] have ${numFlags} choices (one flag per choice of each branch)`);
  }
  for (let i = 0; i < mask.length; ++i) {
    const v = mask[i];
    if (typeof v !== 'boolean' && v !== 0 && v !== 1) throw invalidArgument(`mask[${i}] must be a boolean, 0 or 1 (got ${describe(v)})`);
  }
  return mask;
}

/** Writes an observation at the two pointers (int32 and float32 values). */
export function writeObservation(heap, obs, discretePtr, continuousPtr) {
  heap.i32.set(obs.discrete, discretePtr >> 2);
  heap.f32.set(obs.continuous, continuousPtr >> 2);
}
