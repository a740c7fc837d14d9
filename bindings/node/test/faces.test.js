// SPDX-License-Identifier: BSD-3-Clause
'use strict';
// node --test, issue 30: the whole C surface that makes sense in
// JavaScript, the index as a class, errors that name their cause (and the
// library file when it cannot be loaded), TypeScript declarations that
// match the exports, and `npm pack` giving a tarball that installs into
// an empty folder. References are hand-derived (spheres, diagonal forms).
const test = require('node:test');
const assert = require('node:assert/strict');
const childProcess = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const pw85 = require('..');

const U = 2 ** -53;
const near = (x, y, tol) => Math.abs(x - y) <= tol;
const sphere = (r) => [r * r, 0, 0, r * r, 0, r * r];
const throwsWith = (f, code, text) => assert.throws(f, (e) => {
  assert.ok(e instanceof pw85.Pw85Error, e);
  assert.equal(e.code, code);
  for (const t of [].concat(text)) assert.ok(e.message.includes(t), e.message);
  return true;
});

test('a library that cannot be loaded is named, with PW85_LIBRARY', () => {
  const run = (env) => childProcess.spawnSync(process.execPath,
    ['-e', 'require(".")'], { cwd: path.join(__dirname, '..'),
      env: { ...process.env, ...env }, encoding: 'utf8' });
  const bad = run({ PW85_LIBRARY: '/nonexistent/libpw85.so.2' });
  assert.notEqual(bad.status, 0);
  assert.match(bad.stderr, /cannot load \/nonexistent\/libpw85\.so\.2 \(from the environment variable PW85_LIBRARY\)/);
  const unset = run({ PW85_LIBRARY: '', LD_LIBRARY_PATH: '' });
  if (unset.status !== 0) { // unless a libpw85 is installed system-wide
    assert.match(unset.stderr, /cannot load libpw85\.so\.2 .*PW85_LIBRARY is not set/);
    assert.match(unset.stderr, /Set PW85_LIBRARY to the full path/);
  }
});

test('spheres: μ² = |r|²/(r1 + r2)², λ = r1/(r1 + r2), contact point, normal', () => {
  // Hand-derived: radii 1 and 2, centres 6 apart along (0.6, 0.8, 0).
  const r12 = [3.6, 4.8, 0];
  const { mu2, lambda } = pw85.contactFunction(r12, sphere(1), sphere(2));
  assert.ok(near(mu2, 4, 4 * 4 * U) && near(lambda, 1 / 3, 8 * U));
  const g = pw85.contactGeometry(r12, sphere(1), sphere(2));
  assert.ok(g instanceof Float64Array && g.length === pw85.GEOM.SIZE);
  assert.equal(g[pw85.GEOM.MU2], mu2);
  // The scaled spheres (radii 2 and 4) touch 2 from c1: x − c1 = r12/3.
  for (let k = 0; k < 3; ++k) {
    assert.ok(near(g[pw85.GEOM.POINT + k], r12[k] / 3, 16 * U));
    assert.ok(near(g[pw85.GEOM.NORMAL + k], r12[k] / 6, 16 * U));
  }
  const { geometry, d } = pw85.contactDerivatives(r12, sphere(1), sphere(2));
  assert.deepEqual(geometry, g);
  // ∂μ²/∂r12 = 2·r12/(r1 + r2)², torques 0 on spheres.
  for (let k = 0; k < 3; ++k) {
    assert.ok(near(d[pw85.DERIV.R12 + k], 2 * r12[k] / 9, 16 * U));
    assert.ok(near(d[pw85.DERIV.ROT1 + k], 0, 16 * U));
  }
  assert.equal(pw85.overlap(r12, sphere(1), sphere(2)), 1);
  assert.ok(near(pw85.f(1 / 3, r12, sphere(1), sphere(2)), 4, 8 * U));
});

