// Agent descriptors: a plain object with camelCase fields, checked field by field (an unknown
// field or a wrong type is an error, so a typo does not pass silently), written over the library's
// defaults into a verve_agent_desc, and read back from one.
import { invalidArgument } from './errors.js';

// Sensors of each kind (a sensor group is a 64-bit mask); the C struct keeps sensors 16 and up
// in arrays of their own (its V8 fields), so older hosts' structs keep their layout.
export const MAX_DISCRETE_SENSORS = 64;
export const MAX_CONTINUOUS_SENSORS = 64;
const FIRST_ARRAY = 16;  // VERVE_MAX_DISCRETE_SENSORS, VERVE_MAX_CONTINUOUS_SENSORS
export const MAX_SENSOR_GROUPS = 64;
export const MAX_ACTION_BRANCHES = 8;
export const MAX_CONTINUOUS_ACTIONS = 8;

// Indices into the layout table of wasm/verve_web_layout.c.
export const L = Object.freeze({
  descSize: 0, statsSize: 1, axisSize: 2, batchDescSize: 3,
  numDiscrete: 4, discreteValues: 5, numContinuous: 6, circular: 7,
  resolution: 8, numActions: 9, rbfAllocation: 10, tauValue: 11, tauDiscount: 12, tauEligibility: 13,
  policyMultiplier: 14, traceThreshold: 15, seed: 16, planning: 17, tauModel: 18, maxPlanningSteps: 19,
  planningUncertaintyThreshold: 20, curiosity: 21, curiosityFactor: 22, planningAccumulatesUncertainty: 23,
  learnFromRealSteps: 24, discretePrediction: 25, maxRbfs: 26, policyWeightBound: 27,
  statsSteps: 28, statsRbfCount: 29, statsLiveTraces: 30, statsValue: 31, statsTdError: 32,
  statsModelError: 33, statsPredictedUncertainty: 34, statsPlanningSteps: 35, statsCuriosityReward: 36,
  statsRbfBudgetHits: 37, statsClampedRewards: 38, batchWorkerCount: 39, adaptation: 40,
  sensorGrouping: 41, numSensorGroups: 42, sensorGroups: 43, numActionBranches: 44, actionBranches: 45,
  numContinuousActions: 46, moreDiscreteValues: 47, moreCircular: 48,
});
export const LAYOUT_LENGTH = 49;

const ENUMS = {
  allocation: ['dynamic', 'full'],
  curiosity: ['none', 'novelty', 'progress'],
  discretePrediction: ['categorical', 'ordinal'],
  grouping: ['auto', 'joint', 'custom'],
};

// [field, layout index, kind]; discrete and continuous are handled on their own.
const SCALARS = [
  ['actions', 'numActions', 'u32'],
  ['resolution', 'resolution', 'u32'],
  ['allocation', 'rbfAllocation', 'enum'],
  ['tauValue', 'tauValue', 'f32'],
  ['tauDiscount', 'tauDiscount', 'f32'],
  ['tauEligibility', 'tauEligibility', 'f32'],
  ['policyMultiplier', 'policyMultiplier', 'f32'],
  ['traceThreshold', 'traceThreshold', 'f32'],
  ['seed', 'seed', 'u64'],
  ['planning', 'planning', 'bool'],
  ['tauModel', 'tauModel', 'f32'],
  ['maxPlanningSteps', 'maxPlanningSteps', 'u32'],
  ['planningUncertaintyThreshold', 'planningUncertaintyThreshold', 'f32'],
  ['curiosity', 'curiosity', 'enum'],
  ['curiosityFactor', 'curiosityFactor', 'f32'],
  ['planningAccumulatesUncertainty', 'planningAccumulatesUncertainty', 'bool'],
  ['learnFromRealSteps', 'learnFromRealSteps', 'bool'],
  ['discretePrediction', 'discretePrediction', 'enum'],
  ['maxRbfs', 'maxRbfs', 'u64'],
  ['policyWeightBound', 'policyWeightBound', 'f32'],
  ['adaptation', 'adaptation', 'u64'],
  ['grouping', 'sensorGrouping', 'enum'],
];
const KNOWN = new Set(['discrete', 'continuous', 'sensorGroups', 'actionBranches', 'continuousActions',
  ...SCALARS.map(([name]) => name)]);

function describe(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'array';
  return typeof value === 'number' || typeof value === 'boolean' ? `${typeof value} ${value}` : typeof value;
}

function checkU32(name, value) {
  if (!Number.isInteger(value) || value < 0 || value > 0xffffffff) {
    throw invalidArgument(`descriptor.${name} must be an integer from 0 to 2^32 - 1 (got ${describe(value)})`);
  }
  return value;
}

