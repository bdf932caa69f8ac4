// TypeScript declarations of verve-web (src/index.js): the C ABI of Verve in WebAssembly.

/** The C ABI's result names, e.g. 'VERVE_ERROR_INVALID_ARGUMENT'. */
export type VerveResultName =
  | 'VERVE_OK'
  | 'VERVE_ERROR_INVALID_ARGUMENT'
  | 'VERVE_ERROR_INVALID_STATE'
  | 'VERVE_ERROR_IO'
  | 'VERVE_ERROR_FORMAT'
  | 'VERVE_ERROR_VERSION'
  | 'VERVE_ERROR_OUT_OF_MEMORY'
  | 'VERVE_ERROR_BUFFER_TOO_SMALL'
  | 'VERVE_ERROR_INTERNAL';

export const RESULT_NAMES: readonly VerveResultName[];

/** Every failure: the library's message (or the binding's), its result name and number. A refused call changes nothing. */
export class VerveError extends Error {
  readonly name: 'VerveError';
  readonly code: VerveResultName;
  readonly result: number;
}

/** A continuous sensor: values in [-1, 1]; circular ones wrap (angles). */
export interface ContinuousSensor {
  circular?: boolean;
}

/** An agent's settings; every field is optional (Verve.defaults() has them all). Unknown fields are errors. */
export interface AgentDescriptor {
  /** Values per discrete sensor, e.g. [10, 10] (at most 64 sensors). */
  discrete?: number[];
  /** A count of plain continuous sensors, or one entry per sensor (at most 64; beyond 16 with grouping auto, up to 32, or custom groups of at most 16). */
  continuous?: number | ContinuousSensor[];
  actions?: number;
  /** RBFs across [-1, 1] per continuous sensor (default 10). */
  resolution?: number;
  allocation?: 'dynamic' | 'full';
  /** Seconds (default 0.1). */
  tauValue?: number;
  /** Seconds: the horizon (default 1). */
  tauDiscount?: number;
  tauEligibility?: number;
  policyMultiplier?: number;
  traceThreshold?: number;
  seed?: number | bigint;
  planning?: boolean;
  tauModel?: number;
  maxPlanningSteps?: number;
  planningUncertaintyThreshold?: number;
  curiosity?: 'none' | 'novelty' | 'progress';
  curiosityFactor?: number;
  planningAccumulatesUncertainty?: boolean;
  learnFromRealSteps?: boolean;
  discretePrediction?: 'categorical' | 'ordinal';
  /** RBF budget (default 1000000; 0: unlimited). */
  maxRbfs?: number | bigint;
  /** > 0: actor weights stay within ±bound; 0: unbounded (default). */
  policyWeightBound?: number;
  /** What the agent sets for itself: bits 1 (horizon), 2 (actor scale), 4 (0.1 s decisions), 8 (habit ceiling); default 15, 0: every setting as given. */
  adaptation?: number | bigint;
  /**
   * Which continuous sensors share an RBF lattice. 'auto' (default): one lattice up to 4 sensors,
   * beyond that one per sensor and one per neighbouring pair (i, i + 1), so many sensors stay
   * cheap and learnable; 'joint': one lattice over all (resolution^n RBFs); 'custom': sensorGroups.
   */
  grouping?: 'auto' | 'joint' | 'custom';
  /**
   * 'custom' grouping: one lattice per group, each a list of continuous sensor indices (from 0),
   * e.g. [[0, 1], [2], [3]]; every sensor in at least one group, at most 64 groups. Given without
   * `grouping`, it means 'custom'. Read back: [] for the other groupings.
   */
  sensorGroups?: number[][];
  /**
   * Action branches: several independent choices per step, e.g. [3, 3, 2] for move x turn x use,
   * each by an actor head of its own (at most 8 branches). An action is then the combined index
   * c0 + n0 * (c1 + n1 * (c2 + ...)) (branch 0 fastest; Agent.splitAction/joinAction convert).
   * `actions` may be left out (it becomes the product) or must equal the product. Masks and
   * actionProbabilities() then hold one entry per choice of each branch, branch after branch.
   * Planning needs one action set. Read back: [] without branches.
   */
  actionBranches?: number[];
  /**
   * Continuous actions: this many values in [-1, 1] (0 .. 8, default 0) chosen on every update
   * beside the discrete action, e.g. 2 for steering and throttle; read with
   * Agent.continuousAction(). Without branches `actions` may be left out: it becomes 1 (an agent
   * that only steers keeps one trivial discrete action). Not with planning.
   */
  continuousActions?: number;
}