test('constructors and principal axes, quaternions in either order', () => {
  const a = [3, 2, 1];
  // A quarter turn about z: a[0] along y, a[1] along −x.
  const h = Math.SQRT1_2;
  const q = pw85.ellipsoidQuaternion(a, [h, 0, 0, h]);
  const last = pw85.ellipsoidQuaternion(a, [0, 0, h, h], { scalarFirst: false });
  assert.deepEqual(last, q);
  const expected = [4, 0, 0, 9, 0, 1];
  for (let k = 0; k < 6; ++k) assert.ok(near(q[k], expected[k], 32 * U));
  assert.deepEqual(pw85.ellipsoidRotation(a, [0, -1, 0, 1, 0, 0, 0, 0, 1]),
    Float64Array.from(expected));
  const axes = pw85.principalAxes(expected);
  assert.deepEqual(Array.from(axes.a), a);
  // R has columns e_y, e_x, −e_z: the half-turn about (1, 1, 0)/√2.
  const pq = pw85.principalAxesQuaternion(expected);
  assert.ok(near(pq.p[0], 0, 0) && near(pq.p[1], h, 2 * U) &&
    near(pq.p[2], h, 2 * U) && near(pq.p[3], 0, 0));
  const pl = pw85.principalAxesQuaternion(expected, { scalarFirst: false });
  assert.deepEqual(Array.from(pl.p), [pq.p[1], pq.p[2], pq.p[3], pq.p[0]]);
});

test('spheroid refuses a ≤ 0, c ≤ 0 and a non-unit axis, naming the rule', () => {
  throwsWith(() => pw85.spheroid(0, 2, [0, 0, 1]), 'PW85_EINVAL', 'a = 0 is not > 0');
  throwsWith(() => pw85.spheroid(-1, 2, [0, 0, 1]), 'PW85_EINVAL', 'a = -1 is not > 0');
  throwsWith(() => pw85.spheroid(1, 0, [0, 0, 1]), 'PW85_EINVAL', 'c = 0 is not > 0');
  throwsWith(() => pw85.spheroid(1, 2, [0, 1, 1]), 'PW85_EINVAL', '‖n‖² = 2');
  throwsWith(() => pw85.spheroid(1, 2, [0, 0, 0]), 'PW85_EINVAL', 'not a unit vector');
  throwsWith(() => pw85.spheroid(NaN, 2, [0, 0, 1]), 'PW85_EDOM', 'a = NaN');
  assert.throws(() => pw85.spheroid('1', 2, [0, 0, 1]), TypeError);
  assert.deepEqual(Array.from(pw85.spheroid(2, 3, [0, 0, 1])), [4, 0, 0, 4, 0, 9]);
});

test('batches: one record for all (stride 0), each pair as alone, the item named', () => {
  const n = 600;
  const r12 = new Float64Array(3 * n);
  for (let i = 0; i < n; ++i) r12.set([0.01 * i, 1, 0.5], 3 * i);
  const q1 = pw85.spheroid(1, 0.5, [0, 0, 1]);
  const q2 = pw85.spheroid(0.3, 2, [1, 0, 0]);
  const out = pw85.contactFunctionBatch(r12, q1, q2, { threads: 2 });
  const res = pw85.overlapBatch(r12, q1, q2);
  const geo = pw85.contactGeometryBatch(r12, q1, q2, { threads: 0 });
  const der = pw85.contactDerivativesBatch(r12, q1, q2);
  for (const i of [0, 1, 299, 599]) {
    const r = r12.subarray(3 * i, 3 * i + 3);
    const one = pw85.contactFunction(r, q1, q2);
    assert.deepEqual([out[2 * i], out[2 * i + 1]], [one.mu2, one.lambda]);
    assert.equal(res[i], pw85.overlap(r, q1, q2));
    assert.deepEqual(geo.subarray(8 * i, 8 * i + 8), pw85.contactGeometry(r, q1, q2));
    assert.deepEqual(der.d.subarray(21 * i, 21 * i + 21),
      pw85.contactDerivatives(r, q1, q2).d);
  }
  const bad = new Float64Array(6 * n);
  for (let i = 0; i < n; ++i) bad.set(q2, 6 * i);
  bad[6 * 7 + 3] = -1;
  assert.throws(() => pw85.contactFunctionBatch(r12, q1, bad), (e) => {
    assert.equal(e.code, 'PW85_ENOTPOSDEF');
    assert.equal(e.index, 7);
    assert.ok(e.message.includes('pair 7 of 600 (1 of 600 failed)'), e.message);
    return true;
  });
  assert.throws(() => pw85.overlapBatch(r12.subarray(1), q1, q2), RangeError);
  // Each message names the bound that the count breaks.
  assert.throws(() => pw85.overlapBatch(r12, q1, q2, { threads: -1 }),
    { name: 'RangeError', message: /positive integer, got -1$/ });
  assert.throws(() => pw85.overlapBatch(r12, q1, q2, { threads: 2 ** 31 }),
    { name: 'RangeError', message: /at most 2³¹ − 1 \(a C int\), got 2147483648$/ });
  assert.ok(pw85.batchThreads() >= 1);
  assert.equal(pw85.batchThreads(1), 1);
});

