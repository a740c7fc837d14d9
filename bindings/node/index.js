// SPDX-License-Identifier: BSD-3-Clause
'use strict';
/**
 * pw85 for Node.js: the contact function of Perram and Wertheim for two
 * ellipsoids, from libpw85.so.2 through koffi (a foreign function
 * interface whose native part comes with its npm package: nothing to
 * compile). TypeScript declarations: index.d.ts.
 *
 * Vectors are arrays (or typed arrays) of 3 numbers; a symmetric matrix Q
 * is an array of 6, its upper triangle row by row:
 * [Q00, Q01, Q02, Q11, Q12, Q22]. An ellipsoid of centre c is
 * {m : (m − c)ᵀ Q⁻¹ (m − c) ≤ 1}. A status other than PW85_SUCCESS is
 * thrown as a Pw85Error carrying pw85's message and what was wrong; an
 * array of the wrong length is a RangeError and an argument of the wrong
 * type a TypeError, thrown before libpw85 is called.
 *
 * Batches take Float64Arrays of n records laid end to end (3·n numbers
 * for vectors, 6·n for forms), or one record for every item (stride 0: no
 * copy), and return typed arrays; one call into the library for all.
 *
 * Ellipses (pw85_2d.h): the same functions under `d2` (d2.contactFunction,
 * d2.ellipse, ...), over vectors of 2 numbers and forms of 3,
 * [Q00, Q01, Q11].
 *
 * The library: the environment variable PW85_LIBRARY (a full path), or
 * else libpw85.so.2 wherever the dynamic loader finds it.
 */
const koffi = require('koffi');

const DIM = 3;
const SYM = 6;
const UNIT_TOL = 1e-6;
const GEOM_SIZE = 8;
const DERIV_SIZE = 21;
/** Offsets into the output of contactGeometry (PW85_GEOM_*). */
const GEOM = Object.freeze({ MU2: 0, LAMBDA: 1, POINT: 2, NORMAL: 5,
  SIZE: GEOM_SIZE });
/** Offsets into the derivatives of contactDerivatives (PW85_DERIV_*). */
const DERIV = Object.freeze({ R12: 0, ROT1: 3, ROT2: 6, Q1: 9, Q2: 15,
  SIZE: DERIV_SIZE });
/** The largest id of an Index (PW85_INDEX_MAX_ID). */
const MAX_ID = 0xFFFFFFFE;
const NO_ID = 0xFFFFFFFFFFFFFFFFn;

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
  PW85_ECANCELLED: 8,
});
const statusNames = Object.fromEntries(
  Object.entries(status).map(([name, value]) => [value, name]));

const SONAME = 'libpw85.so.2';
const fromEnv = Boolean(process.env.PW85_LIBRARY);
const path = fromEnv ? process.env.PW85_LIBRARY : SONAME;

function load() {
  try {
    return koffi.load(path);
  } catch (e) {
    const where = fromEnv
      ? `${path} (from the environment variable PW85_LIBRARY)`
      : `${SONAME} (the dynamic loader's search: LD_LIBRARY_PATH, ` +
        '/etc/ld.so.cache, the default directories; PW85_LIBRARY is not set)';
    throw new Error(`pw85: cannot load ${where}: ${e.message}. Set ` +
      `PW85_LIBRARY to the full path of ${SONAME} (for a build: ` +
      'build/src/libpw85.so.2), or install pw85 and run ldconfig.');
  }
}
const lib = load();

// The calls of pw85_index.h (prefix pw85_index) or of pw85_2d_index.h
// (pw85_2d_index): the same prototypes, on their own opaque handle type.
function indexCalls(prefix) {
  const h = koffi.opaque(prefix);
  const fn = (ret, name, args) => lib.func(`${prefix}_${name}`, ret, args);
  const ptr = koffi.pointer(h);
  const dbl = 'const double *';
  const outSize = koffi.out(koffi.pointer('size_t'));
  const outInts = koffi.out(koffi.pointer('int'));
  const outDbls = koffi.out(koffi.pointer('double'));
  const outIds = koffi.out(koffi.pointer('size_t'));
  return {
    create: fn('int', 'create', [dbl, koffi.out(koffi.pointer(ptr))]),
    destroy: fn('void', 'destroy', [ptr]),
    count: fn('int', 'count', [ptr, outSize]),
    insertMany: fn('int', 'insert_many', [ptr, 'size_t', 'const size_t *',
      dbl, dbl]),
    update: fn('int', 'update', [ptr, 'size_t', dbl, dbl]),
    remove: fn('int', 'remove', [ptr, 'size_t']),
    get: fn('int', 'get', [ptr, 'size_t', outDbls, outDbls]),
    overlapAny: fn('int', 'overlap_any', [ptr, dbl, dbl, 'size_t', outInts,
      outSize]),
    overlapAnyBatch: fn('int', 'overlap_any_batch', [ptr, 'size_t', dbl,
      'size_t', dbl, 'size_t', 'const size_t *', outInts, outIds, outInts,
      'int']),
    within: fn('int', 'within', [ptr, dbl, dbl, 'double', 'size_t',
      'size_t', outIds, outInts, outDbls, outSize]),
    overlappingPairs: fn('int', 'overlapping_pairs', [ptr, 'int', 'size_t',
      outIds, outInts, outInts, outSize]),
    pairsWithin: fn('int', 'pairs_within', [ptr, 'double', 'int', 'size_t',
      outIds, outInts, outDbls, outSize]),
  };
}
const BATCH = 'size_t n, const double *r12, size_t r12_stride, ' +
  'const double *q1, size_t q1_stride, const double *q2, size_t q2_stride';
