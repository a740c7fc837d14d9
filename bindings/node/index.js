// SPDX-License-Identifier: BSD-3-Clause
'use strict';
/**
 * pw85 for Node.js: the contact function of Perram and Wertheim for two
 * ellipsoids, from libpw85.so.2 through koffi (a foreign function
 * interface whose native part comes with its npm package: nothing to
 * compile).
 *
 * Vectors are arrays (or typed arrays) of 3 numbers; a symmetric matrix Q
 * is an array of 6, its upper triangle row by row:
 * [Q00, Q01, Q02, Q11, Q12, Q22]. An ellipsoid of centre c is
 * {m : (m − c)ᵀ Q⁻¹ (m − c) ≤ 1}. A status other than PW85_SUCCESS is
 * thrown as a Pw85Error carrying pw85's message; an array of the wrong
 * length is a RangeError, thrown before libpw85 is called.
 *
 * The library: the environment variable PW85_LIBRARY (a path), or else
 * libpw85.so.2 wherever the dynamic loader finds it.
 */
const koffi = require('koffi');

const DIM = 3;
const SYM = 6;

/** Status codes of pw85.h; values never change. */
const status = Object.freeze({
  PW85_SUCCESS: 0,
  PW85_EFAULT: 1,
  PW85_EDOM: 2,
  PW85_ENOTPOSDEF: 3,
  PW85_ERANGE: 4,
  PW85_ENOMEM: 5,
  PW85_ENOCONV: 6,
  PW85_EINVAL: 7,
});
const statusNames = Object.fromEntries(
  Object.entries(status).map(([name, value]) => [value, name]));

const path = process.env.PW85_LIBRARY || 'libpw85.so.2';
const lib = koffi.load(path);
const c = {
  strerror: lib.func('const char *pw85_strerror(int status)'),
  version: lib.func('const char *pw85_version(void)'),
  spheroid: lib.func('void pw85_spheroid(double a, double c, ' +
                     'const double *n, _Out_ double *q)'),
  contactFunction: lib.func('int pw85_contact_function(const double *r12, ' +
                            'const double *q1, const double *q2, ' +
                            '_Out_ double *out)'),
  overlap: lib.func('int pw85_overlap(const double *r12, const double *q1, ' +
                    'const double *q2, _Out_ int *result)'),
};

const loaded = c.version();
if (loaded.split('.')[0] !== '2') {
  throw new Error(`pw85: ${path} is version ${loaded}, not 2.x`);
}

/** A pw85 status other than PW85_SUCCESS. */
class Pw85Error extends Error {
  constructor(code, call) {
    super(`${call}: ${c.strerror(code)}`);
    this.name = 'Pw85Error';
    /** The status, a value of `status`. */
    this.status = code;
    /** Its name, "PW85_EDOM" for example. */
    this.code = statusNames[code] || `PW85_${code}`;
  }
}

// A Float64Array of n numbers from an array-like of length n: x itself if
// it is one (libpw85 only reads it), else a copy.
function doubles(x, n, name) {
  if (x == null || typeof x.length !== 'number' || x.length !== n) {
    throw new RangeError(`pw85: ${name} must hold ${n} numbers`);
  }
  return x instanceof Float64Array ? x : Float64Array.from(x);
}

// The outputs of the calls below, reused: a call runs to completion on
// this thread before the next starts, and the values are copied out.
const outPair = new Float64Array(2);
const outInt = new Int32Array(1);

/**
 * The quadratic form of a spheroid: Q = a²·I + (c² − a²)·n·nᵀ.
 * @param {number} a the equatorial radius.
 * @param {number} c the polar radius.
 * @param {ArrayLike<number>} n the unit vector of the axis (3 numbers).
 * @returns {Float64Array} Q, 6 numbers.
 */
function spheroid(a, c_, n) {
  const q = new Float64Array(SYM);
  c.spheroid(a, c_, doubles(n, DIM, 'n'), q);
  return q;
}

/**
 * The contact function μ² and its maximiser λ.
 * @param {ArrayLike<number>} r12 c2 − c1 (3 numbers).
 * @param {ArrayLike<number>} q1 the form of the first ellipsoid (6).
 * @param {ArrayLike<number>} q2 the form of the second ellipsoid (6).
 * @returns {{mu2: number, lambda: number}} μ² < 1: they overlap.
 * @throws {Pw85Error} on any status but PW85_SUCCESS.
 */
function contactFunction(r12, q1, q2) {
  const code = c.contactFunction(doubles(r12, DIM, 'r12'),
    doubles(q1, SYM, 'q1'), doubles(q2, SYM, 'q2'), outPair);
  if (code !== status.PW85_SUCCESS) {
    throw new Pw85Error(code, 'pw85_contact_function');
  }
  return { mu2: outPair[0], lambda: outPair[1] };
}

/**
 * Do two ellipsoids overlap? The certified sign of μ² − 1.
 * @returns {number} −1 (overlap), +1 (disjoint), 0 (tangent within 4 ulps).
 * @throws {Pw85Error} on any status but PW85_SUCCESS.
 */
function overlap(r12, q1, q2) {
  const code = c.overlap(doubles(r12, DIM, 'r12'), doubles(q1, SYM, 'q1'),
    doubles(q2, SYM, 'q2'), outInt);
  if (code !== status.PW85_SUCCESS) {
    throw new Pw85Error(code, 'pw85_overlap');
  }
  return outInt[0];
}

/** The version of the library loaded, "MAJOR.MINOR.PATCH". */
function version() {
  return loaded;
}

/** pw85's message for a status code. */
function strerror(code) {
  return c.strerror(code);
}

module.exports = {
  DIM, SYM, status, Pw85Error, spheroid, contactFunction, overlap, version,
  strerror, libraryPath: path,
};
