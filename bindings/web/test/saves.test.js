// Saves to and from memory: XML strings and bytes, binary bytes, brains and agents across, and
// hostile bytes (truncated, flipped, random, absurd) refused with a clear error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VerveError } from '../src/index.js';
import { verve, random } from './helpers.js';
import { HotPlate } from './hot_plate.js';

function trainedPlate(continuous) {
  const task = new HotPlate({ continuous, seed: 2 });
  const agent = verve.createAgent(task.descriptor({ seed: 2 }));
  for (let t = 0; t < 10; ++t) task.runTrial(agent, 0.1, 1000);
  return { task, agent };
}

test('a loaded agent acts exactly as the saved one, from XML and binary', () => {
  for (const continuous of [false, true]) {
    const { task, agent } = trainedPlate(continuous);
    const saves = [agent.saveString(), agent.saveBytes(), agent.saveBinaryBytes(), agent.saveBinaryBytes().buffer];
    assert.match(saves[0], /^<\?xml/);
    assert.ok(saves[2].length < saves[1].length, 'binary is smaller');
    const copies = saves.map((s) => verve.loadAgent(s));
    const expected = [];
    const t0 = new HotPlate({ continuous, seed: 9 });
    for (let t = 0; t < 5; ++t) t0.runTrial(agent, 0.1, 1000, expected);
    for (const copy of copies) {
      const actions = [];
      const t1 = new HotPlate({ continuous, seed: 9 });
      for (let t = 0; t < 5; ++t) t1.runTrial(copy, 0.1, 1000, actions);
      assert.deepEqual(actions, expected);
      copy.dispose();
    }
    agent.dispose();
    void task;
  }
});

test('brain and agent saves load either way', () => {
  const brain = verve.createBrain({ continuous: 2, actions: 3 });
  const body = brain.createBody();
  for (let i = 0; i < 50; ++i) body.update(0.1, { continuous: [Math.sin(i), Math.cos(i)] }, 0.1);
  const asAgent = verve.loadAgent(brain.saveBinaryBytes());
  const asBrain = verve.loadBrain(body.saveString());
  assert.equal(asAgent.rbfCount(), brain.rbfCount());
  assert.equal(asBrain.rbfCount(), brain.rbfCount());
  for (const x of [asAgent, asBrain, body, brain]) x.dispose();
});

test('hostile saves: truncated, flipped, random and absurd inputs are refused', () => {
  const { agent } = trainedPlate(true);
  const xml = agent.saveBytes();
  const bin = agent.saveBinaryBytes();
  const next = random(42);
  let refusedCount = 0;
  for (const good of [xml, bin]) {
    for (let i = 0; i < 150; ++i) {
      const bytes = good.slice();
      const kind = i % 3;
      let input = bytes;
      if (kind === 0) input = bytes.subarray(0, Math.floor(next() * bytes.length));
      else if (kind === 1) for (let k = 0; k < 1 + next() * 4; ++k) bytes[Math.floor(next() * bytes.length)] ^= 1 << Math.floor(next() * 8);
      else input = Uint8Array.from({ length: Math.floor(next() * 300) }, () => Math.floor(next() * 256));
      try {
        verve.loadAgent(input).dispose();  // a flip inside XML text may still be a valid save
      } catch (e) {
        assert.ok(e instanceof VerveError, String(e));
        assert.match(e.code, /FORMAT|VERSION|INVALID_ARGUMENT/, e.message);
        ++refusedCount;
      }
    }
  }
  assert.ok(refusedCount > 200, `only ${refusedCount} refused`);
  for (const bad of [null, 42, {}, [1, 2, 3], new Uint8Array(0), '']) {
    assert.throws(() => verve.loadAgent(bad), VerveError);
  }
  assert.throws(() => verve.loadAgent({ length: 2 ** 40 }), /string, Uint8Array or ArrayBuffer/);
  // Deep nesting, open and closed: a format error, not a stack overflow that would trap the module.
  for (const depth of [100000, 1000000]) {
    assert.throws(() => verve.loadAgent('<x>'.repeat(depth)), /not well-formed/);
    assert.throws(() => verve.loadAgent(`<verve_agent format_version="1">${'<x>'.repeat(depth)}${'</x>'.repeat(depth)}</verve_agent>`), /missing <descriptor>/);
  }
  // The agent that was saved is untouched by all of it.
  assert.deepEqual(agent.saveBinaryBytes(), bin);
  agent.dispose();
});

test("the C ABI's file saves work on Emscripten's in-memory file system", () => {
  const { agent } = trainedPlate(false);
  const m = verve.module;
  const rt = agent.rt;
  const path = '/tmp/npc.xml';
  const saves = [['_verve_agent_save', agent.saveBytes()], ['_verve_agent_save_binary', agent.saveBinaryBytes()]];
  const p = m._malloc(64);  // not the binding's scratch area, which the next call reuses
  m.stringToUTF8(path, p, 64);
  for (const [save, bytes] of saves) {
    assert.equal(m[save](agent.handle, p), 0, rt.lastError());
    assert.deepEqual(m.FS.readFile(path), bytes);  // written to a temporary name, then renamed over
    assert.deepEqual(m.FS.readdir('/tmp').filter((n) => n !== '.' && n !== '..'), ['npc.xml']);
  }
  const copy = verve.loadAgent(m.FS.readFile(path));
  assert.equal(copy.rbfCount(), agent.rbfCount());
  m.stringToUTF8('/no/such/dir/npc.xml', p, 64);
  assert.equal(m._verve_agent_save(agent.handle, p), 3);  // VERVE_ERROR_IO
  assert.match(rt.lastError(), /no\/such\/dir/);
  m._free(p);
  copy.dispose();
  agent.dispose();
});

test('a recording of demonstrated steps round-trips through bytes and replays as the steps did', () => {
  const desc = { discrete: [2], continuous: 1, actions: 3, seed: 4 };
  const shown = verve.createAgent(desc);
  const replayed = verve.createAgent(desc);
  const rec = verve.createRecording(shown);
  for (let i = 0; i < 30; ++i) {
    const obs = { discrete: [i % 2], continuous: [Math.sin(i)] };
    rec.addStep(0.1, obs, 0.1, i % 3);
    shown.updateDemonstrated(0.1, obs, 0.1, i % 3);
    if (i % 10 === 9) { rec.addEndEpisode(1); shown.endEpisode(1); }
  }
  rec.addTruncation(0);
  shown.truncateEpisode(0);
  assert.equal(rec.size(), 34);
  const copy = verve.loadRecording(rec.saveBytes());
  assert.deepEqual(copy.saveBytes(), rec.saveBytes());
  replayed.replay(copy);
  assert.deepEqual(replayed.saveBinaryBytes(), shown.saveBinaryBytes());
  const before = rec.saveBytes();
  assert.throws(() => rec.addStep(0, { discrete: [2], continuous: [0] }, 0.1, 0), VerveError);
  assert.throws(() => rec.addStep(0, { discrete: [0], continuous: [0] }, 0.1, -1), /action/);
  assert.deepEqual(rec.saveBytes(), before);
  const damaged = before.slice();
  damaged[damaged.length >> 1] ^= 0x10;
  assert.throws(() => verve.loadRecording(damaged), /checksum/);
  const stranger = verve.createAgent({ continuous: 2, actions: 2 });
  assert.throws(() => stranger.replay(copy), /not the agent's/);
  for (const x of [shown, replayed, rec, copy, stranger]) x.dispose();
  assert.throws(() => rec.size(), /disposed/);
});
