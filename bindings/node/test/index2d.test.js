// SPDX-License-Identifier: BSD-3-Clause
'use strict';
// node --test: pw85.d2.Index, the index of ellipses (pw85_2d_index.h),
// against a brute force over every pair and periodic image computed with
// d2.overlap and d2.contactFunction (the library's 2D contact functions):
// the same results and the same (μ², λ), bit for bit, in an open plane and
// a periodic rectangle, after insert, update and remove, on 1, 2 and 8
// threads; the errors.
const test = require('node:test');
const assert = require('node:assert/strict');
const pw85 = require('..');

const { d2 } = pw85;

// A seeded generator (mulberry32): the tests are deterministic.
function generator(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// Centres on the grid of 2⁻²⁰: every r below (a difference of centres and
// images) is a double, the exact r the index decides.
const snap = (x) => Math.round(x * 2 ** 20) / 2 ** 20;

function scene(seed, n, lo, hi) {
  const rnd = generator(seed);
  const centres = [];
  const forms = [];
  for (let k = 0; k < n; ++k) {
    centres.push([snap(lo + (hi - lo) * rnd()), snap(lo + (hi - lo) * rnd())]);
    forms.push(Array.from(d2.ellipse([0.3 + 0.6 * rnd(), 0.3 + 0.6 * rnd()],
      Math.PI * rnd())));
  }
  return { rnd, centres, forms };
}

// The shifts of the images of b that may lie within μ² < t of a (the
// half-widths √Q_kk bound each ellipse along axis k).
function shifts(ca, cb, qa, qb, box, t) {
  if (box == null) return [[0, 0]];
  const ranges = [0, 1].map((k) => {
    const h = 1.01 * Math.sqrt(t) * (Math.sqrt(qa[2 * k]) +
      Math.sqrt(qb[2 * k]));
    const d = ca[k] - cb[k];
    const out = [];
    for (let s = Math.floor((d - h) / box[k]);
      s <= Math.ceil((d + h) / box[k]); ++s) out.push(s);
    return out;
  });
  return ranges[0].flatMap((s0) => ranges[1].map((s1) => [s0, s1]));
}

const imageOf = (c, s, box) => (box == null ? c
  : [c[0] + s[0] * box[0], c[1] + s[1] * box[1]]);
const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];

// Every pair a ≤ b of stored ellipses (ids ascending) and image: keys
// "i j s0 s1" → overlap result ≤ 0 (t null) or [μ², λ] with μ² < t.
function brute(ids, centres, forms, box, t) {
  const out = new Map();
  const order = ids.map((id, k) => [id, k]).sort((x, y) => x[0] - y[0]);
  for (let a = 0; a < order.length; ++a) {
    for (let b = a; b < order.length; ++b) {
      const [i, ki] = order[a];
      const [j, kj] = order[b];
      for (const s of shifts(centres[ki], centres[kj], forms[ki], forms[kj],
        box, t || 1)) {
        if (i === j && !(s[0] > 0 || (s[0] === 0 && s[1] > 0))) continue;
        const r = sub(imageOf(centres[kj], s, box), centres[ki]);
        const key = `${i} ${j} ${s.join(' ')}`;
        if (t == null) {
          const res = d2.overlap(r, forms[ki], forms[kj]);
          if (res <= 0) out.set(key, res);
        } else {
          const { mu2, lambda } = d2.contactFunction(r, forms[ki], forms[kj]);
          if (mu2 < t) out.set(key, [mu2, lambda]);
        }
      }
    }
  }
  return out;
}