const c = {
  strerror: lib.func('const char *pw85_strerror(int status)'),
  version: lib.func('const char *pw85_version(void)'),
  choleskyDecomp: lib.func('void pw85__cholesky_decomp(const double *a, ' +
    '_Out_ double *l)'),
  spheroid: lib.func('int pw85_spheroid_checked(double a, double c, ' +
    'const double *n, _Out_ double *q)'),
  fNeg: lib.func('double pw85_f_neg(double lambda, const double *params)'),
  contactFunction: lib.func('int pw85_contact_function(const double *r12, ' +
    'const double *q1, const double *q2, _Out_ double *out)'),
  overlap: lib.func('int pw85_overlap(const double *r12, const double *q1, ' +
    'const double *q2, _Out_ int *result)'),
  ellipsoidRotation: lib.func('int pw85_ellipsoid_rotation(const double *a, ' +
    'const double *rot, _Out_ double *q)'),
  ellipsoidQuaternion: lib.func('int pw85_ellipsoid_quaternion(' +
    'const double *a, const double *p, _Out_ double *q)'),
  principalAxes: lib.func('int pw85_principal_axes(const double *q, ' +
    '_Out_ double *a, _Out_ double *rot)'),
  principalAxesQuaternion: lib.func('int pw85_principal_axes_quaternion(' +
    'const double *q, _Out_ double *a, _Out_ double *p)'),
  contactGeometry: lib.func('int pw85_contact_geometry(const double *r12, ' +
    'const double *q1, const double *q2, _Out_ double *out)'),
  contactDerivatives: lib.func('int pw85_contact_derivatives(' +
    'const double *r12, const double *q1, const double *q2, ' +
    '_Out_ double *geometry, _Out_ double *d)'),
  batchThreads: lib.func('int pw85_batch_threads(int threads, size_t n)'),
  contactFunctionBatch: lib.func(`int pw85_contact_function_batch(${BATCH}, ` +
    '_Out_ double *out, _Out_ int *status, int threads)'),
  overlapBatch: lib.func(`int pw85_overlap_batch(${BATCH}, ` +
    '_Out_ int *result, _Out_ int *status, int threads)'),
  contactGeometryBatch: lib.func(`int pw85_contact_geometry_batch(${BATCH}, ` +
    '_Out_ double *out, _Out_ int *status, int threads)'),
  contactDerivativesBatch: lib.func('int pw85_contact_derivatives_batch(' +
    `${BATCH}, _Out_ double *geometry, _Out_ double *d, _Out_ int *status, ` +
    'int threads)'),
};

const loaded = c.version();
if (loaded.split('.')[0] !== '2') {
  throw new Error(`pw85: ${path} is version ${loaded}, not 2.x`);
}

/** A pw85 status other than PW85_SUCCESS. */
class Pw85Error extends Error {
  constructor(code, call, detail) {
    super(`${call}: ${c.strerror(code)} (${statusNames[code] ||
      `status ${code}`})${detail ? `: ${detail}` : ''}`);
    this.name = 'Pw85Error';
    /** The status, a value of `status`. */
    this.status = code;
    /** Its name, "PW85_EDOM" for example. */
    this.code = statusNames[code] || `PW85_${code}`;
    /** What was wrong, or undefined. */
    this.detail = detail;
  }
}

// A Float64Array of the entries of x: x itself if it is one (libpw85 only
// reads it), else a copy, each entry a number (not '1', not 1n): a
// TypeError naming the entry otherwise.
function float64s(x, name) {
  if (x instanceof Float64Array) return x;
  if (!ArrayBuffer.isView(x)) {
    for (let k = 0; k < x.length; ++k) {
      if (typeof x[k] !== 'number') {
        throw new TypeError(`pw85: ${name}[${k}] must be a number, got ` +
          `${x[k] === null ? 'null' : typeof x[k]}`);
      }
    }
  } else if (x instanceof BigInt64Array || x instanceof BigUint64Array) {
    throw new TypeError(`pw85: ${name} must hold numbers, got a ` +
      x.constructor.name);
  }
  return Float64Array.from(x);
}

// A Float64Array of n numbers from an array-like of length n.
function doubles(x, n, name) {
  if (x == null || typeof x.length !== 'number' || x.length !== n) {
    throw new RangeError(`pw85: ${name} must hold ${n} numbers`);
  }
  return float64s(x, name);
}

function number(x, name) {
  if (typeof x !== 'number') {
    throw new TypeError(`pw85: ${name} must be a number, got ${typeof x}`);
  }
  return x;
}

const fmt = (x) => String(x);
const list = (x) => `[${Array.from(x, fmt).join(', ')}]`;
const isPosDef = (q) => {
  const l = new Float64Array(SYM);
  c.choleskyDecomp(q, l);
  return !Number.isNaN(l[0]);
};

// The outputs of the calls below, reused: a call runs to completion on
// this thread before the next starts, and the values are copied out.
const outPair = new Float64Array(2);
const outInt = new Int32Array(1);

function check(code, call, detail) {
  if (code !== status.PW85_SUCCESS) {
    throw new Pw85Error(code, call,
      typeof detail === 'function' ? detail() : detail);
  }
}

function pairDetail(r12, q1, q2) {
  return () => `r12 = ${list(r12)}, q1 = ${list(q1)}, q2 = ${list(q2)}`;
}

/**
 * The preconditions of a spheroid that (a, c, n) breaks, or undefined.
 */
function spheroidRule(a, c_, n) {
  const nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (!(a > 0)) return `a = ${fmt(a)} is not > 0`;
  if (!(c_ > 0)) return `c = ${fmt(c_)} is not > 0`;
  if (!(Math.abs(nn - 1) <= UNIT_TOL)) {
    return `n is not a unit vector: ‖n‖² = ${fmt(nn)}, |‖n‖² − 1| > ` +
      `UNIT_TOL = ${UNIT_TOL}`;
  }
  return undefined;
}

/**
 * The quadratic form of a spheroid: Q = a²·I + (c² − a²)·n·nᵀ
 * (pw85_spheroid_checked: a > 0, c > 0, n a unit vector to UNIT_TOL).
 * @returns {Float64Array} Q, 6 numbers.
 * @throws {Pw85Error} PW85_EDOM, PW85_EINVAL (naming the rule), PW85_ERANGE.
 */
function spheroid(a, c_, n) {
  number(a, 'a');
  number(c_, 'c');
  const nd = doubles(n, DIM, 'n');
  const q = new Float64Array(SYM);
  const code = c.spheroid(a, c_, nd, q);
  check(code, 'pw85_spheroid', () => {
    const rule = code === status.PW85_EINVAL ? spheroidRule(a, c_, nd) : '';
    return `${rule ? `${rule}: ` : ''}a = ${fmt(a)}, c = ${fmt(c_)}, ` +
      `n = ${list(nd)}`;
  });
  return q;
}

/**
 * f(λ) = λ(1−λ)·r12ᵀ·Q(λ)⁻¹·r12, Q(λ) = (1−λ)·Q1 + λ·Q2 (pw85_f_neg).
 * @returns {number} f(λ); NaN if an input is not finite or Q(λ) is not
 *          positive definite.
 */
function f(lambda, r12, q1, q2) {
  const params = new Float64Array(DIM + 2 * SYM);
  params.set(doubles(r12, DIM, 'r12'));
  params.set(doubles(q1, SYM, 'q1'), DIM);
  params.set(doubles(q2, SYM, 'q2'), DIM + SYM);
  return -c.fNeg(number(lambda, 'lambda'), params);
}