function checkU64(name, value) {
  if (typeof value === 'bigint') {
    if (value < 0n || value > 0xffffffffffffffffn) throw invalidArgument(`descriptor.${name} must fit in 64 bits unsigned`);
    return value;
  }
  if (!Number.isSafeInteger(value) || value < 0) {
    throw invalidArgument(`descriptor.${name} must be a non-negative safe integer or a BigInt (got ${describe(value)})`);
  }
  return BigInt(value);
}

function checkList(name, value, max) {
  if (!Array.isArray(value) && !ArrayBuffer.isView(value)) {
    throw invalidArgument(`descriptor.${name} must be an array (got ${describe(value)})`);
  }
  if (value.length > max) throw invalidArgument(`descriptor.${name} has ${value.length} sensors, at most ${max}`);
  return Array.from(value);
}

/** Checks a descriptor object; returns it normalised (continuous as a list of {circular}). */
export function checkDescriptor(desc) {
  if (desc === undefined) desc = {};
  if (desc === null || typeof desc !== 'object' || Array.isArray(desc)) {
    throw invalidArgument(`the descriptor must be an object (got ${describe(desc)})`);
  }
  for (const key of Object.keys(desc)) {
    if (!KNOWN.has(key)) throw invalidArgument(`descriptor has an unknown field '${key}'`);
  }
  const out = {};
  if (desc.discrete !== undefined) {
    out.discrete = checkList('discrete', desc.discrete, MAX_DISCRETE_SENSORS).map((v, i) => checkU32(`discrete[${i}]`, v));
  }
  if (desc.continuous !== undefined) {
    const c = desc.continuous;
    if (typeof c === 'number') {
      if (!Number.isInteger(c) || c < 0 || c > MAX_CONTINUOUS_SENSORS) {
        throw invalidArgument(`descriptor.continuous must be a count from 0 to ${MAX_CONTINUOUS_SENSORS} or a list (got ${describe(c)})`);
      }
      out.continuous = Array.from({ length: c }, () => ({ circular: false }));
    } else {
      out.continuous = checkList('continuous', c, MAX_CONTINUOUS_SENSORS).map((s, i) => {
        if (s === null || typeof s !== 'object') {
          throw invalidArgument(`descriptor.continuous[${i}] must be an object such as {circular: true} (got ${describe(s)})`);
        }
        for (const key of Object.keys(s)) {
          if (key !== 'circular') throw invalidArgument(`descriptor.continuous[${i}] has an unknown field '${key}'`);
        }
        if (s.circular !== undefined && typeof s.circular !== 'boolean') {
          throw invalidArgument(`descriptor.continuous[${i}].circular must be a boolean (got ${describe(s.circular)})`);
        }
        return { circular: s.circular === true };
      });
    }
  }
  for (const [name, , kind] of SCALARS) {
    const value = desc[name];
    if (value === undefined) continue;
    switch (kind) {
      case 'u32': out[name] = checkU32(name, value); break;
      case 'u64': out[name] = checkU64(name, value); break;
      case 'f32':
        if (typeof value !== 'number') throw invalidArgument(`descriptor.${name} must be a number (got ${describe(value)})`);
        out[name] = value;  // NaN and out-of-range values are refused by the library, which says why
        break;
      case 'bool':
        if (typeof value !== 'boolean') throw invalidArgument(`descriptor.${name} must be a boolean (got ${describe(value)})`);
        out[name] = value;
        break;
      case 'enum':
        if (!ENUMS[name].includes(value)) {
          throw invalidArgument(`descriptor.${name} must be one of ${ENUMS[name].map((e) => `'${e}'`).join(', ')} (got ${describe(value)})`);
        }
        out[name] = value;
        break;
    }
  }
  if (desc.sensorGroups !== undefined) out.sensorGroups = checkSensorGroups(desc.sensorGroups);
  checkGroupsFitSensors(out);
  if (desc.actionBranches !== undefined) out.actionBranches = checkActionBranches(desc.actionBranches);
  if (desc.continuousActions !== undefined) {
    // Checked here so that the error names this field (the library's names num_continuous_actions).
    const n = desc.continuousActions;
    if (!Number.isInteger(n) || n < 0 || n > MAX_CONTINUOUS_ACTIONS) {
      throw invalidArgument(`descriptor.continuousActions must be an integer from 0 to ${MAX_CONTINUOUS_ACTIONS} (got ${describe(n)})`);
    }
    out.continuousActions = n;
  }
  return out;
}

/**
 * actionBranches: the choices of each branch, e.g. [3, 3, 2]. Without `actions` the library sets
 * it to their product; `actions` given must be that product (the library says so if not).
 */
