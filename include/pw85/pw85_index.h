/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85_index.h
 * @brief A spatial index of ellipsoids, in an open domain or a periodic
 *        box: overlap and near-contact queries certified as
 *        pw85_overlap() and pw85_contact_function() decide them.
 *
 * Conventions of pw85.h (vectors `double[3]`, symmetric forms `double[6]`,
 * an ellipsoid {m : (m − c)ᵀ Q⁻¹ (m − c) ≤ 1}); lengths in the caller's
 * unit, Q in that unit squared. Arrays of n vectors or forms are
 * contiguous, row by row: `centres[3·i + k]`, `q[6·i + k]`.
 *
 * Ellipsoids are named by ids chosen by the caller, integers from 0 to
 * PW85_INDEX_MAX_ID; the index keeps a table indexed by id, so its memory
 * grows with the largest id in use (12 bytes per id, besides 128 bytes per
 * stored ellipsoid): use small ids, such as the positions of the
 * ellipsoids in the caller's arrays.
 *
 * Domain. Open: centres with |c_k| ≤ 2¹⁰²¹ (about 2.2e307). Periodic: an
 * orthorhombic box of sides L = (L0, L1, L2), each at most 2⁹⁹² (about
 * 4.2e298); an ellipsoid stands for all its images c + n∘L, n ∈ ℤ³ (n∘L =
 * (n0·L0, n1·L1, n2·L2)); centres need not be wrapped into the box, but
 * |c_k| ≤ 2²⁹·L_k. (These bounds keep every difference of centres and every
 * image vector within the range of a double.) Each stored ellipsoid must be
 * narrower than the box along each axis, 2·√Q_kk·(1 + 2⁻²⁰) < L_k, so that
 * it cannot meet its own images; the queries consider every image of every
 * stored ellipsoid (not only the nearest), so the box may be as small as
 * that rule allows, and a pair may meet through several images.
 *
 * Images. A result names a stored ellipsoid j by its id and an image
 * shift n (three ints; 0 in an open domain); the vector from the query's
 * centre c to that image is r = (c_j + n∘L) − c, formed exactly (not
 * rounded to doubles: an error-free sum, a double-double). The queries
 * decide and report for the configuration as stored: μ² is correctly
 * rounded for that exact r, and overlaps are decided by its sign of
 * μ² − 1 (4-ulp band as pw85_overlap()). Where r is a double (as when the
 * centres and sides lie on a common grid of 2^−k, far enough from the
 * range's ends), these are the results of pw85_overlap() and
 * pw85_contact_function() on r, bit for bit. (Where the exact r does not
 * fit two doubles, centres with bits far below ulp(L), it is carried to
 * 2⁻¹⁰⁵ relative.) Periodic images of the query ellipsoid itself are not
 * considered by the queries on a candidate.
 *
 * Certification. The broad phase (a grid over the axis-aligned bounding
 * boxes of the ellipsoids, whose half-widths are √Q_kk exactly, then the
 * projections of the two ellipsoids on the line of their centres) only
 * discards pairs with μ² > t·(1 + 2⁻²⁰), far outside the rounding of any
 * decision, at every length scale; every other pair is decided by the
 * logic of pw85_overlap() or by pw85_contact_function() on the exact image
 * vector. The answers are therefore those of a brute force loop over every
 * pair and every image, deciding each exact configuration as these
 * functions decide theirs.
 *
 * Memory and threads. The index allocates from the heap (that is its
 * job), and every allocation that fails is reported as PW85_ENOMEM, never
 * by an abort; a failed call leaves the index as it was. In a periodic box
 * it also keeps, for each octave of ellipsoid sizes in use, a table of 4
 * bytes per cell of a grid of the box (cells 2 to 4 times as wide as the
 * largest √Q_kk of those ellipsoids), at most 16 MiB each (a larger grid
 * uses a hash table instead). The all-pairs queries allocate, for the time
 * of the call, about 150 bytes per ellipsoid (8 of them per id below the
 * largest in use, stored or not), and per pair reported 48 (overlapping
 * pairs) or 80 (pairs within). Blocks of 1 MiB and more are rounded up to
 * whole 2 MiB pages and marked for transparent huge pages on Linux, a
 * hint that changes nothing but speed.
 * Calls that modify an index (insert, update, remove, destroy) need
 * exclusive access to it; queries only read it and may run concurrently
 * with each other from several threads. The all-pairs queries,
 * pw85_index_energy(), pw85_index_overlap_any_batch() and
 * pw85_index_insert_many_threads() start up to `threads` OpenMP threads
 * when libpw85 was built with OpenMP (see pw85_index_openmp()), and run
 * serially otherwise: no more than their work is worth (the all-pairs
 * queries: one per 256 ellipsoids; overlap_any_batch: one per 256
 * candidates; insert_many_threads: one per 4096 items), and never more
 * than 1024, a larger count running as 1024 (libgomp takes the start
 * data of its threads from the caller's stack); their output (the index
 * they leave, for the last) is the same, bit for bit, for any number of
 * threads. No other function starts a thread.
 *
 * PW85_EINVAL, the status of a finite argument outside its domain, has
 * these causes, each documented with its function: a box side not > 0 or
 * above 2⁹⁹² (create); an id above PW85_INDEX_MAX_ID, or in use, or
 * repeated in one call (insert, insert_many, insert_many_threads); an id
 * not stored (update, remove, get); a centre with |c_k| > 2¹⁰²¹ in an open
 * domain, or with |c_k| > 2²⁹·L_k in a periodic box, and there an ellipsoid
 * not narrower than the box, 2·√Q_kk·(1 + 2⁻²⁰) ≥ L_k (insert, insert_many,
 * update; the centre rules also for the queries on a candidate); t ≤ 0
 * (within, pairs_within); threads < 1 (the all-pairs queries) or < 0, or a
 * stride between 1 and its record's size − 1 (overlap_any_batch). The
 * status alone does not say which: a binding that reports errors to
 * people checks these rules to name the one broken (pypw85 and the
 * Node.js package do).
 *
 * Outputs that may not fit take a capacity (a number of results) and
 * return the number of results in *count, as snprintf does: the first
 * min(count, capacity) results are written, in the documented order;
 * output arrays may be NULL when capacity is 0 (to ask for the count).
 *
 * @since 2.2.0
 */
#ifndef PW85_INDEX_H
#define PW85_INDEX_H

#include <stddef.h>

#include "pw85.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The largest id of an ellipsoid: 2³² − 2.
 *  @since 2.2.0 */
#define PW85_INDEX_MAX_ID ((size_t)0xFFFFFFFEu)
/** No id: the `exclude` argument of the queries on a candidate when no
 *  stored ellipsoid is to be skipped, and the id returned when none was
 *  found.
 *  @since 2.2.0 */
#define PW85_INDEX_NO_ID ((size_t)-1)

/** An index of ellipsoids (opaque).
 *  @since 2.2.0 */
typedef struct pw85_index pw85_index;

/**
 * @brief Create an empty index, for an open domain or a periodic box.
 *
 * @param[in] box NULL for an open domain; else the sides L0, L1, L2 of the
 *            periodic box (lengths, each > 0 and at most 2⁹⁹²).
 * @param[out] index the new index, to be freed with pw85_index_destroy().
 * @return PW85_SUCCESS; PW85_EFAULT if index is NULL; PW85_EDOM if a side
 *         is not finite; PW85_EINVAL if a side is not > 0 or is above
 *         2⁹⁹²; PW85_ENOMEM.
 *         *index is written on success only.
 * @since 2.2.0
 */
PW85_API int pw85_index_create(double const box[PW85_DIM],
                               pw85_index **index) PW85_NOEXCEPT;

/**
 * @brief Free an index and everything it holds. NULL is accepted (and
 *        does nothing).
 * @param[in] index the index.
 * @since 2.2.0
 */
PW85_API void pw85_index_destroy(pw85_index *index) PW85_NOEXCEPT;

/**
 * @brief Does this copy of libpw85 run the all-pairs queries on several
 *        threads?
 * @return 1 if it was built with OpenMP, 0 if `threads` > 1 runs serially.
 * @since 2.2.0
 */
PW85_API int pw85_index_openmp(void) PW85_NOEXCEPT;

/**
 * @brief The number of ellipsoids in an index.
 * @param[in] index the index.
 * @param[out] count the number of ellipsoids stored.
 * @return PW85_SUCCESS; PW85_EFAULT if a pointer is NULL.
 * @since 2.2.0
 */
PW85_API int pw85_index_count(pw85_index const *index,
                              size_t *count) PW85_NOEXCEPT;

/**
 * @brief Insert an ellipsoid (O(1) amortised).
 *
 * @param[in,out] index the index.
 * @param[in] id its id, not in use, at most PW85_INDEX_MAX_ID.
 * @param[in] centre its centre c.
 * @param[in] q its quadratic form Q.
 * @return PW85_SUCCESS; PW85_EFAULT if a pointer is NULL; PW85_EDOM if an
 *         entry of centre or q is not finite; PW85_ENOTPOSDEF if q is not
 *         positive definite (the rule of pw85.h); PW85_EINVAL if id is in
 *         use or above PW85_INDEX_MAX_ID, or if, for some k,
 *         |c_k| > 2¹⁰²¹ in an open domain, or in a periodic box
 *         2·√Q_kk·(1 + 2⁻²⁰) ≥ L_k or |c_k| > 2²⁹·L_k; PW85_ENOMEM. The
 *         index is unchanged on error.
 * @since 2.2.0
 */
PW85_API int pw85_index_insert(pw85_index *index, size_t id,
                               double const centre[PW85_DIM],
                               double const q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief Insert n ellipsoids, all or none.
 *
 * As n calls of pw85_index_insert(), in order, except that on error none
 * is inserted.
 * @param[in,out] index the index.
 * @param[in] n the number of ellipsoids (0 does nothing).
 * @param[in] ids their ids (n values, distinct, not in use).
 * @param[in] centres their centres (3·n doubles).
 * @param[in] q their quadratic forms (6·n doubles).
 * @return the statuses of pw85_index_insert() (the first error met, in the
 *         order of the arrays; for n ≥ 1024, PW85_ENOMEM only when every
 *         ellipsoid is valid); the index is unchanged on error.
 * @since 2.2.0
 */
PW85_API int pw85_index_insert_many(pw85_index *index, size_t n,
                                    size_t const *ids, double const *centres,
                                    double const *q) PW85_NOEXCEPT;

/**
 * @brief pw85_index_insert_many() on `threads` threads.
 *
 * The same index, status and all-or-none rule as pw85_index_insert_many()
 * (and as n calls of pw85_index_insert(), in order), whatever the number
 * of threads: the same stored order, so that every later query, and the
 * id returned by pw85_index_overlap_any(), are those of a serial
 * insertion, bit for bit. At most n/4096 + 1 threads are started (none
 * for threads = 1). For n ≥ 1024 the ellipsoids are placed in passes over
 * the whole call (pw85_index_insert_many() takes the same path, on the
 * calling thread), which allocate, for the time of the call, 20 bytes per
 * ellipsoid and hash tables of 48 to 96 bytes per cell that the
 * ellipsoids of a level may occupy (as many as they are, or, in a
 * periodic box, as the cells of the level's grid times the threads if
 * fewer: a table per thread). The cells
 * that the call creates keep their ellipsoids in one block (marked for
 * transparent huge pages when large), freed with the index; a cell that
 * grows beyond what the call put in it moves to memory of its own, and
 * its part of the block stays allocated, unused, until the index is
 * destroyed.
 * @param[in,out] index the index.
 * @param[in] n the number of ellipsoids (0 does nothing).
 * @param[in] ids their ids (n values, distinct, not in use).
 * @param[in] centres their centres (3·n doubles).
 * @param[in] q their quadratic forms (6·n doubles).
 * @param[in] threads the number of threads (≥ 1; see the file
 *            description).
 * @return the statuses of pw85_index_insert_many(); PW85_EINVAL also if
 *         threads < 1. PW85_ENOMEM only when every ellipsoid is valid.
 *         The index is unchanged on error (but for the spare capacity of
 *         its tables).
 * @since 2.3.0
 */
PW85_API int pw85_index_insert_many_threads(pw85_index *index, size_t n,
                                            size_t const *ids,
                                            double const *centres,
                                            double const *q,
                                            int threads) PW85_NOEXCEPT;

/**
 * @brief Move or reshape a stored ellipsoid (O(1) amortised).
 * @param[in,out] index the index.
 * @param[in] id the id of a stored ellipsoid.
 * @param[in] centre its new centre.
 * @param[in] q its new quadratic form.
 * @return the statuses of pw85_index_insert(); PW85_EINVAL if id is not
 *         stored. The index is unchanged on error.
 * @since 2.2.0
 */
PW85_API int pw85_index_update(pw85_index *index, size_t id,
                               double const centre[PW85_DIM],
                               double const q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief Remove a stored ellipsoid (O(1)); its id becomes free.
 * @param[in,out] index the index.
 * @param[in] id the id of a stored ellipsoid.
 * @return PW85_SUCCESS; PW85_EFAULT if index is NULL; PW85_EINVAL if id is
 *         not stored (the index is then unchanged).
 * @since 2.2.0
 */
PW85_API int pw85_index_remove(pw85_index *index, size_t id) PW85_NOEXCEPT;

/**
 * @brief The centre and quadratic form of a stored ellipsoid, as given.
 * @param[in] index the index.
 * @param[in] id the id of a stored ellipsoid.
 * @param[out] centre its centre (as inserted: not wrapped into the box).
 * @param[out] q its quadratic form.
 * @return PW85_SUCCESS; PW85_EFAULT if a pointer is NULL; PW85_EINVAL if
 *         id is not stored. The outputs are written on success only.
 * @since 2.2.0
 */
PW85_API int pw85_index_get(pw85_index const *index, size_t id,
                            double centre[PW85_DIM],
                            double q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief Does a candidate ellipsoid overlap a stored one? Stops at the
 *        first overlap found: the inner loop of random sequential
 *        addition and of hard-particle Monte Carlo.
 *
 * Every image of every stored ellipsoid but `exclude` is decided as
 * pw85_overlap(r, q, q_j) decides it, r the exact image vector of the file
 * description ("Images").
 * @param[in] index the index.
 * @param[in] centre the candidate's centre c (|c_k| ≤ 2¹⁰²¹ in an open
 *            domain, |c_k| ≤ 2²⁹·L_k in a periodic box).
 * @param[in] q the candidate's quadratic form Q.
 * @param[in] exclude the id of a stored ellipsoid to skip (the one the
 *            candidate would replace, in a Monte Carlo move), or
 *            PW85_INDEX_NO_ID; an id not stored skips nothing.
 * @param[out] result −1 if some stored ellipsoid overlaps the candidate
 *             (pw85_overlap() gives −1), else 0 if some is tangent to it
 *             (gives 0), else +1; the least result of pw85_overlap() over
 *             all pairs.
 * @param[out] id the id of an ellipsoid with that result (which one, when
 *             several, depends on the history of the index), or
 *             PW85_INDEX_NO_ID for +1.
 * @return PW85_SUCCESS; PW85_EFAULT if a pointer is NULL; PW85_EDOM if an
 *         entry of centre or q is not finite; PW85_ENOTPOSDEF if q is not
 *         positive definite; PW85_EINVAL if |c_k| > 2¹⁰²¹ in an open
 *         domain or |c_k| > 2²⁹·L_k in a periodic box; PW85_ERANGE if a
 *         pair's forms span more than the range of a double (as
 *         pw85_overlap()), or if, in a periodic box, the
 *         images of a stored ellipsoid within reach of the candidate span
 *         more than 2²⁰ boxes along an axis (a candidate whose half-length
 *         is about 2¹⁹ sides: the queries enumerate every image);
 *         PW85_ENOMEM (not expected, as pw85_overlap()). The outputs are
 *         written on success only.
 * @since 2.2.0
 */
PW85_API int pw85_index_overlap_any(pw85_index const *index,
                                    double const centre[PW85_DIM],
                                    double const q[PW85_SYM], size_t exclude,
                                    int *result, size_t *id) PW85_NOEXCEPT;

/**
 * @brief pw85_index_overlap_any() for n candidates, each against the
 *        stored ellipsoids (not against each other), on threads.
 *
 * Candidate i is decided alone, exactly as pw85_index_overlap_any()
 * decides it: the same result, id and status, whatever the thread count.
 * The batch conventions of pw85.h ("Batches") apply: strides, `status`,
 * the return value, `threads` (1, 0 for OpenMP's default, or up to k; at
 * most n/256 threads, none started for n < 512). A candidate is about a
 * microsecond: random sequential addition and Monte Carlo can draw
 * candidates in batches, decide them here on every core, then accept them
 * in their order, re-deciding with pw85_index_overlap_any() a candidate
 * that follows an insertion in the same batch (the result of a serial
 * loop, on threads; tests/bench/bench-index.cpp does it).
 * @param[in] index the index (read only, as by every query).
 * @param[in] n the number of candidates (0 is valid).
 * @param[in] centres the candidates' centres.
 * @param[in] centre_stride doubles from one centre to the next: PW85_DIM
 *            when contiguous, 0 for the same centre for every candidate.
 * @param[in] q the candidates' quadratic forms.
 * @param[in] q_stride PW85_SYM when contiguous, 0 for one form.
 * @param[in] exclude NULL (PW85_INDEX_NO_ID for every candidate), or n ids
 *            (`exclude[i]` for candidate i, as pw85_index_overlap_any()).
 * @param[out] results n ints: the result of each candidate (−1, 0, +1).
 * @param[out] ids n ids: the id found for each candidate, or
 *             PW85_INDEX_NO_ID.
 * @param[out] status NULL, or n ints: the status of each candidate.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return PW85_SUCCESS, or the status of the first failing candidate
 *         (those of pw85_index_overlap_any(), whose outputs are left
 *         untouched); for the call itself (nothing computed): PW85_EFAULT
 *         if n > 0 and index, centres, q, results or ids is NULL;
 *         PW85_EINVAL if a stride is between 1 and its record's size − 1,
 *         or threads < 0.
 * @since 2.2.0
 */
PW85_API int pw85_index_overlap_any_batch(
    pw85_index const *index, size_t n, double const *centres,
    size_t centre_stride, double const *q, size_t q_stride,
    size_t const *exclude, int *results, size_t *ids, int *status,
    int threads) PW85_NOEXCEPT;

/**
 * @brief Every stored ellipsoid, and image, within μ² < t of a candidate.
 *
 * μ² and λ of pw85_contact_function(r, q, q_j), r the exact image vector
 * of the file description ("Images"): λ is the weight of the stored
 * ellipsoid's form. The
 * results are sorted by id, then by image shift (lexicographically).
 * @param[in] index the index.
 * @param[in] centre the candidate's centre (as pw85_index_overlap_any()).
 * @param[in] q the candidate's quadratic form.
 * @param[in] t the threshold (dimensionless, > 0 and finite; 1 for
 *            overlaps, above 1 for near neighbours).
 * @param[in] exclude as pw85_index_overlap_any().
 * @param[in] capacity the number of results the arrays below can hold.
 * @param[out] ids the ids (capacity values).
 * @param[out] shifts the image shifts (3·capacity ints).
 * @param[out] mu2_lambda μ² and λ (2·capacity doubles).
 * @param[out] count the number of results (which may exceed capacity).
 * @return the statuses of pw85_index_overlap_any(); PW85_EFAULT also if
 *         an array is NULL while capacity > 0; PW85_EDOM if t is not
 *         finite; PW85_EINVAL if t ≤ 0; PW85_ERANGE if the reach of the
 *         query, √t times the bounding boxes, spans more than 2²⁰ boxes
 *         along an axis. Nothing is written on error.
 * @since 2.2.0
 */
PW85_API int pw85_index_within(pw85_index const *index,
                               double const centre[PW85_DIM],
                               double const q[PW85_SYM], double t,
                               size_t exclude, size_t capacity, size_t *ids,
                               int *shifts, double *mu2_lambda,
                               size_t *count) PW85_NOEXCEPT;

/**
 * @brief Every overlapping (or tangent) pair of stored ellipsoids, each
 *        once, with its image shift.
 *
 * A pair is (i, j, n), i < j, decided by pw85_overlap(r, q_i, q_j) with
 * r = (c_j + n∘L) − c_i, exact ("Images"); it is reported when the result is −1 or 0 (the
 * side rule of a periodic box keeps an ellipsoid from meeting its own
 * images). Sorted by i, then j, then n; the same output, bit for bit, for
 * any number of threads.
 * @param[in] index the index.
 * @param[in] threads the number of threads (≥ 1; see the file description).
 * @param[in] capacity the number of pairs the arrays below can hold.
 * @param[out] ids i and j of each pair (2·capacity values).
 * @param[out] shifts n (3·capacity ints).
 * @param[out] results −1 (overlap) or 0 (tangent to 4 ulps), as
 *             pw85_overlap() (capacity ints).
 * @param[out] count the number of pairs (which may exceed capacity).
 * @return PW85_SUCCESS; PW85_EFAULT if index or count is NULL, or an array
 *         is NULL while capacity > 0; PW85_EINVAL if threads < 1;
 *         PW85_ERANGE as pw85_overlap() on some pair; PW85_ENOMEM.
 *         Nothing is written on error.
 * @since 2.2.0
 */
PW85_API int pw85_index_overlapping_pairs(pw85_index const *index,
                                          int threads, size_t capacity,
                                          size_t *ids, int *shifts,
                                          int *results,
                                          size_t *count) PW85_NOEXCEPT;

/**
 * @brief Every pair of stored ellipsoids, and image, with μ² < t, each
 *        once.
 *
 * A pair (i, j, n) as in pw85_index_overlapping_pairs(), with μ² and λ of
 * pw85_contact_function(r, q_i, q_j). With t > 1 an ellipsoid may be
 * within reach of its own image: such a pair is (i, i, n), reported once,
 * with n lexicographically positive. Sorted by i, then j, then n; the same
 * output, bit for bit, for any number of threads.
 * @param[in] index the index.
 * @param[in] t the threshold (> 0 and finite).
 * @param[in] threads the number of threads (≥ 1).
 * @param[in] capacity the number of pairs the arrays below can hold.
 * @param[out] ids i and j of each pair (2·capacity values).
 * @param[out] shifts n (3·capacity ints).
 * @param[out] mu2_lambda μ² and λ (2·capacity doubles).
 * @param[out] count the number of pairs (which may exceed capacity).
 * @return the statuses of pw85_index_overlapping_pairs(); PW85_EDOM if t
 *         is not finite; PW85_EINVAL if t ≤ 0; PW85_ERANGE also as
 *         pw85_index_within(). Nothing is written on error.
 * @since 2.2.0
 */
PW85_API int pw85_index_pairs_within(pw85_index const *index, double t,
                                     int threads, size_t capacity,
                                     size_t *ids, int *shifts,
                                     double *mu2_lambda,
                                     size_t *count) PW85_NOEXCEPT;

/** @name Energy, forces and torques of an assembly
 *  @{ */
/** The overlap energy U = ε·(1 − μ)² for μ < 1, 0 for μ ≥ 1 (ε > 0, the
 *  `param` of pw85_index_energy()): its minimisation removes overlaps.
 *  @since 2.4.0 */
#define PW85_ENERGY_OVERLAP 0
/** A caller's pair energy U(μ²), through a pw85_pair_energy function, for
 *  the pairs with μ² < t (t > 0, the `param`). @since 2.4.0 */
#define PW85_ENERGY_USER 1
/** @} */

/**
 * @brief A caller's pair energy: U and dU/dμ² at μ².
 * @param[in] mu2 the pair's μ² (0 ≤ μ² < t).
 * @param[in] data the `data` pointer given to pw85_index_energy().
 * @param[out] out out[0] = U(μ²), out[1] = dU/dμ² (both finite).
 * @return 0 to go on; non-zero stops the call (PW85_ECANCELLED).
 * @since 2.4.0
 */
typedef int (*pw85_pair_energy)(double mu2, void *data, double out[2]);

/**
 * @brief The energy summed over every pair of stored ellipsoids, and the
 *        force and torque on every ellipsoid.
 *
 * The pairs are those of pw85_index_pairs_within() with t = `param`
 * (PW85_ENERGY_USER), or those of pw85_index_overlapping_pairs()
 * (PW85_ENERGY_OVERLAP: the other pairs have U = 0), each pair and image
 * (i, j, n) once, with μ² and its maximiser λ from the search of
 * pw85_contact_function() on the exact image vector (the μ² and λ that
 * pw85_index_pairs_within() reports, bit for bit). For
 * each, with r = (c_j + n∘L) − c_i rounded to doubles (exact where the
 * centres and sides lie on a common grid, see "Images"), the derivatives
 * of μ² that pw85_contact_derivatives() documents, computed from λ by the
 * envelope theorem (s = Q(λ)⁻¹·r solved in double, no second search;
 * where Q(λ) does not factorise in double or a derivative is not finite,
 * that pair's derivatives as pw85_contact_derivatives() computes them):
 * g = ∂μ²/∂r and ∂μ²/∂ω_i, ∂μ²/∂ω_j. With U′ = dU/dμ²: the force on j is
 * −U′·g and on i +U′·g; the torque on i is −U′·∂μ²/∂ω_i and on j
 * −U′·∂μ²/∂ω_j (about each ellipsoid's own centre; docs/packing.rst).
 * So the forces sum to zero, and the torques plus the moments of the
 * forces applied at the images' centres, c_j + n∘L, sum to zero (to
 * rounding). Overlap energy: U′ = −ε·(1 − μ)/μ; a pair with coincident
 * centres (r = 0, μ = 0) adds U = ε and no force, and so does a pair whose
 * μ² underflows to 0 (|r| below about 1e-162 of the sizes: its force is
 * then lost). U and U′ are taken at
 * the μ² of the query; for PW85_ENERGY_USER they come from fn,
 * called in the calling thread only, once per pair, in the order (i, j,
 * n); the derivatives of μ² are computed on threads.
 *
 * Units: energy in the unit of U (ε), forces in that unit per length,
 * torques in that unit (per radian). The sums are made in the order
 * (i, j, n): the outputs are the same, bit for bit, for any number of
 * threads. Cost: one all-pairs query, one search per pair reported (of
 * the query itself for PW85_ENERGY_USER, after it for the overlap
 * energy, whose query decides most pairs by cheaper filters), then a 3×3
 * solve per pair, on `threads` threads. Memory, besides the outputs:
 * the query's pairs (40 bytes each), a copy of the stored ellipsoids
 * (72 bytes per id below the id table's size) and two arrays of 3·n
 * doubles. Accuracy, measured: forces and torques agree with central
 * differences of the energy to 1.2e-9 relative on triaxial ellipsoids of
 * semi-axes s·(1, 0.6, 0.3) (tests/test-energy.c). s is solved in
 * double, so each pair's derivatives carry an error of order
 * u·cond(Q(λ)) (u = 2⁻⁵³): 2.9e-8 for a force and 9.4e-8 for a torque
 * on a pair of aspect ratio 3.4e4, cond(Q(λ)) = 5e9 (an adversarial
 * review); pw85_contact_derivatives() is accurate there.
 *
 * @param[in] index the index.
 * @param[in] kind PW85_ENERGY_OVERLAP or PW85_ENERGY_USER.
 * @param[in] param ε > 0 (overlap) or t > 0 (user); finite.
 * @param[in] fn the pair energy for PW85_ENERGY_USER (else ignored, may be
 *            NULL).
 * @param[in] data passed to fn.
 * @param[in] threads the number of threads (≥ 1).
 * @param[in] n the rows of forces and torques: above every stored id.
 * @param[out] energy the total energy.
 * @param[out] forces NULL, or 3·n doubles: the force on the ellipsoid of
 *             id k at forces[3k..3k+2] (0 for ids in no pair, or not
 *             stored).
 * @param[out] torques NULL, or 3·n doubles, as forces.
 * @return PW85_SUCCESS; PW85_EFAULT if index or energy is NULL; PW85_EDOM
 *         if param is not finite, or fn returned a value not finite;
 *         PW85_EINVAL if kind is unknown, param ≤ 0, fn is NULL for
 *         PW85_ENERGY_USER, threads < 1, or n is not above every stored id;
 *         PW85_ECANCELLED if fn returned non-zero; PW85_ERANGE as
 *         pw85_index_pairs_within() or pw85_contact_derivatives() on a
 *         pair, or if the energy, or an entry of forces or torques (those
 *         asked for), is beyond the range of a double, or, with forces
 *         or torques asked for, if a pair's U′ is (ε·(1 − μ)/μ of the
 *         overlap energy with ε near the top of a double's range, even
 *         where the forces themselves would fit); PW85_ENOMEM (also
 *         when forces or torques is given and the size in bytes of 3·n
 *         doubles would not fit a size_t). Nothing is written on error.
 * @since 2.4.0
 */
PW85_API int pw85_index_energy(pw85_index const *index, int kind,
                               double param, pw85_pair_energy fn, void *data,
                               int threads, size_t n, double *energy,
                               double *forces,
                               double *torques) PW85_NOEXCEPT;

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* PW85_INDEX_H */