/**
 * The contact function μ² and its maximiser λ.
 * @returns {{mu2: number, lambda: number}} μ² < 1: they overlap.
 * @throws {Pw85Error} on any status but PW85_SUCCESS.
 */
function contactFunction(r12, q1, q2) {
  const args = [doubles(r12, DIM, 'r12'), doubles(q1, SYM, 'q1'),
    doubles(q2, SYM, 'q2')];
  check(c.contactFunction(...args, outPair), 'pw85_contact_function',
    pairDetail(...args));
  return { mu2: outPair[0], lambda: outPair[1] };
}

/**
 * Do two ellipsoids overlap? The certified sign of μ² − 1.
 * @returns {number} −1 (overlap), +1 (disjoint), 0 (tangent within 4
 *          ulps): a number, not a boolean (test `overlap(...) < 0`).
 * @throws {Pw85Error} on any status but PW85_SUCCESS.
 */
function overlap(r12, q1, q2) {
  const args = [doubles(r12, DIM, 'r12'), doubles(q1, SYM, 'q1'),
    doubles(q2, SYM, 'q2')];
  check(c.overlap(...args, outInt), 'pw85_overlap', pairDetail(...args));
  return outInt[0];
}

/** Q = R·diag(a²)·Rᵀ; rot: 9 numbers row by row, column j the direction
 *  of a[j] (pw85_ellipsoid_rotation). */
function ellipsoidRotation(a, rot) {
  const ad = doubles(a, DIM, 'a');
  const rd = doubles(rot, DIM * DIM, 'rot');
  const q = new Float64Array(SYM);
  check(c.ellipsoidRotation(ad, rd, q), 'pw85_ellipsoid_rotation',
    () => `a = ${list(ad)}, rot = ${list(rd)}`);
  return q;
}

/**
 * Q = R(p)·diag(a²)·R(p)ᵀ from semi-axes and a unit quaternion
 * (pw85_ellipsoid_quaternion). p is (w, x, y, z), scalar first, by
 * default; OVITO and SciPy write (x, y, z, w): pass
 * `{ scalarFirst: false }`.
 */
function ellipsoidQuaternion(a, p, { scalarFirst = true } = {}) {
  const ad = doubles(a, DIM, 'a');
  let pd = doubles(p, 4, 'p');
  if (!scalarFirst) pd = Float64Array.of(pd[3], pd[0], pd[1], pd[2]);
  const q = new Float64Array(SYM);
  check(c.ellipsoidQuaternion(ad, pd, q), 'pw85_ellipsoid_quaternion',
    () => `a = ${list(ad)}, p (w, x, y, z) = ${list(pd)}`);
  return q;
}

/** Semi-axes (decreasing) and rotation (9 numbers, row by row) of Q
 *  (pw85_principal_axes). */
function principalAxes(q) {
  const qd = doubles(q, SYM, 'q');
  const a = new Float64Array(DIM);
  const rot = new Float64Array(DIM * DIM);
  check(c.principalAxes(qd, a, rot), 'pw85_principal_axes',
    () => `q = ${list(qd)}`);
  return { a, rot };
}

/** Semi-axes (decreasing) and the unit quaternion of Q, w ≥ 0
 *  (pw85_principal_axes_quaternion): (w, x, y, z) by default, (x, y, z, w)
 *  (OVITO, SciPy) with `{ scalarFirst: false }`. */
function principalAxesQuaternion(q, { scalarFirst = true } = {}) {
  const qd = doubles(q, SYM, 'q');
  const a = new Float64Array(DIM);
  let p = new Float64Array(4);
  check(c.principalAxesQuaternion(qd, a, p),
    'pw85_principal_axes_quaternion', () => `q = ${list(qd)}`);
  if (!scalarFirst) p = Float64Array.of(p[1], p[2], p[3], p[0]);
  return { a, p };
}

/** μ², λ, the contact point x − c1 and the unit normal, laid out as GEOM
 *  (pw85_contact_geometry). */
function contactGeometry(r12, q1, q2) {
  const args = [doubles(r12, DIM, 'r12'), doubles(q1, SYM, 'q1'),
    doubles(q2, SYM, 'q2')];
  const out = new Float64Array(GEOM_SIZE);
  check(c.contactGeometry(...args, out), 'pw85_contact_geometry',
    pairDetail(...args));
  return out;
}

/** The geometry and the derivatives of μ², laid out as GEOM and DERIV
 *  (pw85_contact_derivatives): forces and torques. */
function contactDerivatives(r12, q1, q2) {
  const args = [doubles(r12, DIM, 'r12'), doubles(q1, SYM, 'q1'),
    doubles(q2, SYM, 'q2')];
  const geometry = new Float64Array(GEOM_SIZE);
  const d = new Float64Array(DERIV_SIZE);
  check(c.contactDerivatives(...args, geometry, d),
    'pw85_contact_derivatives', pairDetail(...args));
  return { geometry, d };
}

// ---------------------------------------------------------------------------
// Batches.

function threadCount(threads) {
  if (!Number.isInteger(threads) || threads < 0) {
    throw new RangeError('pw85: threads must be 0 (OpenMP\'s default) or a ' +
      `positive integer, got ${threads}`);
  }
  if (threads > 2 ** 31 - 1) {
    throw new RangeError('pw85: threads must be at most 2³¹ − 1 (a C int), ' +
      `got ${threads}`);
  }
  return threads;
}

/** The number of threads a batch of n pairs runs on (pw85_batch_threads);
 *  n defaults to a batch large enough for every thread asked for. */
function batchThreads(threads = 0, n = 256 * (2 ** 31 - 1)) {
  return c.batchThreads(threadCount(threads), n);
}

// Inputs of a batch: each a Float64Array (or array) of one record (stride
// 0) or of n records end to end.
function records(inputs) {
  let n = 1;
  for (const [name, x, size] of inputs) {
    if (x == null || typeof x.length !== 'number' || x.length % size !== 0) {
      throw new RangeError(`pw85: ${name} must hold ${size}·n numbers`);
    }
    if (x.length !== size) n = x.length / size;
  }
  return inputs.map(([name, x, size]) => {
    if (x.length !== size && x.length !== size * n) {
      throw new RangeError(`pw85: ${name} holds ${x.length / size} records, ` +
        `the others ${n}`);
    }
    const data = float64s(x, name);
    return { name, data, size, stride: x.length === size ? 0 : size };
  }).concat([n]);
}

