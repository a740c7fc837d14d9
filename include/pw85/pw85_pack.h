/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85_pack.h
 * @brief A certified packer: N ellipsoids in a periodic box at a target
 *        packing fraction, no pair overlapping as pw85_overlap() decides.
 *
 * Conventions of pw85.h and pw85_index.h (vectors `double[3]`, forms
 * `double[6]`, arrays row by row). Quaternions are (w, x, y, z), scalar
 * first, as pw85_ellipsoid_quaternion(): ellipsoid i has semi-axis
 * semi_axes[3i + j] along R(p_i)·e_j.
 *
 * Method (docs/packing.rst, with its sources): the ellipsoids are placed
 * at random (uniform centres; orientations isotropic or aligned) in the
 * box of the target packing fraction φ = Σ(4π/3)·a0·a1·a2 / (L0·L1·L2),
 * then the overlap energy of pw85_index_energy(), U = Σ(1 − μ)² over the
 * pairs with μ < 1, is minimised over centres and orientations by FIRE
 * (Bitzek et al., Phys. Rev. Lett. 97, 170201, 2006), the shapes inflated
 * by 1 + 2⁻¹⁰, until √U < 2⁻¹¹ (no real pair can then overlap): the
 * jamming protocol of O'Hern et al. (Phys. Rev. E 68, 011306, 2003), with
 * the contact function of Perram and Wertheim as the overlap measure of
 * ellipsoids (Zeravcic et al., EPL 87, 26001, 2009). Where the energy
 * falls by less than half in 500 steps (more, up to 5000, with sizes far
 * apart: docs/packing.rst) (the target is beyond jamming for
 * this protocol), the box grows (by 2% at most) and bisection proceeds
 * between the densest certified and the least jammed packing fraction,
 * until they are within 0.1%. At any time, a
 * configuration is made certified by scaling the box and centres by
 * 1/min μ (times 1 + 2⁻²⁰): μ of a pair scales with the distance of the
 * centres, so the smallest μ over the pairs is the largest uniform growth
 * of the ellipsoids, centres fixed, that keeps them apart.
 *
 * Certification. Every configuration returned has no pair (i, j, n) for
 * which pw85_overlap() on r = (c_j + n∘L) − c_i decides −1 or 0: before it
 * returns, pw85_pack() inserts its outputs (centres, forms, box) into an
 * index and checks that pw85_index_overlapping_pairs() finds none.
 *
 * Determinism: the outputs are a function of the inputs (including the
 * seed), bit for bit, whatever the thread count (each step is the same
 * for any count: pw85_index_energy()); random numbers are drawn from a
 * counter-based generator per ellipsoid. A time limit makes the outputs
 * depend on the speed of the machine (where the run stops).
 *
 * Threads: up to `threads` OpenMP threads, at most 1024 (see
 * pw85_index_openmp() and pw85_index.h). Thread
 * safety: reentrant; the callback is called from the calling thread.
 *
 * @since 2.4.0
 */
#ifndef PW85_PACK_H
#define PW85_PACK_H

#include <stddef.h>
#include <stdint.h>

#include "pw85.h"