test('Index: a class with close(), the queries, ids as a collection', () => {
  const q = sphere(1);
  const index = new pw85.Index([6, 6, 6]);
  index.insert([4, 2, 9], [0, 0, 0, 1.5, 0, 0, 3.4, 0, 0], q);
  index.insert([10, 11], [0, 3, 0], pw85.spheroid(1, 1, [0, 0, 1]));
  assert.equal(index.size, 5);
  assert.deepEqual(index.ids(), [2, 4, 9, 10, 11]);
  assert.deepEqual([...index], [2, 4, 9, 10, 11]);
  assert.ok(index.has(9) && !index.has(3) && !index.has(9.5));
  assert.equal(String(index), 'pw85.Index: periodic box (6, 6, 6), 5 ellipsoids');
  // Hand-derived: unit spheres whose centres are d apart have μ² = d²/4.
  const pairs = index.overlappingPairs({ threads: 2 });
  assert.deepEqual(pairs.map((p) => [p.i, p.j, p.result]),
    [[2, 4, -1], [2, 9, -1], [10, 11, -1]]);
  const within = index.within([0, 0, 0], q, 1);
  assert.deepEqual(within.map((x) => [x.id, x.mu2]), [[2, 0.5625], [4, 0]]);
  assert.deepEqual(index.overlapAny([0, 0, 0], q, 4).result, -1);
  assert.deepEqual(index.overlapAny([3, 3, 3], sphere(0.1)), { result: 1, id: null });
  const batch = index.overlapAnyBatch([0, 0, 0, 3, 3, 3], q, { exclude: [4, -1] });
  assert.deepEqual(Array.from(batch.results), [-1, 1]);
  assert.deepEqual(Array.from(batch.ids), [2, -1]);
  const near1 = index.pairsWithin(1.01);
  assert.ok(near1.some((p) => p.i === 2 && p.j === 4 && p.mu2 === 1.5 * 1.5 / 4));
  assert.deepEqual(index.get(9).centre, Float64Array.of(3.4, 0, 0));
  index.update(9, [4, 0, 0], q);
  index.remove(9);
  assert.ok(!index.has(9) && index.size === 4);
  index.close();
  assert.throws(() => index.size, /closed/);
  assert.equal(String(index), 'pw85.Index (closed)');
});