function batchCall(fn, call, inputs, outputs, threads) {
  const n = inputs[inputs.length - 1];
  const ins = inputs.slice(0, -1);
  const args = [n];
  for (const x of ins) args.push(x.data, x.stride);
  const code = fn(...args, ...outputs, null, threadCount(threads));
  if (code !== status.PW85_SUCCESS) {
    const st = new Int32Array(n);
    fn(...args, ...outputs, st, threads);
    const i = st.findIndex((s) => s !== 0);
    const failed = st.reduce((k, s) => k + (s !== 0), 0);
    const values = ins.map((x) => `${x.name} = ${list(
      x.data.subarray(i * x.stride, i * x.stride + x.size))}`).join(', ');
    const e = new Pw85Error(code, call,
      `pair ${i} of ${n} (${failed} of ${n} failed): ${values}`);
    e.index = i;
    e.statuses = st;
    throw e;
  }
}

function pairs(r12, q1, q2) {
  return records([['r12', r12, DIM], ['q1', q1, SYM], ['q2', q2, SYM]]);
}

/** contactFunction for n pairs: Float64Array(2·n) of (μ², λ) pairs. */
function contactFunctionBatch(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs(r12, q1, q2);
  const out = new Float64Array(2 * ins[3]);
  batchCall(c.contactFunctionBatch, 'pw85_contact_function_batch', ins,
    [out], threads);
  return out;
}

/** overlap for n pairs: Int32Array(n) of −1, 0, +1. */
function overlapBatch(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs(r12, q1, q2);
  const out = new Int32Array(ins[3]);
  batchCall(c.overlapBatch, 'pw85_overlap_batch', ins, [out], threads);
  return out;
}

/** contactGeometry for n pairs: Float64Array(8·n). */
function contactGeometryBatch(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs(r12, q1, q2);
  const out = new Float64Array(GEOM_SIZE * ins[3]);
  batchCall(c.contactGeometryBatch, 'pw85_contact_geometry_batch', ins,
    [out], threads);
  return out;
}

/** contactDerivatives for n pairs: {geometry: Float64Array(8·n),
 *  d: Float64Array(21·n)}. */
function contactDerivativesBatch(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs(r12, q1, q2);
  const geometry = new Float64Array(GEOM_SIZE * ins[3]);
  const d = new Float64Array(DERIV_SIZE * ins[3]);
  batchCall(c.contactDerivativesBatch, 'pw85_contact_derivatives_batch', ins,
    [geometry, d], threads);
  return { geometry, d };
}

// ---------------------------------------------------------------------------
// Ellipses (pw85_2d.h): vectors of 2 numbers, forms [Q00, Q01, Q11].

const DIM_2D = 2;
const SYM_2D = 3;
const GEOM_SIZE_2D = 6;
const DERIV_SIZE_2D = 10;

const c2 = {
  fNeg: lib.func('double pw85_2d_f_neg(double lambda, const double *params)'),
  contactFunction: lib.func('int pw85_2d_contact_function(' +
    'const double *r12, const double *q1, const double *q2, ' +
    '_Out_ double *out)'),
  overlap: lib.func('int pw85_2d_overlap(const double *r12, ' +
    'const double *q1, const double *q2, _Out_ int *result)'),
  contactGeometry: lib.func('int pw85_2d_contact_geometry(' +
    'const double *r12, const double *q1, const double *q2, ' +
    '_Out_ double *out)'),
  contactDerivatives: lib.func('int pw85_2d_contact_derivatives(' +
    'const double *r12, const double *q1, const double *q2, ' +
    '_Out_ double *geometry, _Out_ double *d)'),
  ellipse: lib.func('int pw85_2d_ellipse(const double *a, double theta, ' +
    '_Out_ double *q)'),
  principalAxes: lib.func('int pw85_2d_principal_axes(const double *q, ' +
    '_Out_ double *a, _Out_ double *theta)'),
  contactFunctionBatch: lib.func('int pw85_2d_contact_function_batch(' +
    `${BATCH}, _Out_ double *out, _Out_ int *status, int threads)`),
  overlapBatch: lib.func(`int pw85_2d_overlap_batch(${BATCH}, ` +
    '_Out_ int *result, _Out_ int *status, int threads)'),
  contactGeometryBatch: lib.func('int pw85_2d_contact_geometry_batch(' +
    `${BATCH}, _Out_ double *out, _Out_ int *status, int threads)`),
  contactDerivativesBatch: lib.func('int pw85_2d_contact_derivatives_batch(' +
    `${BATCH}, _Out_ double *geometry, _Out_ double *d, ` +
    '_Out_ int *status, int threads)'),
  ellipseBatch: lib.func('int pw85_2d_ellipse_batch(size_t n, ' +
    'const double *a, size_t a_stride, const double *theta, ' +
    'size_t theta_stride, _Out_ double *q, _Out_ int *status, int threads)'),
  principalAxesBatch: lib.func('int pw85_2d_principal_axes_batch(size_t n, ' +
    'const double *q, size_t q_stride, _Out_ double *a, ' +
    '_Out_ double *theta, _Out_ int *status, int threads)'),
};

function pair2d(r12, q1, q2) {
  return [doubles(r12, DIM_2D, 'r12'), doubles(q1, SYM_2D, 'q1'),
    doubles(q2, SYM_2D, 'q2')];
}

function pairs2d(r12, q1, q2) {
  return records([['r12', r12, DIM_2D], ['q1', q1, SYM_2D],
    ['q2', q2, SYM_2D]]);
}

/**
 * f(λ) for two ellipses (pw85_2d_f_neg).
 * @returns {number} f(λ); NaN if an input is not finite or a form is not
 *          positive definite.
 */
function f2d(lambda, r12, q1, q2) {
  const params = new Float64Array(DIM_2D + 2 * SYM_2D);
  const [r, a, b] = pair2d(r12, q1, q2);
  params.set(r);
  params.set(a, DIM_2D);
  params.set(b, DIM_2D + SYM_2D);
  return -c2.fNeg(number(lambda, 'lambda'), params);
}

/** μ² and λ of two ellipses (pw85_2d_contact_function). */
function contactFunction2d(r12, q1, q2) {
  const args = pair2d(r12, q1, q2);
  check(c2.contactFunction(...args, outPair), 'pw85_2d_contact_function',
    pairDetail(...args));
  return { mu2: outPair[0], lambda: outPair[1] };
}

/** −1 (overlap), +1 (disjoint), 0 (tangent within 4 ulps): the certified
 *  sign of μ² − 1 of two ellipses (pw85_2d_overlap). */
function overlap2d(r12, q1, q2) {
  const args = pair2d(r12, q1, q2);
  check(c2.overlap(...args, outInt), 'pw85_2d_overlap', pairDetail(...args));
  return outInt[0];
}