function checkAll(index, ids, centres, forms, box) {
  const pairs = brute(ids, centres, forms, box, null);
  const near = brute(ids, centres, forms, box, 1.7);
  assert.ok(pairs.size > 5, 'the configuration has overlaps');
  for (const threads of [1, 2, 8]) {
    const got = index.overlappingPairs({ threads });
    assert.deepEqual(new Map(got.map((p) => [`${p.i} ${p.j} ` +
      p.shift.join(' '), p.result])), pairs);
    const keys = got.map((p) => [p.i, p.j, ...p.shift]);
    assert.deepEqual(keys, [...keys].sort((x, y) => x[0] - y[0] ||
      x[1] - y[1] || x[2] - y[2] || x[3] - y[3]));
    const within = index.pairsWithin(1.7, { threads });
    assert.deepEqual(new Map(within.map((p) => [`${p.i} ${p.j} ` +
      p.shift.join(' '), [p.mu2, p.lambda]])), near);
  }
  const rnd = generator(41);
  for (let k = 0; k < 8; ++k) {
    const cc = [snap(8 * rnd()), snap(7 * rnd())];
    const qq = Array.from(d2.ellipse([0.2 + 0.5 * rnd(), 0.2 + 0.5 * rnd()],
      Math.PI * rnd()));
    const ref = new Map();
    let best = 1;
    ids.forEach((id, m) => {
      for (const s of shifts(cc, centres[m], qq, forms[m], box, 1.7)) {
        const r = sub(imageOf(centres[m], s, box), cc);
        const { mu2, lambda } = d2.contactFunction(r, qq, forms[m]);
        if (mu2 < 1.7) ref.set(`${id} ${s.join(' ')}`, [mu2, lambda]);
        best = Math.min(best, d2.overlap(r, qq, forms[m]));
      }
    });
    const got = index.within(cc, qq, 1.7);
    assert.deepEqual(new Map(got.map((w) => [`${w.id} ${w.shift.join(' ')}`,
      [w.mu2, w.lambda]])), ref);
    const { result, id } = index.overlapAny(cc, qq);
    assert.equal(result, best);
    assert.equal(id === null, best === 1);
  }
}

for (const box of [null, [8, 7]]) {
  test(`d2.Index ${box ? 'periodic' : 'open'}: every query against the ` +
    'brute force, after insert, update and remove', () => {
    const n = 90;
    const { rnd, centres, forms } = scene(29, n, -1, 9);
    const ids = Array.from({ length: n }, (_, k) => 3 * k);
    const index = new d2.Index(box);
    try {
      index.insert(ids, centres.flat(), forms.flat());
      assert.equal(index.size, n);
      assert.deepEqual(index.ids(), ids);
      checkAll(index, ids, centres, forms, box);
      for (let k = 0; k < n; k += 4) {
        centres[k] = [snap(-1 + 10 * rnd()), snap(-1 + 10 * rnd())];
        forms[k] = Array.from(d2.ellipse([0.3 + 0.6 * rnd(),
          0.3 + 0.6 * rnd()], Math.PI * rnd()));
        index.update(ids[k], centres[k], forms[k]);
      }
      const keep = ids.map((_, k) => k).filter((k) => k % 5 !== 1);
      ids.forEach((id, k) => { if (k % 5 === 1) index.remove(id); });
      const kept = (xs) => keep.map((k) => xs[k]);
      checkAll(index, kept(ids), kept(centres), kept(forms), box);
      const { centre, q } = index.get(ids[0]);
      assert.deepEqual(Array.from(centre), centres[0]);
      assert.deepEqual(Array.from(q), forms[0]);
    } finally {
      index.close();
    }
  });
}

test('d2.Index overlapAnyBatch: overlapAny for each candidate, any threads',
  () => {
    const { rnd, centres, forms } = scene(3, 80, 0, 10);
    const index = new d2.Index([10, 10]);
    index.insert(centres.map((_, k) => k), centres.flat(), forms.flat());
    const m = 700; // above 512: threads are started
    const cc = [];
    const qq = [];
    for (let k = 0; k < m; ++k) {
      cc.push(snap(10 * rnd()), snap(10 * rnd()));
      qq.push(...d2.ellipse([0.2 + 0.3 * rnd(), 0.2 + 0.3 * rnd()],
        Math.PI * rnd()));
    }
    const exclude = Array.from({ length: m }, (_, k) => (k % 4 ? -1 : k % 80));
    const ref = exclude.map((ex, k) => index.overlapAny(
      cc.slice(2 * k, 2 * k + 2), qq.slice(3 * k, 3 * k + 3),
      ex === -1 ? null : ex));
    const hits = ref.filter((r) => r.result < 0).length;
    assert.ok(hits > m / 10 && hits < m - m / 10, `${hits} overlaps`);
    for (const threads of [1, 2, 8, 0]) {
      const { results, ids } = index.overlapAnyBatch(cc, qq,
        { exclude, threads });
      assert.deepEqual(Array.from(results), ref.map((r) => r.result));
      assert.deepEqual(Array.from(ids), ref.map((r) => (r.id === null ? -1
        : r.id)));
    }
    index.close();
  });