test('Index errors name the rule, the id, the item and the numbers', () => {
  const q = sphere(1);
  const index = new pw85.Index([3, 3, 3]);
  index.insert([0, 1], [0, 0, 0, 1, 1, 1], q);
  const wide = [...q, 2.4, 0, 0, 1, 0, 1];
  const width = 2 * Math.sqrt(2.4) * (1 + 2 ** -20);
  throwsWith(() => index.insert([5, 12], [0, 0, 0], wide), 'PW85_EINVAL',
    ['ellipsoid 12 (item 1 of 2)', `2·√Q_00·(1 + 2⁻²⁰) = ${width} ≥ L_0 = 3`]);
  throwsWith(() => index.insert(1, [0, 0, 0], q), 'PW85_EINVAL', 'id 1 is already stored');
  throwsWith(() => index.insert([7, 7], [0, 0, 0], q), 'PW85_EINVAL',
    'id 7 is already used by an earlier item');
  throwsWith(() => index.remove(9), 'PW85_EINVAL', 'id 9 is not stored');
  throwsWith(() => index.get(9), 'PW85_EINVAL', 'id 9 is not stored');
  throwsWith(() => index.update(9, [0, 0, 0], q), 'PW85_EINVAL', 'id 9 is not stored');
  throwsWith(() => index.insert([3, 4], [0, 0, 0, NaN, 0, 0], q), 'PW85_EDOM',
    ['ellipsoid 4 (item 1 of 2)', 'centre = [NaN, 0, 0] is not finite']);
  throwsWith(() => index.insert(3, [0, 0, 0], [1, 2, 0, 1, 0, 1]), 'PW85_ENOTPOSDEF',
    'is not positive definite');
  throwsWith(() => index.update(0, [1e10, 0, 0], q), 'PW85_EINVAL',
    `|c_0| = 10000000000 > 2²⁹·L_0 = ${2 ** 29 * 3}`);
  throwsWith(() => index.overlapAny([0, -1e10, 0], q), 'PW85_EINVAL', '|c_1| = 10000000000');
  throwsWith(() => index.within([0, 0, 0], q, 0), 'PW85_EINVAL', 't = 0 is not > 0');
  throwsWith(() => index.overlappingPairs({ threads: 0 }), 'PW85_EINVAL', 'threads = 0');
  throwsWith(() => index.overlappingPairs({ threads: 2 ** 31 }), 'PW85_EINVAL',
    'threads = 2147483648 is above 2³¹ − 1 (a C int)');
  throwsWith(() => index.overlapAnyBatch([0, 0, 0, 0, 0, 0], [...q, 1, 2, 0, 1, 0, 1]),
    'PW85_ENOTPOSDEF', 'candidate 1 of 2');
  assert.throws(() => index.insert(2.5, [0, 0, 0], q), TypeError);
  assert.throws(() => index.insert(-1, [0, 0, 0], q), TypeError);
  assert.equal(index.size, 2);
  index.close();
  throwsWith(() => new pw85.Index([1, -2, 1]), 'PW85_EINVAL', 'box side L_1 = -2 is not > 0');
  throwsWith(() => new pw85.Index([1, 2, Infinity]), 'PW85_EDOM', 'L_2 = Infinity is not finite');
  // The bounds that keep sums of centres and sides finite (pw85_index.h).
  throwsWith(() => new pw85.Index([1, 1e299, 1]), 'PW85_EINVAL',
    'box side L_1 = 1e+299 is above 2⁹⁹² = 4.185580496821357e+298');
  throwsWith(() => new pw85.d2.Index([2 ** 993, 1]), 'PW85_EINVAL',
    'rectangle side L_0 = 8.371160993642713e+298 is above 2⁹⁹²');
  for (const open of [new pw85.Index(), new pw85.d2.Index()]) {
    const dim = open instanceof pw85.Index ? 3 : 2;
    const centre = new Array(dim).fill(0);
    centre[dim - 1] = -1e308;
    const form = dim === 3 ? [1, 0, 0, 1, 0, 1] : [1, 0, 1];
    throwsWith(() => open.insert(0, centre, form), 'PW85_EINVAL',
      `|c_${dim - 1}| = 1e+308 > 2¹⁰²¹ = 2.247116418577895e+307`);
    throwsWith(() => open.overlapAny(centre, form), 'PW85_EINVAL', '> 2¹⁰²¹');
    assert.equal(open.size, 0);
    open.close();
  }
});

test('within and pairsWithin name t when it is not finite, not the candidate', () => {
  // t = ±Infinity reached libpw85 (PW85_EDOM), whose detail then listed the
  // centre and q.
  for (const [index, c, q] of [[new pw85.Index([3, 3, 3]), [0, 0, 0], sphere(1)],
    [new pw85.d2.Index([3, 3]), [0, 0], [1, 0, 1]]]) {
    index.insert(0, c, q);
    for (const t of [Infinity, -Infinity, NaN]) {
      for (const f of [() => index.within(c, q, t), () => index.pairsWithin(t)]) {
        assert.throws(f, (e) => {
          assert.equal(e.code, 'PW85_EDOM');
          assert.equal(e.detail, `t = ${t} is not finite`);
          return true;
        });
      }
    }
    throwsWith(() => index.pairsWithin(-1), 'PW85_EINVAL', 't = -1 is not > 0');
    index.close();
  }
});

test('a candidate reaching across more than 2²⁰ images: PW85_ERANGE naming the reach', () => {
  // pw85_index.h: the queries refuse a candidate whose images in reach span
  // more than 2²⁰ boxes (a half-length of about 2¹⁹ sides). The detail cited
  // the width rule of stored ellipsoids, which candidates are not under.
  for (const [index, c, ball] of [
    [new pw85.Index([1, 1, 1]), [0.5, 0, 0], [0.01, 0, 0, 0.01, 0, 0.01]],
    [new pw85.d2.Index([1, 1]), [0.5, 0], [0.01, 0, 0.01]]]) {
    index.insert(0, c.map(() => 0), ball);
    const needle = [...ball];
    needle[0] = 2 ** 36; // a half-length of 2¹⁸ sides: decided
    assert.deepEqual(index.overlapAny(c, needle), { result: -1, id: 0 });
    needle[0] = 2 ** 38; // 2¹⁹ sides
    const reach = ['√Q_00 = 524288 against L_0 = 1', 'images of the ' +
      `${c.length === 3 ? 'box' : 'rectangle'}`, 'refuse more than 2²⁰'];
    const notWidth = (f, text) => assert.throws(f, (e) => {
      assert.equal(e.code, 'PW85_ERANGE');
      for (const x of [].concat(text)) assert.ok(e.detail.includes(x), e.detail);
      assert.ok(!e.detail.includes('narrower'), e.detail);
      return true;
    });
    notWidth(() => index.overlapAny(c, needle), reach);
    notWidth(() => index.overlapAnyBatch([...c, ...c], [...ball, ...needle]),
      ['candidate 1 of 2: ', ...reach]);
    notWidth(() => index.within(c, needle), reach);
    // within's reach is √t times the candidate's.
    notWidth(() => index.within(c, ball, 2 ** 80), '√(t·Q_00) = 109951162777.6');
    index.close();
  }
});