/** μ², λ, the contact point x − c1 and the unit normal, laid out as
 *  d2.GEOM (pw85_2d_contact_geometry). */
function contactGeometry2d(r12, q1, q2) {
  const args = pair2d(r12, q1, q2);
  const out = new Float64Array(GEOM_SIZE_2D);
  check(c2.contactGeometry(...args, out), 'pw85_2d_contact_geometry',
    pairDetail(...args));
  return out;
}

/** The geometry and the derivatives of μ² (∂μ²/∂r12, ∂μ²/∂θ1, ∂μ²/∂θ2,
 *  ∂μ²/∂q1, ∂μ²/∂q2), laid out as d2.GEOM and d2.DERIV
 *  (pw85_2d_contact_derivatives). */
function contactDerivatives2d(r12, q1, q2) {
  const args = pair2d(r12, q1, q2);
  const geometry = new Float64Array(GEOM_SIZE_2D);
  const d = new Float64Array(DERIV_SIZE_2D);
  check(c2.contactDerivatives(...args, geometry, d),
    'pw85_2d_contact_derivatives', pairDetail(...args));
  return { geometry, d };
}

/** Q = R(θ)·diag(a0², a1²)·R(θ)ᵀ, a[0] along (cos θ, sin θ)
 *  (pw85_2d_ellipse). */
function ellipse(a, theta) {
  const ad = doubles(a, DIM_2D, 'a');
  number(theta, 'theta');
  const q = new Float64Array(SYM_2D);
  check(c2.ellipse(ad, theta, q), 'pw85_2d_ellipse',
    () => `a = ${list(ad)}, theta = ${fmt(theta)}`);
  return q;
}

/** The semi-axes (decreasing) and the angle θ in (−π/2, π/2] of a[0]
 *  (pw85_2d_principal_axes). */
function principalAxes2d(q) {
  const qd = doubles(q, SYM_2D, 'q');
  const a = new Float64Array(DIM_2D);
  const theta = new Float64Array(1);
  check(c2.principalAxes(qd, a, theta), 'pw85_2d_principal_axes',
    () => `q = ${list(qd)}`);
  return { a, theta: theta[0] };
}

/** d2.contactFunction for n pairs: Float64Array(2·n) of (μ², λ). */
function contactFunctionBatch2d(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs2d(r12, q1, q2);
  const out = new Float64Array(2 * ins[3]);
  batchCall(c2.contactFunctionBatch, 'pw85_2d_contact_function_batch', ins,
    [out], threads);
  return out;
}

/** d2.overlap for n pairs: Int32Array(n). */
function overlapBatch2d(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs2d(r12, q1, q2);
  const out = new Int32Array(ins[3]);
  batchCall(c2.overlapBatch, 'pw85_2d_overlap_batch', ins, [out], threads);
  return out;
}

/** d2.contactGeometry for n pairs: Float64Array(6·n). */
function contactGeometryBatch2d(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs2d(r12, q1, q2);
  const out = new Float64Array(GEOM_SIZE_2D * ins[3]);
  batchCall(c2.contactGeometryBatch, 'pw85_2d_contact_geometry_batch', ins,
    [out], threads);
  return out;
}

/** d2.contactDerivatives for n pairs: {geometry: Float64Array(6·n),
 *  d: Float64Array(10·n)}. */
function contactDerivativesBatch2d(r12, q1, q2, { threads = 1 } = {}) {
  const ins = pairs2d(r12, q1, q2);
  const geometry = new Float64Array(GEOM_SIZE_2D * ins[3]);
  const d = new Float64Array(DERIV_SIZE_2D * ins[3]);
  batchCall(c2.contactDerivativesBatch, 'pw85_2d_contact_derivatives_batch',
    ins, [geometry, d], threads);
  return { geometry, d };
}

/** d2.ellipse for n ellipses: a (2·n numbers, or 2), theta (n numbers, or
 *  1); Float64Array(3·n). */
function ellipseBatch(a, theta, { threads = 1 } = {}) {
  const ins = records([['a', a, DIM_2D], ['theta', theta, 1]]);
  const q = new Float64Array(SYM_2D * ins[2]);
  batchCall(c2.ellipseBatch, 'pw85_2d_ellipse_batch', ins, [q], threads);
  return q;
}

/** d2.principalAxes for n forms: {a: Float64Array(2·n),
 *  theta: Float64Array(n)}. */
function principalAxesBatch2d(q, { threads = 1 } = {}) {
  const ins = records([['q', q, SYM_2D]]);
  const a = new Float64Array(DIM_2D * ins[1]);
  const theta = new Float64Array(ins[1]);
  batchCall(c2.principalAxesBatch, 'pw85_2d_principal_axes_batch', ins,
    [a, theta], threads);
  return { a, theta };
}

/** The ellipses of pw85_2d.h, with the conventions of the functions
 *  above. */
const d2 = {
  DIM: DIM_2D,
  SYM: SYM_2D,
  /** Offsets into the output of d2.contactGeometry (PW85_2D_GEOM_*). */
  GEOM: Object.freeze({ MU2: 0, LAMBDA: 1, POINT: 2, NORMAL: 4,
    SIZE: GEOM_SIZE_2D }),
  /** Offsets into the derivatives of d2.contactDerivatives
   *  (PW85_2D_DERIV_*). */
  DERIV: Object.freeze({ R12: 0, THETA1: 2, THETA2: 3, Q1: 4, Q2: 7,
    SIZE: DERIV_SIZE_2D }),
  f: f2d,
  contactFunction: contactFunction2d,
  overlap: overlap2d,
  contactGeometry: contactGeometry2d,
  contactDerivatives: contactDerivatives2d,
  ellipse,
  principalAxes: principalAxes2d,
  contactFunctionBatch: contactFunctionBatch2d,
  overlapBatch: overlapBatch2d,
  contactGeometryBatch: contactGeometryBatch2d,
  contactDerivativesBatch: contactDerivativesBatch2d,
  ellipseBatch,
  principalAxesBatch: principalAxesBatch2d,
};

// ---------------------------------------------------------------------------
// The index (pw85_index.h).

