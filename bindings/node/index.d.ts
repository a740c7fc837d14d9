// SPDX-License-Identifier: BSD-3-Clause
// TypeScript declarations of the pw85 package (index.js). Vectors are 3
// numbers, symmetric forms 6 (upper triangle, row by row); batches take
// n records end to end (n = 0: empty results), or one record for every
// item; the index's insert takes n = 0 ids too (nothing done). Ellipses
// (pw85_2d.h) under d2: vectors of 2 numbers, forms [Q00, Q01, Q11].

export type Vector = ArrayLike<number>;
export type Form = ArrayLike<number>;

export const DIM: 3;
export const SYM: 6;
export const UNIT_TOL: number;
export const MAX_ID: number;
export const GEOM: Readonly<{ MU2: 0; LAMBDA: 1; POINT: 2; NORMAL: 5;
  SIZE: 8 }>;
export const DERIV: Readonly<{ R12: 0; ROT1: 3; ROT2: 6; Q1: 9; Q2: 15;
  SIZE: 21 }>;
export const status: Readonly<{
  PW85_SUCCESS: 0; PW85_EFAULT: 1; PW85_EDOM: 2; PW85_ENOTPOSDEF: 3;
  PW85_ERANGE: 4; PW85_ENOMEM: 5; PW85_ENOCONV: 6; PW85_EINVAL: 7; PW85_ECANCELLED: 8;
}>;
/** The path the library was loaded from (PW85_LIBRARY, or the soname). */
export const libraryPath: string;

/** A pw85 status other than PW85_SUCCESS, with what was wrong. */
export class Pw85Error extends Error {
  status: number;
  code: string;
  detail?: string;
  /** Batches: the first failing item, and every item's status. */
  index?: number;
  statuses?: Int32Array;
  /** Index: the id and the item of a batch insert that failed. */
  id?: number;
  item?: number;
}

export interface QuaternionOrder {
  /** true (default): (w, x, y, z); false: (x, y, z, w) (OVITO, SciPy). */
  scalarFirst?: boolean;
}
export interface Threads {
  /** 1 (default), 0 for OpenMP's default, or up to k threads. */
  threads?: number;
}

export function version(): string;
export function strerror(code: number): string;
export function spheroid(a: number, c: number, n: Vector): Float64Array;
export function f(lambda: number, r12: Vector, q1: Form, q2: Form): number;
export function contactFunction(r12: Vector, q1: Form, q2: Form):
  { mu2: number; lambda: number };
/** −1 (overlap), +1 (disjoint), 0 (tangent): a number, not a boolean. */
export function overlap(r12: Vector, q1: Form, q2: Form): -1 | 0 | 1;
export function ellipsoidRotation(a: Vector, rot: ArrayLike<number>):
  Float64Array;
export function ellipsoidQuaternion(a: Vector, p: ArrayLike<number>,
  options?: QuaternionOrder): Float64Array;
export function principalAxes(q: Form): { a: Float64Array; rot: Float64Array };
export function principalAxesQuaternion(q: Form, options?: QuaternionOrder):
  { a: Float64Array; p: Float64Array };
export function contactGeometry(r12: Vector, q1: Form, q2: Form):
  Float64Array;
export function contactDerivatives(r12: Vector, q1: Form, q2: Form):
  { geometry: Float64Array; d: Float64Array };
export function batchThreads(threads?: number, n?: number): number;
export function contactFunctionBatch(r12: ArrayLike<number>,
  q1: ArrayLike<number>, q2: ArrayLike<number>, options?: Threads):
  Float64Array;
export function overlapBatch(r12: ArrayLike<number>, q1: ArrayLike<number>,
  q2: ArrayLike<number>, options?: Threads): Int32Array;
export function contactGeometryBatch(r12: ArrayLike<number>,
  q1: ArrayLike<number>, q2: ArrayLike<number>, options?: Threads):
  Float64Array;
export function contactDerivativesBatch(r12: ArrayLike<number>,
  q1: ArrayLike<number>, q2: ArrayLike<number>, options?: Threads):
  { geometry: Float64Array; d: Float64Array };

export interface Neighbour { id: number; shift: number[]; mu2: number;
  lambda: number }
export interface OverlappingPair { i: number; j: number; shift: number[];
  result: -1 | 0 }
export interface Pair { i: number; j: number; shift: number[]; mu2: number;
  lambda: number }

