// SPDX-License-Identifier: BSD-3-Clause
'use strict';
// node --test: the package against the library of PW85_LIBRARY, whose
// version is PW85_EXPECTED_VERSION (both set by meson).
const test = require('node:test');
const assert = require('node:assert/strict');
const pw85 = require('..');

// The tutorial's pair (docs/tutorial.rst, tutorial/tutorial.c).
const q1 = pw85.spheroid(10, 0.1, [0, 0, 1]);
const q2 = pw85.spheroid(0.5, 5, [1, 0, 0]);
const r12 = [0.7, -0.7, 1.1];

test('version is that of the library built', () => {
  assert.equal(pw85.version(), process.env.PW85_EXPECTED_VERSION);
});

test('spheroid: Q = a²I + (c² − a²)nnᵀ', () => {
  assert.ok(q1 instanceof Float64Array);
  assert.deepEqual(Array.from(q1), [100, 0, 0, 100, 0, 0.1 * 0.1]);
  assert.deepEqual(Array.from(q2), [25, 0, 0, 0.25, 0, 0.25]);
});

test('contactFunction: the tutorial figures, exactly', () => {
  const { mu2, lambda } = pw85.contactFunction(r12, q1, q2);
  assert.equal(mu2, 3.3627060406386291);
  assert.equal(lambda, 0.16685895534055478);
  assert.equal(mu2.toPrecision(6), '3.36271');
  assert.equal(lambda.toPrecision(6), '0.166859');
});

test('contactFunction: typed arrays and plain arrays agree', () => {
  const a = pw85.contactFunction(Float64Array.from(r12), q1, q2);
  const b = pw85.contactFunction(r12, Array.from(q1), Array.from(q2));
  assert.deepEqual(a, b);
});

test('overlap: disjoint, overlapping, coincident', () => {
  assert.equal(pw85.overlap(r12, q1, q2), 1);
  assert.equal(pw85.overlap(r12.map((x) => x / 10), q1, q2), -1);
  assert.equal(pw85.overlap([0, 0, 0], q1, q2), -1);
});

test('errors are Pw85Error with the status and pw85\'s message', () => {
  const bad = Array.from(q1);
  bad[3] = -1;
  assert.throws(() => pw85.contactFunction(r12, bad, q2), (e) =>
    e instanceof pw85.Pw85Error &&
    e.status === pw85.status.PW85_ENOTPOSDEF &&
    e.code === 'PW85_ENOTPOSDEF' &&
    e.message.startsWith('pw85_contact_function: ' +
      pw85.strerror(pw85.status.PW85_ENOTPOSDEF) + ' (PW85_ENOTPOSDEF): '));
  assert.throws(() => pw85.overlap([NaN, 0, 0], q1, q2),
    (e) => e instanceof pw85.Pw85Error && e.code === 'PW85_EDOM');
});

test('entries of the wrong type are TypeErrors naming the entry, before any call', () => {
  // They reached libpw85 as NaN (PW85_EDOM) or, numeric strings, as numbers.
  const typeError = (f, text) => assert.throws(f, (e) => {
    assert.ok(e instanceof TypeError && !(e instanceof pw85.Pw85Error), e);
    assert.ok(e.message.includes(text), e.message);
    return true;
  });
  typeError(() => pw85.contactFunction(['x', 0, 0], q1, q2), 'r12[0] must be a number, got string');
  typeError(() => pw85.contactFunction(['0.7', '-0.7', '1.1'], q1, q2), 'r12[0]');
  typeError(() => pw85.overlap(r12, q1, [25, 0, 0, 0.25, {}, 0.25]), 'q2[4] must be a number, got object');
  typeError(() => pw85.contactFunction(r12, q1, [25, 0, 0, 0.25, null, 0.25]), 'q2[4] must be a number, got null');
  typeError(() => pw85.contactFunction([1n, 0n, 0n], q1, q2), 'r12[0] must be a number, got bigint');
  typeError(() => pw85.contactFunction(BigInt64Array.of(1n, 0n, 0n), q1, q2), 'r12 must hold numbers');
  typeError(() => pw85.spheroid(1, 2, [0, 0, '1']), 'n[2]');
  typeError(() => pw85.contactFunctionBatch([0.7, -0.7, 1.1, 'x', 0, 0], q1, q2), 'r12[3]');
  typeError(() => pw85.d2.contactFunction([1, '0'], [1, 0, 1], [1, 0, 1]), 'r12[1]');
  const index = new pw85.Index([3, 3, 3]);
  typeError(() => index.insert(0, ['1', 0, 0], [1, 0, 0, 1, 0, 1]), 'centres[0]');
  typeError(() => index.within([0, 0, 0], [1, 0, 0, 1, 0, '1']), 'q[5]');
  assert.equal(index.size, 0);
  index.close();
  typeError(() => new pw85.Index([3, '3', 3]), 'box[1]');
  // Typed arrays of numbers are numbers: accepted as they were.
  assert.deepEqual(pw85.contactFunction(Float32Array.of(0.5, 0, 0), q1, q2),
    pw85.contactFunction([0.5, 0, 0], q1, q2));
});

test('wrong lengths are RangeErrors, before any call', () => {
  assert.throws(() => pw85.contactFunction([1, 2], q1, q2), RangeError);
  assert.throws(() => pw85.overlap(r12, q1.subarray(1), q2), RangeError);
  assert.throws(() => pw85.spheroid(1, 2, [0, 0, 1, 0]), RangeError);
  assert.throws(() => pw85.contactFunction(r12, null, q2), RangeError);
});

test('strerror names every status, and an unknown one', () => {
  const messages = new Set(Object.values(pw85.status).map(pw85.strerror));
  assert.equal(messages.size, Object.keys(pw85.status).length);
  assert.ok(pw85.strerror(-1).length > 0);
});