const INDEX_3D = Object.freeze({
  dim: DIM, sym: SYM, diagonal: [0, 3, 5], shape: 'ellipsoid',
  domain: 'box', name: 'pw85.Index', prefix: 'pw85_index', isPosDef,
  c: indexCalls('pw85_index'),
});
// The exact rule of pw85_2d.h, asked of the library: pw85_2d_overlap
// answers PW85_ENOTPOSDEF for a finite form that breaks it.
const r12Zero = new Float64Array(DIM_2D);
const INDEX_2D = Object.freeze({
  dim: DIM_2D, sym: SYM_2D, diagonal: [0, 2], shape: 'ellipse',
  domain: 'rectangle', name: 'pw85.d2.Index', prefix: 'pw85_2d_index',
  isPosDef: (q) => c2.overlap(r12Zero, q, q, outInt) !==
    status.PW85_ENOTPOSDEF,
  c: indexCalls('pw85_2d_index'),
});

const SIDE_MARGIN = 1 + 2 ** -20;
const CENTRE_REACH = 2 ** 29;
const MAX_SIDE = 2 ** 992;
const MAX_CENTRE = 2 ** 1021;
const IMAGE_SPAN = 2 ** 20;

// The threshold t of within and pairsWithin: finite (PW85_EDOM) and > 0
// (PW85_EINVAL), checked here to name t (libpw85's status does not).
function threshold(t, call) {
  number(t, 't');
  if (!Number.isFinite(t)) {
    throw new Pw85Error(status.PW85_EDOM, call, `t = ${t} is not finite`);
  }
  if (!(t > 0)) {
    throw new Pw85Error(status.PW85_EINVAL, call, `t = ${t} is not > 0`);
  }
  return t;
}

function idOf(x, name) {
  if (!Number.isInteger(x) || x < 0 || x > MAX_ID) {
    throw new TypeError(`pw85: ${name} must be an integer from 0 to ` +
      `MAX_ID = ${MAX_ID}, got ${typeof x === 'number' ? x : typeof x}`);
  }
  return x;
}

/**
 * The index of either dimension: Index (ellipsoids) and d2.Index
 * (ellipses) set `dimension`, the calls and sizes of their C header.
 */
class IndexBase {
  /** @param {ArrayLike<number>|null} box the sides of a periodic box (or
   *  rectangle), or null for an open domain. */
  constructor(box = null) {
    const d = this.constructor.dimension;
    /** The sizes, calls and words of this dimension (INDEX_3D, INDEX_2D). */
    this._d = d;
    const b = box == null ? null : doubles(box, d.dim, 'box');
    const h = [null];
    const code = this._d.c.create(b, h);
    check(code, this._call('create'), () => {
      const k = b.findIndex((x) => !(Number.isFinite(x) && x > 0 &&
        x <= MAX_SIDE));
      let rule = 'is not finite';
      if (Number.isFinite(b[k])) {
        rule = b[k] > 0 ? `is above 2⁹⁹² = ${fmt(MAX_SIDE)}` : 'is not > 0';
      }
      return `${d.domain} side L_${k} = ${fmt(b[k])} ${rule}`;
    });
    this._h = h[0];
    this._ids = new Set();
    /** The sides of the box (a copy), or null. */
    this.box = b == null ? null : Float64Array.from(b);
  }

  _call(name) {
    return `${this._d.prefix}_${name}`;
  }

  _handle() {
    if (this._h == null) throw new Error('pw85: the index is closed');
    return this._h;
  }

  /** Free the library's memory; the index is unusable afterwards. */
  close() {
    if (this._h != null) {
      this._d.c.destroy(this._h);
      this._h = null;
    }
  }

  /** The number of ellipsoids stored. */
  get size() {
    const n = [0];
    check(this._d.c.count(this._handle(), n), this._call('count'));
    return Number(n[0]);
  }

  /** Is this id stored? */
  has(id) {
    this._handle();
    return Number.isInteger(id) && this._ids.has(id);
  }

  /** The stored ids, ascending. */
  ids() {
    this._handle();
    return Array.from(this._ids).sort((x, y) => x - y);
  }

  [Symbol.iterator]() {
    return this.ids()[Symbol.iterator]();
  }

  _placement(centre, q) {
    if (this.box == null) {
      const k = centre.findIndex((x) => !(Math.abs(x) <= MAX_CENTRE));
      return k < 0 ? undefined : `|c_${k}| = ${fmt(Math.abs(centre[k]))} ` +
        `> 2¹⁰²¹ = ${fmt(MAX_CENTRE)} (a centre must lie within 2¹⁰²¹ of ` +
        'the origin)';
    }
    const { dim, diagonal, shape, domain } = this._d;
    for (let k = 0; k < dim; ++k) {
      const qkk = q[diagonal[k]];
      const width = qkk > 0 ? 2 * Math.sqrt(qkk) * SIDE_MARGIN : 0;
      if (!(width < this.box[k])) {
        return `2·√Q_${k}${k}·(1 + 2⁻²⁰) = ${fmt(width)} ≥ L_${k} = ` +
          `${fmt(this.box[k])} (an ${shape} must be narrower than the ` +
          `${domain})`;
      }
    }
    for (let k = 0; k < dim; ++k) {
      if (!(Math.abs(centre[k]) <= CENTRE_REACH * this.box[k])) {
        return `|c_${k}| = ${fmt(Math.abs(centre[k]))} > 2²⁹·L_${k} = ` +
          `${fmt(CENTRE_REACH * this.box[k])} (a centre must lie within 2²⁹ ` +
          'box sides of the origin)';
      }
    }
    return undefined;
  }

  // What makes (id, centre, q) fail, preferring a cause of status code.
  _cause(code, centre, q, id, isNew, seen) {
    const causes = [];
    for (const [name, x] of [['centre', centre], ['q', q]]) {
      if (!x.every(Number.isFinite)) {
        causes.push([status.PW85_EDOM, `${name} = ${list(x)} is not finite`]);
      }
    }
    if (id !== undefined) {
      if (isNew && (this._ids.has(id) || seen.has(id))) {
        causes.push([status.PW85_EINVAL, `id ${id} is already ` +
          (this._ids.has(id) ? 'stored'
            : 'used by an earlier item of this call')]);
      }
      if (!isNew && !this._ids.has(id)) {
        causes.push([status.PW85_EINVAL, `id ${id} is not stored`]);
      }
    }
    if (causes.length === 0) {
      if (!this._d.isPosDef(q)) {
        causes.push([status.PW85_ENOTPOSDEF,
          `q = ${list(q)} is not positive definite`]);
      }
      const rule = this._placement(centre, q);
      if (rule) causes.push([status.PW85_EINVAL, rule]);
    }
    const match = causes.find(([s]) => s === code) || causes[0];
    return match ? match[1] : undefined;
  }