#ifdef __cplusplus
extern "C" {
#endif

/** @name Orientation rules
 *  @{ */
/** Uniform random orientations (Shoemake's uniform quaternions).
 *  @since 2.4.0 */
#define PW85_PACK_ISOTROPIC 0
/** The largest semi-axis of every ellipsoid along `axis` (fibres), a
 *  random rotation about it; the ellipsoids turn only about `axis`.
 *  @since 2.4.0 */
#define PW85_PACK_ALIGNED 1
/** @} */

/** @name Outcomes (the `outcome` of pw85_pack(), with PW85_SUCCESS)
 *  @{ */
/** The target packing fraction was reached. @since 2.4.0 */
#define PW85_PACK_TARGET 0
/** The time or step limit came first: the densest certified
 *  configuration found. @since 2.4.0 */
#define PW85_PACK_LIMIT 1
/** The target is beyond jamming for this method: the densest certified
 *  configuration found, within 0.1% of the jamming packing fraction of
 *  the run. @since 2.4.0 */
#define PW85_PACK_JAMMED 2
/** The progress callback returned non-zero: the densest certified
 *  configuration found so far. @since 2.4.0 */
#define PW85_PACK_CANCELLED 3
/** @} */

/** What the progress callback receives. @since 2.4.0 */
typedef struct pw85_pack_progress {
  double phi;        /**< the packing fraction of the densest certified
                          configuration so far (0 if none yet). */
  double phi_trial;  /**< the packing fraction being relaxed. */
  double energy;     /**< the overlap energy per ellipsoid (of the
                          inflated shapes; 0 when certified). */
  double elapsed;    /**< seconds since the call began (wall clock). */
  size_t steps;      /**< FIRE steps so far. */
  size_t pairs;      /**< overlapping pairs (inflated shapes). */
} pw85_pack_progress;

/** A progress callback: return 0 to go on, non-zero to stop (outcome
 *  PW85_PACK_CANCELLED). @since 2.4.0 */
typedef int (*pw85_pack_callback)(pw85_pack_progress const *progress,
                                  void *data);

/** The options of pw85_pack(), and of pw85_2d_pack() (pw85_2d_pack.h,
 *  which reads the first two entries of aspect, and of axis with
 *  PW85_PACK_ALIGNED only); fill with pw85_pack_options_init() first,
 *  then set what differs. @since 2.4.0 */
typedef struct pw85_pack_options {
  size_t size;          /**< sizeof(pw85_pack_options), set by
                             pw85_pack_options_init(): later releases
                             append members. */
  double target;        /**< the target packing fraction, in (0, 1);
                             default 0.5. */
  uint64_t seed;        /**< the seed of the random placement; default 0. */
  double aspect[3];     /**< the box's sides are proportional to these
                             (each > 0, finite; only their ratios count);
                             default 1, 1, 1 (cube). */
  int orientation;      /**< PW85_PACK_ISOTROPIC (default) or
                             PW85_PACK_ALIGNED. */
  double axis[3];       /**< the axis of PW85_PACK_ALIGNED (finite, not
                             zero, of any length: normalised by
                             pw85_pack()); default 0, 0, 1. */
  int threads;          /**< threads (≥ 1); default 1. */
  double time_limit;    /**< seconds of wall clock (> 0), or 0 for none
                             (default). */
  size_t step_limit;    /**< FIRE steps, or 0 for none (default). */
  size_t progress_every;  /**< steps between calls of the callback (≥ 1);
                               default 100. */
  pw85_pack_callback progress;  /**< NULL (default) or a callback. */
  void *progress_data;  /**< passed to the callback. */
} pw85_pack_options;

/**
 * @brief The default options.
 * @param[out] options filled with the defaults (NULL: nothing done).
 * @since 2.4.0
 */
PW85_API void pw85_pack_options_init(pw85_pack_options *options) PW85_NOEXCEPT;

/**
 * @brief Pack n ellipsoids in a periodic box (see the file description).
 *
 * @param[in] n the number of ellipsoids (≥ 1).
 * @param[in] semi_axes 3·n semi-axes (each > 0 and finite), any mix of
 *            sizes and shapes. (Every result is certified; how close to
 *            jamming a mixture gets is a measurement: at φ = 0.3, 2 + 1,
 *            6 + 30, 8 + 72 and 20 + 180 unit spheres and spheres of
 *            0.01 reach the target (seeds 1 and 2); at 1000 : 1, 6 + 30
 *            stop at 0.25 (PW85_PACK_JAMMED), and in 2D 10 + 90 discs
 *            at 100 : 1 stop at 0.293 and 0.2997.)
 * @param[in] options the options (NULL: the defaults).
 * @param[out] box the sides L0, L1, L2 of the box.
 * @param[out] centres 3·n doubles: the centres, in [0, L_k).
 * @param[out] quaternions NULL, or 4·n doubles: the unit quaternions.
 * @param[out] q 6·n doubles: the forms, pw85_ellipsoid_quaternion() of
 *             semi_axes and quaternions, bit for bit.
 * @param[out] phi the packing fraction of the result (as computed from
 *             box: Σ(4π/3)·a0·a1·a2 / (L0·L1·L2)).
 * @param[out] outcome PW85_PACK_TARGET, PW85_PACK_LIMIT, PW85_PACK_JAMMED
 *             or PW85_PACK_CANCELLED.
 * @return PW85_SUCCESS (with an outcome); PW85_EFAULT if semi_axes, box,
 *         centres, q, phi or outcome is NULL; PW85_EDOM if a semi-axis,
 *         the target, an aspect, the axis or the time limit is NaN or
 *         infinite; PW85_EINVAL if n = 0, a semi-axis ≤ 0, the target not
 *         in (0, 1), an aspect ≤ 0, the orientation rule unknown, the axis
 *         zero, threads < 1, the time limit < 0, progress_every = 0,
 *         options->size too small, or if the box at the target cannot
 *         hold the largest ellipsoid (the side rule of pw85_index.h with
 *         the largest semi-axis: 2·a_max·(1 + 2⁻⁹) ≥ L_k for some k);
 *         PW85_ERANGE if the semi-axes span more than 2⁴⁰, or a side of
 *         the box at the target, or of the box of the packing returned,
 *         is above 2⁹⁹² (the bound of pw85_index_create()), or the
 *         volume Σa0·a1·a2 is beyond the range of a double while a
 *         semi-axis is outside [2⁻⁵⁰⁰, 2⁵⁰¹) (inside, they are packed
 *         scaled by a power of two, and the outputs scaled back: exactly
 *         the packing of the scaled semi-axes, scaled); PW85_ENOMEM
 *         (also if 6·n doubles would not fit a size_t). Nothing is
 *         written on error.
 * @since 2.4.0
 */
PW85_API int pw85_pack(size_t n, double const *semi_axes,
                       pw85_pack_options const *options,
                       double box[PW85_DIM], double *centres,
                       double *quaternions, double *q, double *phi,
                       int *outcome) PW85_NOEXCEPT;

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* PW85_PACK_H */
