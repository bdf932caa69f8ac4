// Errors: every failure is a VerveError carrying the library's message and result name. A refused
// call changes nothing (the C ABI's rule, kept by the binding's own checks).

/** The C ABI's result codes, by number. */
export const RESULT_NAMES = Object.freeze([
  'VERVE_OK',
  'VERVE_ERROR_INVALID_ARGUMENT',
  'VERVE_ERROR_INVALID_STATE',
  'VERVE_ERROR_IO',
  'VERVE_ERROR_FORMAT',
  'VERVE_ERROR_VERSION',
  'VERVE_ERROR_OUT_OF_MEMORY',
  'VERVE_ERROR_BUFFER_TOO_SMALL',
  'VERVE_ERROR_INTERNAL',
]);

export const OK = 0;
export const INVALID_ARGUMENT = 1;
export const INVALID_STATE = 2;
export const OUT_OF_MEMORY = 6;
export const BUFFER_TOO_SMALL = 7;

export class VerveError extends Error {
  /**
   * @param {string} message
   * @param {number} result one of the C ABI's verve_result values
   */
  constructor(message, result) {
    const code = RESULT_NAMES[result] ?? 'VERVE_ERROR_INTERNAL';
    super(`${message} [${code}]`);
    this.name = 'VerveError';
    /** The result's name, e.g. 'VERVE_ERROR_INVALID_ARGUMENT'. */
    this.code = code;
    /** The result's number. */
    this.result = result;
  }
}

/** A refusal by the binding itself, before anything reaches the library. */
export function invalidArgument(what) {
  return new VerveError(`verve: ${what}`, INVALID_ARGUMENT);
}

export function invalidState(what) {
  return new VerveError(`verve: ${what}`, INVALID_STATE);
}
