// Shared by the tests: the module (one per test file), and a check that a refused call changed nothing.
import assert from 'node:assert/strict';
import { loadVerve, VerveError } from '../src/index.js';

export const verve = await loadVerve();

/** Asserts that fn throws a VerveError with the given code and that agent's save is unchanged. */
export function refused(agent, fn, code = 'VERVE_ERROR_INVALID_ARGUMENT', pattern) {
  const before = agent.saveBinaryBytes();
  assert.throws(fn, (e) => {
    assert.ok(e instanceof VerveError, `not a VerveError: ${e}`);
    assert.equal(e.code, code, e.message);
    if (pattern) assert.match(e.message, pattern);
    return true;
  });
  assert.deepEqual(agent.saveBinaryBytes(), before, 'a refused call changed the agent');
}

/** A small deterministic generator (mulberry32) for tests and the fuzz loop. */
export function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
