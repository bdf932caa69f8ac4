// Compiled (not run) by scripts/test_web.sh with tsc --noEmit: index.d.ts describes what a game
// writes, and refuses what the API refuses at the type level.
import { loadVerve, VerveError, type Agent, type AgentDescriptor } from 'verve-web';

const verve = await loadVerve();
const desc: AgentDescriptor = { continuous: [{ circular: true }, {}], discrete: [4], actions: 3, seed: 1n };
const agent: Agent = verve.createAgent(desc);
const action: number = agent.update(0.5, { continuous: new Float32Array([0.1, -0.2]), discrete: [2] }, 1 / 60);
agent.update(0, { continuous: [0, 0], discrete: [0] }, 0.1, [true, false, true]);
const p: Float32Array = agent.actionProbabilities();
const values: Float32Array = agent.sampleValues([{ kind: 'continuous', index: 0, samples: 32 }]);
const bytes: Uint8Array = agent.saveBinaryBytes();
const copy = verve.loadAgent(bytes);
const brain = verve.createBrain({ continuous: 2, actions: 3 });
const npc = verve.createAgent({ continuous: 12, actions: 4 });  // grouping 'auto': a lattice per sensor and per pair
const custom = verve.createAgent({ continuous: 3, actions: 2, grouping: 'custom', sensorGroups: [[0, 1], [2]] });
const groups: number[][] = custom.descriptor().sensorGroups;
const branched = verve.createAgent({ continuous: 2, actionBranches: [3, 3, 2] });  // actions: 18
const [move, turn, use]: number[] = branched.splitAction(branched.update(0, { continuous: [0, 0] }, 0.1));
const joined: number = branched.joinAction([move, turn, use]);
const sizes: number[] = branched.descriptor().actionBranches;
const car = verve.createAgent({ continuous: 2, continuousActions: 2 });  // actions: 1
car.update(0, { continuous: [0, 0] }, 0.1);
const controls: Float32Array = car.continuousAction(new Float32Array(car.numContinuousActions));
const steer: number = car.continuousAction()[0];
const count: number = car.descriptor().continuousActions;
car.updateDemonstratedContinuous(0, { continuous: [0.1, 0.2] }, 0.1, 0, [0.5, -1]);  // a player drove
const carRecording = verve.createRecording(car);
carRecording.addStepContinuous(0, { continuous: [0.1, 0.2] }, 0.1, 0, new Float32Array([0.5, -1]));
const bodies = [brain.createBody(), brain.createBody()];
const actions: Uint32Array = verve.createBatch().update(bodies, [0, 0], [{ continuous: [0, 0] }, null], 0.05);
agent.setActionSelection('greedy');
try {
  verve.createAgent({ actions: 0 });
} catch (e) {
  if (e instanceof VerveError) console.log(e.code satisfies string, e.message);
}
// @ts-expect-error unknown descriptor field
verve.createAgent({ tauVale: 1 });
// @ts-expect-error the grouping is 'auto', 'joint' or 'custom'
verve.createAgent({ grouping: 'pairs' });
// @ts-expect-error action branches are a list of sizes
verve.createAgent({ actionBranches: 3 });
// @ts-expect-error continuous actions are a count
verve.createAgent({ continuousActions: [2] });
// @ts-expect-error the teacher's values are numbers
car.updateDemonstratedContinuous(0, null, 0.1, 0, ['left']);
// @ts-expect-error continuousAction fills a Float32Array
car.continuousAction([0, 0]);
// @ts-expect-error the selection is 'sample' or 'greedy'
agent.setActionSelection('best');
// @ts-expect-error a reward is a number
agent.update('1', null, 0.1);
console.log(action, p, values, copy.rbfCount(), actions, agent.stats().steps, verve.defaults().tauValue);
console.log(groups, joined, sizes, branched.numChoices, controls, steer, count);
for (const x of [agent, copy, npc, custom, branched, car, ...bodies, brain]) x.dispose();