/** A descriptor as read back: every field present, continuous as a list. */
export type FullDescriptor = Required<Omit<AgentDescriptor, 'continuous'>> & { continuous: ContinuousSensor[] };

export type Numbers = ArrayLike<number>;

/** What the sensors read: discrete values (integers from 0) and continuous ones ([-1, 1]). */
export interface Observation {
  discrete?: Numbers;
  continuous?: Numbers;
}

export interface AgentStats {
  steps: number;
  rbfCount: number;
  liveTraces: number;
  value: number;
  tdError: number;
  modelError: number;
  predictedUncertainty: number;
  planningSteps: number;
  curiosityReward: number;
  rbfBudgetHits: number;
  clampedRewards: number;
}

export interface ValueAxis {
  kind: 'discrete' | 'continuous';
  /** Which sensor of that kind (from 0). */
  index: number;
  /** Continuous: points from -1 to 1; discrete: the sensor's value count. */
  samples: number;
}

export class Agent {
  private constructor();
  /** Combined actions (with action branches, the product of their sizes). */
  readonly numActions: number;
  /** The action branches' sizes ([] with one action set). */
  readonly actionBranches: readonly number[];
  /** Flags in a mask, values in actionProbabilities(): numActions, or the branches' sizes summed. */
  readonly numChoices: number;
  /** Values continuousAction() returns (descriptor.continuousActions; 0 without). */
  readonly numContinuousActions: number;
  readonly numDiscrete: number;
  readonly numContinuous: number;
  readonly disposed: boolean;
  /**
   * One step; returns the action (0 .. actions - 1). mask: one flag per action, at least one true;
   * with action branches one per choice of each branch, branch after branch, at least one true in each.
   */
  update(reward: number, observation: Observation | null | undefined, dt: number, mask?: ArrayLike<boolean | 0 | 1>): number;
  /** A step the player or a scripted AI took (docs/teaching.md): `action` is learned from as the agent's own. */
  updateDemonstrated(reward: number, observation: Observation | null | undefined, dt: number, action: number,
    mask?: ArrayLike<boolean | 0 | 1>): void;
  /**
   * updateDemonstrated with the continuous actions the host played too (docs/teaching.md): one per
   * continuous action, each in [-1, 1]; continuousAction() then reads them back.
   */
  updateDemonstratedContinuous(reward: number, observation: Observation | null | undefined, dt: number, action: number,
    continuousAction: ArrayLike<number>, mask?: ArrayLike<boolean | 0 | 1>): void;
  /** A teacher's judgement in [-1, 1] of what the agent did over the last 2.5 s (docs/teaching.md); not a reward. */
  teach(praise: number): void;
  /** Every entry of a recording into this agent, as demonstrated steps and trial ends (docs/teaching.md). */
  replay(recording: Recording): void;
  endEpisode(finalReward: number): void;
  truncateEpisode(reward: number): void;
  resetShortTermMemory(): void;
  setLearning(enabled: boolean): void;
  learning(): boolean;
  setActionSelection(mode: 'sample' | 'greedy'): void;
  actionSelection(): 'sample' | 'greedy';
  /** Each action's probability; with action branches, each branch's choices in turn, each branch summing to 1. */
  actionProbabilities(out?: Float32Array): Float32Array;
  /**
   * The latest update's continuous actions, numContinuousActions values in [-1, 1]: drawn around the
   * policy's mean, or the mean when greedy; 0s before the first update. Into `out` when given (at
   * least numContinuousActions long; returned): no allocation, for every frame.
   */
  continuousAction(out?: Float32Array): Float32Array;
  /** The choice of each action branch (from 0) within a combined action; [action] without branches. */
  splitAction(action: number): number[];
  /** The combined action of one choice per branch (each from 0, branch 0 varying fastest). */
  joinAction(choices: ArrayLike<number>): number;
  value(): number;
  tdError(): number;
  rbfCount(): number;
  stats(): AgentStats;
  descriptor(): FullDescriptor;
  /** V over 1 or 2 swept sensors, the others at `base` (default 0): axes[0].samples (× axes[1].samples) values, axis 0 fastest. */
  sampleValues(axes: [ValueAxis] | [ValueAxis, ValueAxis], base?: Observation): Float32Array;
  /** XML. */
  saveString(): string;
  saveBytes(): Uint8Array;
  /** The compact binary format. */
  saveBinaryBytes(): Uint8Array;
  dispose(): void;
}

