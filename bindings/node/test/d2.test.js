// SPDX-License-Identifier: BSD-3-Clause
'use strict';
// node --test: pw85.d2, the ellipses of pw85_2d.h. References: two pairs
// of data/pw85_2d_geometry.h5 (records 0, generic, and 45, needles: μ²
// correctly rounded, the contact point, normal and derivatives at 100
// digits, by data/gen_2d_data.py, which does not use the library), held
// to the bounds that pw85_2d.h states and tests/test-2d-ref-data.c
// checks; closed forms (circles); the batches against the single calls,
// bit for bit; the errors; index.d.ts against the exports of d2.
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const pw85 = require('..');

const { d2 } = pw85;
const U = 2 ** -53;

const REFS = [
  { r12: [1.9989159046617608, -3.044689301411269],
    q1: [0.2417720451269342, 0.2850317448721523, 0.48931277063246487],
    q2: [0.28553482236021804, -0.14094123595110067, 0.1244247848425048],
    mu2: 16.878830868251367, lambda: 0.30368373455936615,
    oneMinusLambda: 0.6963162654406339, condQ: 3.2429251694831644,
    point: [-0.12065865299204054, -1.747854754907362],
    normal: [0.7492435313217497, -0.6622945951557465],
    dR12: [7.197378009569009, -6.362129742543438],
    dTheta1: -13.347617381786767, dTheta2: 4.151199887730983,
    dQ1: [-42.644900201677494, 75.39200736161852, -33.32142147791189],
    dQ2: [-18.598678784218375, 32.8806427306638, -14.53243909049787] },
  { r12: [0.032140944055141306, -0.08389241585244309],
    q1: [773943.2895381401, 348993.80348200165, 157371.57556351958],
    q2: [1567872.5893307645, 707280.0624238843, 319059.7855222649],
    mu2: 0.24472390461969842, lambda: 0.5863494102016485,
    oneMinusLambda: 0.4136505897983514, condQ: 187102379.02312982,
    point: [435.1502087256998, 196.22201971177108],
    normal: [0.4111695474935831, -0.9115588863117523],
    dR12: [2.243839342977438, -4.97456999190566],
    dTheta1: 2604.975858086117, dTheta2: -2605.0042118135757,
    dQ1: [-2.1466786311603525, 9.518331278268155, -10.551023917572406],
    dQ2: [-3.04291539844523, 13.492227664505748, -14.95606872966853] },
];

const norm = (v) => Math.hypot(...v);
const dist = (x, y) => Math.hypot(...Array.from(x, (t, i) => t - y[i]));
const { GEOM, DERIV } = d2;