function checkActionBranches(value) {
  if (!Array.isArray(value) && !ArrayBuffer.isView(value)) {
    throw invalidArgument(`descriptor.actionBranches must be an array of choice counts such as [3, 3, 2] (got ${describe(value)})`);
  }
  if (value.length > MAX_ACTION_BRANCHES) {
    throw invalidArgument(`descriptor.actionBranches has ${value.length} branches, at most ${MAX_ACTION_BRANCHES}`);
  }
  return Array.from(value, (n, b) => {
    if (!Number.isInteger(n) || n < 1 || n > 0xffffffff) {
      throw invalidArgument(`descriptor.actionBranches[${b}] must be a number of choices, at least 1 (got ${describe(n)})`);
    }
    return n;
  });
}

/** sensorGroups: a list of groups, each a list of continuous sensors (indices from 0). */
function checkSensorGroups(value) {
  if (!Array.isArray(value)) {
    throw invalidArgument(`descriptor.sensorGroups must be an array of groups such as [[0, 1], [2]] (got ${describe(value)})`);
  }
  if (value.length > MAX_SENSOR_GROUPS) {
    throw invalidArgument(`descriptor.sensorGroups has ${value.length} groups, at most ${MAX_SENSOR_GROUPS}`);
  }
  return value.map((group, g) => {
    if (!Array.isArray(group) && !ArrayBuffer.isView(group)) {
      throw invalidArgument(`descriptor.sensorGroups[${g}] must be an array of continuous sensor indices (got ${describe(group)})`);
    }
    if (group.length === 0) throw invalidArgument(`descriptor.sensorGroups[${g}] is empty`);
    if (group.length > MAX_CONTINUOUS_SENSORS) {
      throw invalidArgument(`descriptor.sensorGroups[${g}] has ${group.length} entries, at most ${MAX_CONTINUOUS_SENSORS} sensors`);
    }
    const sensors = Array.from(group);
    sensors.forEach((s, k) => {
      if (!Number.isInteger(s) || s < 0 || s >= MAX_CONTINUOUS_SENSORS) {
        throw invalidArgument(`descriptor.sensorGroups[${g}][${k}] must be a continuous sensor index from 0 to ${MAX_CONTINUOUS_SENSORS - 1} (got ${describe(s)})`);
      }
      if (sensors.indexOf(s) !== k) throw invalidArgument(`descriptor.sensorGroups[${g}] lists continuous sensor ${s} twice`);
    });
    return sensors.sort((a, b) => a - b);
  });
}

// Groups against sensors, in this API's terms (the library checks the same, in C's); groups given
// without a grouping mean 'custom'.
function checkGroupsFitSensors(out) {
  const groups = out.sensorGroups ?? [];
  if (out.grouping === undefined && groups.length > 0) out.grouping = 'custom';
  if (out.grouping !== 'custom') {
    if (groups.length > 0) {
      throw invalidArgument(`descriptor.sensorGroups is only used with grouping 'custom' (got '${out.grouping}')`);
    }
    return;
  }
  const n = out.continuous?.length ?? 0;
  if (groups.length === 0 && n > 0) {
    throw invalidArgument("descriptor.grouping 'custom' needs sensorGroups covering every continuous sensor");
  }
  const covered = new Set();
  groups.forEach((group, g) => {
    for (const s of group) {
      if (s >= n) throw invalidArgument(`descriptor.sensorGroups[${g}] lists continuous sensor ${s}, but the agent has ${n}`);
      covered.add(s);
    }
  });
  for (let s = 0; s < n; ++s) {
    if (!covered.has(s)) {
      throw invalidArgument(`continuous sensor ${s} is in none of descriptor.sensorGroups: its readings would be ignored`);
    }
  }
}