/** The index of either dimension: Index (ellipsoids: centres of 3
 *  numbers, forms of 6, shifts of 3) and d2.Index (ellipses: 2, 3, 2). */
declare class IndexBase implements Iterable<number> {
  constructor(box?: ArrayLike<number> | null);
  readonly box: Float64Array | null;
  readonly size: number;
  close(): void;
  has(id: number): boolean;
  ids(): number[];
  [Symbol.iterator](): Iterator<number>;
  insert(ids: number | ArrayLike<number>, centres: ArrayLike<number>,
    q: ArrayLike<number>): void;
  update(id: number, centre: Vector, q: Form): void;
  remove(id: number): void;
  get(id: number): { centre: Float64Array; q: Float64Array };
  overlapAny(centre: Vector, q: Form, exclude?: number | null):
    { result: -1 | 0 | 1; id: number | null };
  overlapAnyBatch(centres: ArrayLike<number>, q: ArrayLike<number>,
    options?: Threads & { exclude?: ArrayLike<number> | null }):
    { results: Int32Array; ids: Float64Array };
  within(centre: Vector, q: Form, t?: number, exclude?: number | null):
    Neighbour[];
  overlappingPairs(options?: Threads): OverlappingPair[];
  pairsWithin(t: number, options?: Threads): Pair[];
  toString(): string;
}

/** A spatial index of ellipsoids (pw85_index.h); close() frees it. */
export class Index extends IndexBase {
  constructor(box?: Vector | null);
}

/** A spatial index of ellipses (pw85_2d_index.h), in an open plane or a
 *  periodic rectangle: Index for vectors of 2 numbers and forms
 *  [Q00, Q01, Q11]; close() frees it. */
declare class Index2d extends IndexBase {
  constructor(box?: ArrayLike<number> | null);
}

/** The ellipses of pw85_2d.h (pw85.d2): vectors of 2 numbers, forms of 3
 *  [Q00, Q01, Q11]; the conventions and errors of the functions above. */
export interface D2 {
  readonly DIM: 2;
  readonly SYM: 3;
  readonly GEOM: Readonly<{ MU2: 0; LAMBDA: 1; POINT: 2; NORMAL: 4;
    SIZE: 6 }>;
  readonly DERIV: Readonly<{ R12: 0; THETA1: 2; THETA2: 3; Q1: 4; Q2: 7;
    SIZE: 10 }>;
  f(lambda: number, r12: Vector, q1: Form, q2: Form): number;
  contactFunction(r12: Vector, q1: Form, q2: Form):
    { mu2: number; lambda: number };
  /** −1 (overlap), +1 (disjoint), 0 (tangent): a number, not a boolean. */
  overlap(r12: Vector, q1: Form, q2: Form): -1 | 0 | 1;
  contactGeometry(r12: Vector, q1: Form, q2: Form): Float64Array;
  contactDerivatives(r12: Vector, q1: Form, q2: Form):
    { geometry: Float64Array; d: Float64Array };
  /** Q = R(θ)·diag(a0², a1²)·R(θ)ᵀ, a[0] along (cos θ, sin θ). */
  ellipse(a: Vector, theta: number): Float64Array;
  /** Semi-axes (decreasing), and θ in (−π/2, π/2] of a[0]. */
  principalAxes(q: Form): { a: Float64Array; theta: number };
  contactFunctionBatch(r12: ArrayLike<number>, q1: ArrayLike<number>,
    q2: ArrayLike<number>, options?: Threads): Float64Array;
  overlapBatch(r12: ArrayLike<number>, q1: ArrayLike<number>,
    q2: ArrayLike<number>, options?: Threads): Int32Array;
  contactGeometryBatch(r12: ArrayLike<number>, q1: ArrayLike<number>,
    q2: ArrayLike<number>, options?: Threads): Float64Array;
  contactDerivativesBatch(r12: ArrayLike<number>, q1: ArrayLike<number>,
    q2: ArrayLike<number>, options?: Threads):
    { geometry: Float64Array; d: Float64Array };
  ellipseBatch(a: ArrayLike<number>, theta: ArrayLike<number>,
    options?: Threads): Float64Array;
  principalAxesBatch(q: ArrayLike<number>, options?: Threads):
    { a: Float64Array; theta: Float64Array };
  /** The index of ellipses (pw85_2d_index.h). */
  readonly Index: typeof Index2d;
}
export const d2: D2;