test('d2 constants: the layouts of pw85_2d.h', () => {
  const header = fs.readFileSync(path.join(__dirname, '..', '..', '..',
    'include', 'pw85', 'pw85_2d.h'), 'utf8');
  const macros = Object.fromEntries([...header.matchAll(
    /^#define PW85_2D_(\w+) (\d+)/gm)].map((m) => [m[1], Number(m[2])]));
  assert.ok(Object.keys(macros).length >= 13, Object.keys(macros));
  for (const [name, value] of Object.entries(macros)) {
    const [group, ...rest] = name.split('_');
    const key = rest.join('_');
    if (group === 'GEOM') assert.equal(GEOM[key], value, name);
    else if (group === 'DERIV') assert.equal(DERIV[key], value, name);
    else assert.equal(d2[name], value, name);
  }
  assert.equal(Object.keys(GEOM).length + Object.keys(DERIV).length + 2,
    Object.keys(macros).length);
});

test('d2.contactFunction, overlap, f: the mpmath references', () => {
  for (const p of REFS) {
    const { mu2, lambda } = d2.contactFunction(p.r12, p.q1, p.q2);
    assert.equal(mu2, p.mu2); // correctly rounded (pw85_2d.h)
    // λ: 8·u·cond(Q(λ*)) relative to min(λ*, 1 − λ*) (test-2d-ref-data).
    assert.ok(Math.abs(lambda - p.lambda) <=
      8 * U * p.condQ * Math.min(p.lambda, p.oneMinusLambda), lambda);
    assert.equal(d2.overlap(p.r12, p.q1, p.q2), p.mu2 > 1 ? 1 : -1);
    // f at the maximiser: μ² to within an ulp (the maximum is flat).
    assert.ok(Math.abs(d2.f(lambda, p.r12, p.q1, p.q2) - mu2) <= 2 * U * mu2);
    // Swapping the ellipses: the same μ², bit for bit.
    const sw = d2.contactFunction(p.r12.map((x) => -x), p.q2, p.q1);
    assert.equal(sw.mu2, mu2);
  }
});

test('d2.contactDerivatives: point, normal, derivatives within the bounds', () => {
  for (const p of REFS) {
    const { geometry: g, d } = d2.contactDerivatives(p.r12, p.q1, p.q2);
    assert.equal(g[GEOM.MU2], p.mu2);
    const scale = 8 * U * (Math.max(1, p.condQ) +
      1 / Math.min(p.lambda, p.oneMinusLambda));
    const grad = norm(p.dR12);
    const blocks = [
      ['point', g.subarray(GEOM.POINT, GEOM.POINT + 2), p.point, 0],
      ['normal', g.subarray(GEOM.NORMAL, GEOM.NORMAL + 2), p.normal, 0],
      ['dR12', d.subarray(DERIV.R12, DERIV.R12 + 2), p.dR12, 0],
      ['dTheta1', [d[DERIV.THETA1]], [p.dTheta1], grad * norm(p.point)],
      ['dTheta2', [d[DERIV.THETA2]], [p.dTheta2],
        grad * dist(p.point, p.r12)],
      ['dQ1', d.subarray(DERIV.Q1, DERIV.Q1 + 3), p.dQ1, 0],
      ['dQ2', d.subarray(DERIV.Q2, DERIV.Q2 + 3), p.dQ2, 0],
    ];
    for (const [name, got, ref, floor] of blocks) {
      const size = Math.max(norm(ref), floor);
      assert.ok(dist(got, ref) <= scale * size,
        `${name}: ${Array.from(got)} vs ${ref}`);
    }
    assert.deepEqual(d2.contactGeometry(p.r12, p.q1, p.q2), g);
  }
});

test('d2: circles of radii 1 and 2, centres 6 apart: μ² = 4, λ = 1/3', () => {
  const { geometry: g, d } = d2.contactDerivatives([0, 6], [1, 0, 1],
    [4, 0, 4]);
  assert.equal(g[GEOM.MU2], 4);
  assert.ok(Math.abs(g[GEOM.LAMBDA] - 1 / 3) <= 2 * U);
  assert.ok(dist(g.subarray(GEOM.NORMAL, GEOM.NORMAL + 2), [0, 1]) <= 4 * U);
  assert.equal(d[DERIV.THETA1], 0);
  assert.equal(d[DERIV.THETA2], 0);
});

test('d2.ellipse and principalAxes: exact at θ = 0, and back', () => {
  assert.deepEqual(Array.from(d2.ellipse([3, 0.5], 0)), [9, 0, 0.25]);
  const { a, theta } = d2.principalAxes([0.25, 0, 9]);
  assert.deepEqual(Array.from(a), [3, 0.5]);
  assert.ok(Math.abs(theta - Math.PI / 2) <= 2 * U * Math.PI);
  // A constructor case of pw85_2d_geometry.h5 (constructors, record 5):
  // the bound of pw85_2d.h, 2u·(|Q_k| + Σ|R_im·R_jm|·a_m²) ≤ 2u·(|Q_k| +
  // a0² + a1²); semi-axes correctly rounded, θ within 2 ulps.
  const a5 = [0.00251694804667738, 0.12496376264403215];
  const q5 = [0.014509557560258637, 0.004005763268284064,
    0.0011127194413650422];
  const q = d2.ellipse(a5, -1.3013165446603447);
  const s = a5[0] ** 2 + a5[1] ** 2;
  q5.forEach((x, k) => assert.ok(Math.abs(q[k] - x) <= 2 * U * (Math.abs(x) + s)));
  const back = d2.principalAxes(q5);
  assert.deepEqual(Array.from(back.a), [0.12496376264403215,
    0.0025169480466774186]);
  assert.ok(Math.abs(back.theta - 0.2694797821345518) <= 4 * U * 0.27);
});

test('d2 batches: the same bits as the single calls', () => {
  const r12 = Float64Array.from(REFS.flatMap((p) => p.r12));
  const q1 = Float64Array.from(REFS.flatMap((p) => p.q1));
  const q2 = Float64Array.from(REFS.flatMap((p) => p.q2));
  const out = d2.contactFunctionBatch(r12, q1, q2, { threads: 2 });
  const res = d2.overlapBatch(r12, q1, q2);
  const geo = d2.contactGeometryBatch(r12, q1, q2);
  const der = d2.contactDerivativesBatch(r12, q1, q2);
  REFS.forEach((p, i) => {
    const one = d2.contactFunction(p.r12, p.q1, p.q2);
    assert.deepEqual([out[2 * i], out[2 * i + 1]], [one.mu2, one.lambda]);
    assert.equal(res[i], d2.overlap(p.r12, p.q1, p.q2));
    const { geometry, d } = d2.contactDerivatives(p.r12, p.q1, p.q2);
    assert.deepEqual(geo.subarray(6 * i, 6 * i + 6), geometry);
    assert.deepEqual(der.geometry.subarray(6 * i, 6 * i + 6), geometry);
    assert.deepEqual(der.d.subarray(10 * i, 10 * i + 10), d);
  });
  // One ellipse for every pair (stride 0).
  const many = d2.contactFunctionBatch([0, 6, 0, 3], [1, 0, 1], [4, 0, 4]);
  assert.deepEqual([many[0], many[2]], [4, 1]);
  const qs = d2.ellipseBatch([3, 0.5], [0, 0.4, -2]);
  assert.equal(qs.length, 9);
  assert.deepEqual(qs.subarray(3, 6), d2.ellipse([3, 0.5], 0.4));
  const axes = d2.principalAxesBatch(qs);
  const single = d2.principalAxes(qs.subarray(6, 9));
  assert.deepEqual(axes.a.subarray(4, 6), single.a);
  assert.equal(axes.theta[2], single.theta);
});

test('d2 errors: statuses, the failing item, wrong lengths', () => {
  const [p] = REFS;
  const code = (name) => (e) => e instanceof pw85.Pw85Error && e.code === name;
  assert.throws(() => d2.contactFunction([NaN, 0], p.q1, p.q2),
    code('PW85_EDOM'));
  assert.throws(() => d2.overlap(p.r12, [1, 2, 1], p.q2),
    (e) => code('PW85_ENOTPOSDEF')(e) &&
      e.message.startsWith('pw85_2d_overlap: '));
  assert.throws(() => d2.contactGeometry(p.r12, p.q1, [1, Infinity, 1]),
    code('PW85_EDOM'));
  assert.throws(() => d2.contactDerivatives([1e300, 0], [1e-300, 0, 1e-300],
    [1e-300, 0, 1e-300]), code('PW85_ERANGE'));
  assert.throws(() => d2.ellipse([0, 1], 0), code('PW85_EINVAL'));
  assert.throws(() => d2.ellipse([1, 1], NaN), code('PW85_EDOM'));
  assert.throws(() => d2.principalAxes([1, 2, 1]), code('PW85_ENOTPOSDEF'));
  assert.ok(Number.isNaN(d2.f(0.5, p.r12, [1, 2, 1], p.q2)));
  assert.throws(() => d2.contactFunctionBatch([1, 1, 1, 1, 1, 1],
    [1, 0, 1, 1, 2, 1, 1, 0, 1], [1, 0, 1]), (e) =>
    code('PW85_ENOTPOSDEF')(e) && e.index === 1 &&
    Array.from(e.statuses).join() === '0,3,0');
  assert.throws(() => d2.ellipseBatch([1, 1, 0, 1], [0]), (e) =>
    code('PW85_EINVAL')(e) && e.index === 1);
  // 3D inputs are wrong lengths, thrown before the library is called.
  assert.throws(() => d2.contactFunction([1, 2, 3], p.q1, p.q2), RangeError);
  assert.throws(() => d2.overlap(p.r12, [1, 0, 0, 1, 0, 1], p.q2),
    RangeError);
  assert.throws(() => d2.ellipse([1, 2], '0'), TypeError);
  assert.throws(() => d2.contactFunctionBatch([1, 2, 3, 4], [1, 0, 1, 1],
    [1, 0, 1]), RangeError);
});

test('index.d.ts declares every member of d2, and only those', () => {
  const dts = fs.readFileSync(path.join(__dirname, '..', 'index.d.ts'), 'utf8');
  const body = dts.match(/export interface D2 \{([\s\S]*?)\n\}/);
  assert.ok(body, 'interface D2 in index.d.ts');
  const declared = [...body[1].matchAll(/^ {2}(?:readonly )?(\w+)[(:]/gm)]
    .map((m) => m[1]);
  assert.deepEqual(declared.sort(), Object.keys(d2).sort());
  assert.match(dts, /^export const d2: D2;$/m);
});