  /**
   * Insert ellipsoids, all or none: ids (one integer or an array of n),
   * centres (3 or 3·n numbers: one centre for all, or one each), q (6 or
   * 6·n numbers). A Pw85Error names the first failing item, its id and
   * the rule it breaks; the index is then unchanged.
   */
  insert(ids, centres, q) {
    const one = typeof ids === 'number';
    const idList = one ? [ids] : Array.from(ids);
    const n = idList.length;
    idList.forEach((id, k) => idOf(id, one ? 'id' : `ids[${k}]`));
    const { dim, sym, shape } = this._d;
    const cs = records([['centres', centres, dim]]);
    const qs = records([['q', q, sym]]);
    const expand = ({ data, stride }, size) => {
      if (stride === 0 && n !== 1) {
        const out = new Float64Array(size * n);
        for (let i = 0; i < n; ++i) out.set(data, i * size);
        return out;
      }
      if (data.length !== size * n) {
        throw new RangeError(`pw85: ${n} ids but ${data.length / size} ` +
          'records');
      }
      return data;
    };
    const cd = expand(cs[0], dim);
    const qd = expand(qs[0], sym);
    const idArray = BigUint64Array.from(idList, BigInt);
    const code = this._d.c.insertMany(this._handle(), n, idArray, cd, qd);
    if (code !== status.PW85_SUCCESS) {
      const seen = new Set();
      for (let k = 0; k < n; ++k) {
        const ck = cd.subarray(dim * k, dim * k + dim);
        const qk = qd.subarray(sym * k, sym * k + sym);
        const cause = this._cause(code, ck, qk, idList[k], true, seen);
        if (cause) {
          const e = new Pw85Error(code, this._call('insert'),
            `${shape} ${idList[k]}${one ? '' : ` (item ${k} of ${n})`}: ` +
            cause);
          e.id = idList[k];
          e.item = one ? undefined : k;
          throw e;
        }
        seen.add(idList[k]);
      }
      throw new Pw85Error(code, this._call('insert'));
    }
    for (const id of idList) this._ids.add(id);
  }

  /** Move or reshape a stored ellipsoid. */
  update(id, centre, q) {
    idOf(id, 'id');
    const cd = doubles(centre, this._d.dim, 'centre');
    const qd = doubles(q, this._d.sym, 'q');
    const code = this._d.c.update(this._handle(), id, cd, qd);
    if (code !== status.PW85_SUCCESS) {
      const e = new Pw85Error(code, this._call('update'),
        `${this._d.shape} ${id}: ${this._cause(code, cd, qd, id, false) ||
          `centre = ${list(cd)}, q = ${list(qd)}`}`);
      e.id = id;
      throw e;
    }
  }

  /** Remove a stored ellipsoid. */
  remove(id) {
    idOf(id, 'id');
    check(this._d.c.remove(this._handle(), id), this._call('remove'),
      `id ${id} is not stored`);
    this._ids.delete(id);
  }

  /** {centre, q} of a stored ellipsoid, as inserted. */
  get(id) {
    idOf(id, 'id');
    const centre = new Float64Array(this._d.dim);
    const q = new Float64Array(this._d.sym);
    check(this._d.c.get(this._handle(), id, centre, q), this._call('get'),
      `id ${id} is not stored`);
    return { centre, q };
  }

  // The candidate's reach across the images of the box, where it is so
  // long that the queries, which enumerate every image, refuse it
  // (PW85_ERANGE: more than 2²⁰ boxes along an axis, pw85_index.h), or
  // undefined. The reach of within is √t times the candidate's.
  _reach(q, t = 1) {
    if (this.box == null) return undefined;
    const { dim, diagonal, domain } = this._d;
    const qkk = t === 1 ? 'Q_kk' : 't·Q_kk';
    for (let k = 0; k < dim; ++k) {
      const half = q[diagonal[k]] > 0 ? Math.sqrt(t * q[diagonal[k]]) : 0;
      if (half > IMAGE_SPAN / 2 * (1 - 2 ** -4) * this.box[k]) {
        const name = (x) => x.replace(/kk/g, `${k}${k}`);
        const root = t === 1 ? `√${name(qkk)}` : `√(${name(qkk)})`;
        return `${root} = ${fmt(half)} against L_${k} = ` +
          `${fmt(this.box[k])}: the candidate reaches across about ` +
          `2·${root}/L_${k} images of the ${domain}, and the queries, ` +
          'which enumerate every image, refuse more than 2²⁰ along an axis';
      }
    }
    return undefined;
  }

  _candidateError(code, call, centre, q, t = 1) {
    const reach = code === status.PW85_ERANGE
      ? this._reach(q, t) : undefined;
    const detail = code === status.PW85_EINVAL
      ? (this._placement(centre, new Float64Array(this._d.sym)) ||
         `centre = ${list(centre)}`)
      : (reach || this._cause(code, centre, q) ||
         `centre = ${list(centre)}, q = ${list(q)}`);
    return new Pw85Error(code, call, detail);
  }

  /**
   * Does a candidate overlap a stored ellipsoid (but `exclude`)?
   * @returns {{result: number, id: number|null}} result −1 (overlap), 0
   *          (tangent), +1 (none); id of one with that result, or null.
   */
  overlapAny(centre, q, exclude = null) {
    const cd = doubles(centre, this._d.dim, 'centre');
    const qd = doubles(q, this._d.sym, 'q');
    const ex = exclude == null ? NO_ID : BigInt(idOf(exclude, 'exclude'));
    const found = [0];
    const code = this._d.c.overlapAny(this._handle(), cd, qd, ex, outInt,
      found);
    if (code !== status.PW85_SUCCESS) {
      throw this._candidateError(code, this._call('overlap_any'), cd, qd);
    }
    const id = BigInt(found[0]);
    return { result: outInt[0], id: id === NO_ID ? null : Number(id) };
  }

  /**
   * overlapAny for n candidates (centres: 3·n numbers; q: 6·n, or 6 for
   * all), on threads. exclude: null or n ids (−1 for none).
   * @returns {{results: Int32Array, ids: Float64Array}} ids −1 for none.
   */
  overlapAnyBatch(centres, q, { exclude = null, threads = 1 } = {}) {
    const ins = records([['centres', centres, this._d.dim],
      ['q', q, this._d.sym]]);
    const n = ins[2];
    let ex = null;
    if (exclude != null) {
      if (exclude.length !== n) {
        throw new RangeError(`pw85: exclude must hold ${n} ids`);
      }
      ex = BigUint64Array.from(exclude, (x) => (x === -1 ? NO_ID
        : BigInt(idOf(x, 'exclude'))));
    }
    const results = new Int32Array(n);
    const found = new BigUint64Array(n);
    const args = [this._handle(), n, ins[0].data, ins[0].stride,
      ins[1].data, ins[1].stride, ex, results, found];
    const code = this._d.c.overlapAnyBatch(...args, null,
      threadCount(threads));
    if (code !== status.PW85_SUCCESS) {
      const st = new Int32Array(n);
      this._d.c.overlapAnyBatch(...args, st, threads);
      const i = st.findIndex((s) => s !== 0);
      const at = (x) => x.data.subarray(i * x.stride, i * x.stride + x.size);
      const inner = this._candidateError(code, this._call('overlap_any_batch'),
        at(ins[0]), at(ins[1]));
      const e = new Pw85Error(code, this._call('overlap_any_batch'),
        `candidate ${i} of ${n}: ${inner.detail}`);
      e.index = i;
      e.statuses = st;
      throw e;
    }
    const ids = Float64Array.from(found, (x) => (x === NO_ID ? -1
      : Number(x)));
    return { results, ids };
  }