test('empty inputs: nothing done, empty results, as n = 0 in C', () => {
  // They were RangeErrors; libpw85 takes n = 0 (PW85_SUCCESS, nothing read).
  const q = sphere(1);
  for (const [index, c, f] of [[new pw85.Index([3, 3, 3]), [0, 0, 0], q],
    [new pw85.d2.Index(null), [0, 0], [1, 0, 1]]]) {
    index.insert([], [], []);
    index.insert([], c, f); // one record for all of no items
    assert.equal(index.size, 0);
    index.insert(7, c, f);
    index.insert([], [], []);
    assert.deepEqual(index.ids(), [7]);
    for (const out of [index.overlapAnyBatch([], f),
      index.overlapAnyBatch([], [], { exclude: [], threads: 2 })]) {
      assert.ok(out.results instanceof Int32Array && out.results.length === 0);
      assert.ok(out.ids instanceof Float64Array && out.ids.length === 0);
    }
    assert.throws(() => index.insert([], c.concat(c), f), RangeError); // 0 ids, 2 centres
    index.close();
    assert.throws(() => index.insert([], [], []), /closed/);
  }
  const out = pw85.contactFunctionBatch([], q, q);
  assert.ok(out instanceof Float64Array && out.length === 0);
  assert.equal(pw85.overlapBatch([], [], []).length, 0);
  assert.equal(pw85.d2.ellipseBatch([], []).length, 0);
});

test('index.d.ts declares every export, and only those', () => {
  const dts = fs.readFileSync(path.join(__dirname, '..', 'index.d.ts'), 'utf8');
  const declared = new Set([...dts.matchAll(
    /^export (?:declare )?(?:function|const|class) (\w+)/gm)].map((m) => m[1]));
  assert.deepEqual([...declared].sort(), Object.keys(pw85).sort());
  const pkg = require('../package.json');
  assert.equal(pkg.types, 'index.d.ts');
  assert.ok(pkg.files.includes('index.d.ts'));
});

test('npm pack: a tarball that installs into an empty folder and works', (t) => {
  const npm = childProcess.spawnSync('npm', ['--version'], { encoding: 'utf8' });
  if (npm.status !== 0) {
    t.skip('npm not found');
    return;
  }
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'pw85-pack-'));
  try {
    const pack = childProcess.spawnSync('npm', ['pack', '--pack-destination', tmp],
      { cwd: path.join(__dirname, '..'), encoding: 'utf8' });
    assert.equal(pack.status, 0, pack.stderr);
    const tarball = path.join(tmp, pack.stdout.trim().split('\n').pop());
    const app = path.join(tmp, 'app');
    fs.mkdirSync(app);
    const install = childProcess.spawnSync('npm', ['install', '--no-audit',
      '--no-fund', '--prefer-offline', tarball], { cwd: app, encoding: 'utf8' });
    assert.equal(install.status, 0, install.stderr);
    const files = fs.readdirSync(path.join(app, 'node_modules', 'pw85')).sort();
    assert.deepEqual(files, ['index.d.ts', 'index.js', 'package.json']);
    const run = childProcess.spawnSync(process.execPath, ['-e',
      'const p = require("pw85"); const s = [1, 0, 0, 1, 0, 1];' +
      'console.log(p.version(), p.contactFunction([4, 0, 0], s, s).mu2)'],
    { cwd: app, encoding: 'utf8' });
    assert.equal(run.status, 0, run.stderr);
    assert.equal(run.stdout.trim(), `${process.env.PW85_EXPECTED_VERSION} 4`);
  } finally {
    fs.rmSync(tmp, { recursive: true, force: true });
  }
});