/** Writes a checked descriptor over the defaults already at `ptr` (verve_agent_desc_default). */
export function writeDescriptor(heap, layout, ptr, desc) {
  const { u8, u32, f32 } = heap;
  const at = (field) => ptr + layout[L[field]];
  if (desc.discrete) {
    u32[at('numDiscrete') >> 2] = desc.discrete.length;
    desc.discrete.forEach((v, i) => {
      u32[i < FIRST_ARRAY ? (at('discreteValues') >> 2) + i : (at('moreDiscreteValues') >> 2) + i - FIRST_ARRAY] = v;
    });
  }
  if (desc.continuous) {
    u32[at('numContinuous') >> 2] = desc.continuous.length;
    desc.continuous.forEach((s, i) => {
      u8[i < FIRST_ARRAY ? at('circular') + i : at('moreCircular') + i - FIRST_ARRAY] = s.circular ? 1 : 0;
    });
  }
  if (desc.sensorGroups) {
    u32[at('numSensorGroups') >> 2] = desc.sensorGroups.length;
    desc.sensorGroups.forEach((group, g) => {
      let low = 0, high = 0;  // bit s: continuous sensor s (up to 63)
      for (const s of group) {
        if (s < 32) low |= 1 << s;
        else high |= 1 << (s - 32);
      }
      const p = (at('sensorGroups') >> 2) + 2 * g;
      u32[p] = low >>> 0;
      u32[p + 1] = high >>> 0;
    });
  }
  if (desc.actionBranches) {
    u32[at('numActionBranches') >> 2] = desc.actionBranches.length;
    desc.actionBranches.forEach((n, b) => { u32[(at('actionBranches') >> 2) + b] = n; });
    // Without `actions`: 0, which the library sets to the branches' product.
    if (desc.actions === undefined && desc.actionBranches.length > 0) u32[at('numActions') >> 2] = 0;
  }
  if (desc.continuousActions !== undefined) {
    const p = at('numContinuousActions') >> 2;  // a uint64: the count, then 0
    u32[p] = desc.continuousActions;
    u32[p + 1] = 0;
    // Without `actions` or branches: 0, which the library makes the one discrete action of an
    // agent that only steers (not the default 2).
    if (desc.actions === undefined && !(desc.actionBranches?.length > 0) && desc.continuousActions > 0) {
      u32[at('numActions') >> 2] = 0;
    }
  }
  for (const [name, field, kind] of SCALARS) {
    const value = desc[name];
    if (value === undefined) continue;
    const p = at(field);
    switch (kind) {
      case 'u32': u32[p >> 2] = value; break;
      case 'f32': f32[p >> 2] = value; break;
      case 'bool': u32[p >> 2] = value ? 1 : 0; break;
      case 'enum': u32[p >> 2] = ENUMS[name].indexOf(value); break;
      case 'u64':
        u32[p >> 2] = Number(value & 0xffffffffn);
        u32[(p >> 2) + 1] = Number(value >> 32n);
        break;
    }
  }
}

/** A float32 as the shortest decimal that reads back to it (0.1, not 0.10000000149011612). */
function shortFloat(value) {
  if (!Number.isFinite(value)) return value;
  for (let digits = 1; digits < 9; ++digits) {
    const short = Number(value.toPrecision(digits));
    if (Math.fround(short) === value) return short;
  }
  return value;
}

/** A verve_agent_desc at `ptr` as a descriptor object (valid input for createAgent). */
export function readDescriptor(heap, layout, ptr) {
  const { u8, u32, f32 } = heap;
  const at = (field) => ptr + layout[L[field]];
  const nd = u32[at('numDiscrete') >> 2];
  const nc = u32[at('numContinuous') >> 2];
  const desc = {
    discrete: Array.from({ length: Math.min(nd, MAX_DISCRETE_SENSORS) }, (_, i) =>
      u32[i < FIRST_ARRAY ? (at('discreteValues') >> 2) + i : (at('moreDiscreteValues') >> 2) + i - FIRST_ARRAY]),
    continuous: Array.from({ length: Math.min(nc, MAX_CONTINUOUS_SENSORS) }, (_, i) =>
      ({ circular: u8[i < FIRST_ARRAY ? at('circular') + i : at('moreCircular') + i - FIRST_ARRAY] !== 0 })),
    actionBranches: Array.from({ length: Math.min(u32[at('numActionBranches') >> 2], MAX_ACTION_BRANCHES) },
      (_, b) => u32[(at('actionBranches') >> 2) + b]),
    // A uint64 the library keeps within 0..8: its high word is 0.
    continuousActions: u32[at('numContinuousActions') >> 2],
    sensorGroups: Array.from({ length: Math.min(u32[at('numSensorGroups') >> 2], MAX_SENSOR_GROUPS) }, (_, g) => {
      const p = (at('sensorGroups') >> 2) + 2 * g;
      const sensors = [];
      for (let s = 0; s < 64; ++s) {
        if ((u32[p + (s >> 5)] >>> (s & 31)) & 1) sensors.push(s);
      }
      return sensors;
    }),
  };
  for (const [name, field, kind] of SCALARS) {
    const p = at(field);
    switch (kind) {
      case 'u32': desc[name] = u32[p >> 2]; break;
      case 'f32': desc[name] = shortFloat(f32[p >> 2]); break;
      case 'bool': desc[name] = u32[p >> 2] !== 0; break;
      case 'enum': desc[name] = ENUMS[name][u32[p >> 2]] ?? u32[p >> 2]; break;
      case 'u64': {
        const v = (BigInt(u32[(p >> 2) + 1]) << 32n) | BigInt(u32[p >> 2]);
        desc[name] = v <= BigInt(Number.MAX_SAFE_INTEGER) ? Number(v) : v;
        break;
      }
    }
  }
  return desc;
}