  // Call with room for `guess` results, then again if too few.
  _collect(call, name, idsPerRow, doublesPerRow, guess, error) {
    let cap = guess;
    for (;;) {
      const ids = new BigUint64Array(idsPerRow * cap);
      const shifts = new Int32Array(this._d.dim * cap);
      const values = doublesPerRow ? new Float64Array(2 * cap)
        : new Int32Array(cap);
      const count = [0];
      const code = call(cap, ids, shifts, values, count);
      if (code !== status.PW85_SUCCESS) {
        throw error ? error(code) : new Pw85Error(code, name);
      }
      const m = Number(count[0]);
      if (m <= cap) return { m, ids, shifts, values };
      cap = m;
    }
  }

  /** Every stored ellipsoid and image with μ² < t from a candidate:
   *  [{id, shift, mu2, lambda}], sorted by id, then shift. */
  within(centre, q, t = 1, exclude = null) {
    const cd = doubles(centre, this._d.dim, 'centre');
    const qd = doubles(q, this._d.sym, 'q');
    threshold(t, this._call('within'));
    const ex = exclude == null ? NO_ID : BigInt(idOf(exclude, 'exclude'));
    const r = this._collect((cap, ids, shifts, ml, count) => this._d.c.within(
      this._handle(), cd, qd, t, ex, cap, ids, shifts, ml, count),
    this._call('within'), 1, true, 16,
    (code) => this._candidateError(code, this._call('within'), cd, qd, t));
    return Array.from({ length: r.m }, (_, k) => ({
      id: Number(r.ids[k]),
      shift: this._shift(r.shifts, k),
      mu2: r.values[2 * k],
      lambda: r.values[2 * k + 1],
    }));
  }

  _shift(shifts, k) {
    const n = this._d.dim;
    return Array.from(shifts.subarray(n * k, n * k + n));
  }

  _threads(threads, name) {
    if (!Number.isInteger(threads) || threads < 1) {
      throw new Pw85Error(status.PW85_EINVAL, name,
        `threads = ${threads} is not an integer ≥ 1`);
    }
    if (threads > 2 ** 31 - 1) {
      throw new Pw85Error(status.PW85_EINVAL, name,
        `threads = ${threads} is above 2³¹ − 1 (a C int)`);
    }
    return threads;
  }

  /** Every overlapping (or tangent) pair, each once:
   *  [{i, j, shift, result}], sorted by i, j, shift. */
  overlappingPairs({ threads = 1 } = {}) {
    const th = this._threads(threads, this._call('overlapping_pairs'));
    const r = this._collect((cap, ids, shifts, res, count) =>
      this._d.c.overlappingPairs(this._handle(), th, cap, ids, shifts, res,
        count), this._call('overlapping_pairs'), 2, false,
    4 * this.size + 16);
    return Array.from({ length: r.m }, (_, k) => ({
      i: Number(r.ids[2 * k]),
      j: Number(r.ids[2 * k + 1]),
      shift: this._shift(r.shifts, k),
      result: r.values[k],
    }));
  }

  /** Every pair (and image) with μ² < t, each once:
   *  [{i, j, shift, mu2, lambda}]. */
  pairsWithin(t, { threads = 1 } = {}) {
    threshold(t, this._call('pairs_within'));
    const th = this._threads(threads, this._call('pairs_within'));
    const r = this._collect((cap, ids, shifts, ml, count) =>
      this._d.c.pairsWithin(this._handle(), t, th, cap, ids, shifts, ml,
        count),
    this._call('pairs_within'), 2, true, 8 * this.size + 16);
    return Array.from({ length: r.m }, (_, k) => ({
      i: Number(r.ids[2 * k]),
      j: Number(r.ids[2 * k + 1]),
      shift: this._shift(r.shifts, k),
      mu2: r.values[2 * k],
      lambda: r.values[2 * k + 1],
    }));
  }

  toString() {
    const d = this._d;
    if (this._h == null) return `${d.name} (closed)`;
    const n = this.size;
    return `${d.name}: ${this.box == null ? 'open domain'
      : `periodic ${d.domain} (${list(this.box).slice(1, -1)})`}, ${n} ` +
      `${d.shape}${n === 1 ? '' : 's'}`;
  }
}

/**
 * A spatial index of ellipsoids in an open domain or a periodic box
 * (pw85_index.h): its queries give the answers of overlap() and
 * contactFunction() on every pair and periodic image. Holds library
 * memory: call close() when done. Ids are integers from 0 to MAX_ID.
 */
class Index extends IndexBase {
  static get dimension() {
    return INDEX_3D;
  }
}

/**
 * The index of ellipses in an open plane or a periodic rectangle
 * (pw85_2d_index.h, pw85.d2.Index): Index for vectors of 2 numbers and
 * forms [Q00, Q01, Q11], shifts of 2 integers; the answers of
 * d2.overlap() and d2.contactFunction() on every pair and image.
 */
class Index2d extends IndexBase {
  static get dimension() {
    return INDEX_2D;
  }
}

d2.Index = Index2d;
Object.freeze(d2);

/** The version of the library loaded, "MAJOR.MINOR.PATCH". */
function version() {
  return loaded;
}

/** pw85's message for a status code. */
function strerror(code) {
  return c.strerror(code);
}

module.exports = {
  DIM, SYM, UNIT_TOL, GEOM, DERIV, MAX_ID, status, Pw85Error, version,
  strerror, libraryPath: path, spheroid, f, contactFunction, overlap,
  ellipsoidRotation, ellipsoidQuaternion, principalAxes,
  principalAxesQuaternion, contactGeometry, contactDerivatives, batchThreads,
  contactFunctionBatch, overlapBatch, contactGeometryBatch,
  contactDerivativesBatch, Index, d2,
};