test('d2.Index errors: statuses, causes, sizes', () => {
  const throwsWith = (fn, code, text) => assert.throws(fn, (e) => {
    assert.ok(e instanceof pw85.Pw85Error, String(e));
    assert.equal(e.code, code);
    if (text) assert.ok(e.message.includes(text), e.message);
    return true;
  });
  const circle = [1, 0, 1];
  throwsWith(() => new d2.Index([1, -2]), 'PW85_EINVAL',
    'rectangle side L_1 = -2 is not > 0');
  throwsWith(() => new d2.Index([Infinity, 2]), 'PW85_EDOM', 'not finite');
  assert.throws(() => new d2.Index([1, 2, 3]), RangeError);
  const index = new d2.Index([4, 4]);
  index.insert(2, [0, 0], circle);
  throwsWith(() => index.insert([4, 2], [1, 1, 2, 2], circle), 'PW85_EINVAL',
    'ellipse 2 (item 1 of 2): id 2 is already stored');
  assert.equal(index.size, 1);
  throwsWith(() => index.insert(5, [1, 1], [1, 1, 1]), 'PW85_ENOTPOSDEF',
    'ellipse 5: q = [1, 1, 1] is not positive definite');
  throwsWith(() => index.insert(5, [1, 1], [4, 0, 1]), 'PW85_EINVAL',
    'an ellipse must be narrower than the rectangle');
  throwsWith(() => index.insert(5, [1, 1], [1, 0, 4]), 'PW85_EINVAL',
    '2·√Q_11·(1 + 2⁻²⁰) = 4.000003814697266 ≥ L_1 = 4');
  throwsWith(() => index.insert(5, [NaN, 1], circle), 'PW85_EDOM');
  assert.throws(() => index.insert(5, [1, 1, 1], circle), RangeError);
  assert.throws(() => index.update(2, [1, 1], [1, 0, 0, 1, 0, 1]),
    RangeError);
  assert.throws(() => index.insert(1.5, [1, 1], circle), TypeError);
  throwsWith(() => index.update(9, [0, 0], circle), 'PW85_EINVAL',
    'not stored');
  throwsWith(() => index.remove(9), 'PW85_EINVAL');
  throwsWith(() => index.get(9), 'PW85_EINVAL');
  throwsWith(() => index.within([0, 0], circle, 0), 'PW85_EINVAL');
  throwsWith(() => index.overlapAny([0, 0], [1, 2, 1]), 'PW85_ENOTPOSDEF');
  throwsWith(() => index.pairsWithin(1, { threads: 0 }), 'PW85_EINVAL');
  assert.throws(() => index.overlapAnyBatch([0, 0, 0, 0, 0, 0],
    [...circle, 1, 2, 1, ...circle]), (e) => {
    assert.equal(e.code, 'PW85_ENOTPOSDEF');
    assert.equal(e.index, 1);
    assert.deepEqual(Array.from(e.statuses),
      [0, pw85.status.PW85_ENOTPOSDEF, 0]);
    return true;
  });
  assert.equal(String(index),
    'pw85.d2.Index: periodic rectangle (4, 4), 1 ellipse');
  index.close();
  assert.equal(String(index), 'pw85.d2.Index (closed)');
  assert.throws(() => index.size, /closed/);
});
