// The methods index.d.ts declares exist on the classes (and no public method goes undeclared).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as api from '../src/index.js';

const dts = readFileSync(new URL('../index.d.ts', import.meta.url), 'utf8');

function declared(className) {
  const body = dts.match(new RegExp(`export class ${className}\\b[^{]*\\{([\\s\\S]*?)\\n\\}`))[1];
  return [...body.matchAll(/^ {2}([a-zA-Z]+)\(/gm)].map((m) => m[1]).sort();
}

const INTERNAL = new Set(['constructor', 'live', 'readFloat', 'descriptorPointer', 'toString']);

for (const name of ['Agent', 'Brain', 'Batch', 'Verve']) {
  test(`${name}: index.d.ts and the class agree`, () => {
    const proto = api[name].prototype;
    const methods = Object.getOwnPropertyNames(proto)
      .filter((m) => typeof Object.getOwnPropertyDescriptor(proto, m).value === 'function' && !INTERNAL.has(m))
      .sort();
    assert.deepEqual(methods, declared(name));
  });
}

test('exports', () => {
  for (const name of ['loadVerve', 'VerveError', 'RESULT_NAMES', 'BINDING_MAJOR_VERSION']) {
    assert.ok(name in api, name);
    assert.match(dts, new RegExp(`export (const|class|function) ${name}\\b`));
  }
});