export class Brain {
  private constructor();
  readonly disposed: boolean;
  createBody(): Agent;
  rbfCount(): number;
  saveString(): string;
  saveBytes(): Uint8Array;
  saveBinaryBytes(): Uint8Array;
  dispose(): void;
}

/** Demonstrated steps kept for replay (docs/teaching.md, "Recordings"). */
export class Recording {
  private constructor();
  readonly disposed: boolean;
  addStep(reward: number, observation: Observation | null | undefined, dt: number, action: number): void;
  /** A step with the host's continuous actions, as Agent.updateDemonstratedContinuous takes it (no mask). */
  addStepContinuous(reward: number, observation: Observation | null | undefined, dt: number, action: number,
    continuousAction: ArrayLike<number>): void;
  addEndEpisode(finalReward: number): void;
  addTruncation(reward: number): void;
  size(): number;
  saveBytes(): Uint8Array;
  dispose(): void;
}

export class Batch {
  private constructor();
  readonly disposed: boolean;
  /** One step of every agent, as the same updates in array order; returns the actions. */
  update(agents: Agent[], rewards: Numbers, observations: Array<Observation | null | undefined>, dt: number, out?: Uint32Array,
    demonstrated?: Array<number | null>, continuousActions?: Array<Numbers | null>): Uint32Array;
  dispose(): void;
}

export interface Version {
  major: number;
  minor: number;
  patch: number;
  number: number;
  text: string;
}

/** A save: XML as a string or bytes, or the binary format's bytes. */
export type SaveData = string | Uint8Array | ArrayBuffer | ArrayBufferView;

export class Verve {
  private constructor();
  version(): Version;
  defaults(): FullDescriptor;
  createAgent(desc?: AgentDescriptor): Agent;
  loadAgent(data: SaveData): Agent;
  createBrain(desc?: AgentDescriptor): Brain;
  loadBrain(data: SaveData): Brain;
  createRecording(agent: Agent): Recording;
  loadRecording(data: SaveData): Recording;
  createBatch(): Batch;
  /** libverve's warnings since the previous call, oldest first (usually none): a reward clamped to [-1, 1], an agent's RBF budget reached, each once per agent. */
  takeWarnings(): string[];
  /** The Emscripten module underneath, for tools and tests. */
  readonly module: unknown;
}

export interface LoadOptions {
  /** Where the browser fetches verve_wasm.wasm from (default: beside dist/verve_wasm.mjs). */
  wasmUrl?: string | URL;
  /** The .wasm's bytes, when the host has them already. */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

export function loadVerve(options?: LoadOptions): Promise<Verve>;

export const BINDING_MAJOR_VERSION: number;
