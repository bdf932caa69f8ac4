// Handles are freed by dispose(), or by the FinalizationRegistry when a program forgets: observed
// through verve_set_hooks, which the library refuses while it holds any memory.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { setTimeout as sleep } from 'node:timers/promises';
import { verve } from './helpers.js';

const holdsMemory = () => verve.module._verve_set_hooks(0) !== 0;

test('dispose() frees agents, bodies, brains and batches', () => {
  assert.equal(holdsMemory(), false);
  const agent = verve.createAgent({ continuous: 2, actions: 3 });
  agent.update(0, { continuous: [0.1, 0.2] }, 0.1);
  const brain = verve.createBrain({ actions: 2 });
  const body = brain.createBody();
  const batch = verve.createBatch();
  assert.equal(holdsMemory(), true);
  for (const x of [agent, body, batch]) x.dispose();
  assert.equal(holdsMemory(), true, 'the brain is still there');
  brain.dispose();
  assert.equal(holdsMemory(), false);
});

test('forgotten handles are freed once collected', { skip: typeof globalThis.gc !== 'function' && 'needs node --expose-gc' }, async () => {
  (() => {
    const brain = verve.createBrain({ actions: 2 });
    for (let i = 0; i < 3; ++i) brain.createBody().update(0, null, 0.1);
    verve.createAgent({ continuous: 1, actions: 2 }).update(0, { continuous: [0.5] }, 0.1);
  })();
  assert.equal(holdsMemory(), true);
  for (let i = 0; i < 50 && holdsMemory(); ++i) {
    globalThis.gc();
    await sleep(10);
  }
  assert.equal(holdsMemory(), false);
});
