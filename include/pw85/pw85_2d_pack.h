/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85_2d_pack.h
 * @brief A certified packer of ellipses: N ellipses in a periodic
 *        rectangle at a target packing fraction, no pair overlapping as
 *        pw85_2d_overlap() decides.
 *
 * The two-dimensional counterpart of pw85_pack.h: the library runs the
 * same code for both (the placement, FIRE on the overlap energy of
 * pw85_2d_index_energy(), the bisection near jamming and the
 * certification are written once, for a dimension D = 2 or 3), and its
 * contract holds word for word where it is not about sizes. Conventions
 * of pw85_2d.h (vectors `double[2]`, forms `double[3]` = (Q00, Q01, Q11));
 * arrays row by row. Ellipse i has semi-axis semi_axes[2i] along
 * (cos θ_i, sin θ_i) and semi_axes[2i + 1] along (−sin θ_i, cos θ_i), as
 * pw85_2d_ellipse() of the semi-axes and the angle θ_i.
 *
 * Method: that of pw85_pack() (docs/packing.rst): random placement in the
 * rectangle of the target packing fraction φ = Σπ·a0·a1 / (L0·L1), with
 * uniform angles or aligned; FIRE on the overlap energy U = Σ(1 − μ)² of
 * the shapes inflated by 1 + 2⁻¹⁰ over centres and angles until
 * √U < 2⁻¹¹; where the energy falls by less than half in 500 steps (up to
 * 5000 with sizes far apart, as pw85_pack()), the
 * rectangle grows (by 2% at most) and bisection proceeds between the
 * densest certified and the least jammed packing fraction, until within
 * 0.1%. Any configuration is certified by scaling the rectangle and
 * centres by 1/min μ (times 1 + 2⁻²⁰).
 *
 * Options: pw85_pack_options of pw85_pack.h, with these readings for
 * ellipses: only aspect[0] and aspect[1] (the proportions of the sides
 * L0, L1) are read, and, with PW85_PACK_ALIGNED only, axis[0] and
 * axis[1] (a direction in the plane; set it: the default axis (0, 0, 1)
 * has none); aspect[2] and axis[2] are ignored (not checked), and so is
 * the axis with PW85_PACK_ISOTROPIC. PW85_PACK_ISOTROPIC: angles uniform
 * in [−π, π). PW85_PACK_ALIGNED: the largest semi-axis of every ellipse
 * along `axis` (the first of two equal ones), and the ellipses never
 * turn. The outcomes are those of pw85_pack.h
 * (PW85_PACK_TARGET, ..._LIMIT, ..._JAMMED, ..._CANCELLED); the progress
 * callback receives the same pw85_pack_progress (its energy per ellipse,
 * its steps those of FIRE).
 *
 * Certification. Every configuration returned has no pair (i, j, n) for
 * which pw85_2d_overlap() on r = (c_j + n∘L) − c_i decides −1 or 0:
 * before it returns, pw85_2d_pack() inserts its outputs (centres, forms,
 * rectangle) into a pw85_2d_index and checks that
 * pw85_2d_index_overlapping_pairs() finds none.
 *
 * Determinism: the outputs are a function of the inputs (including the
 * seed), bit for bit, whatever the thread count; a time limit makes them
 * depend on the speed of the machine. Threads: up to `threads` OpenMP
 * threads, at most 1024 (see pw85_index_openmp() and pw85_index.h). Thread safety: reentrant; the callback is
 * called from the calling thread.
 *
 * The command-line tool packs ellipses with it (pw85-pack --2d); the
 * Fortran and Node.js wrappers pack ellipsoids only.
 *
 * @since 2.5.0
 */
#ifndef PW85_2D_PACK_H
#define PW85_2D_PACK_H

#include <stddef.h>

#include "pw85_2d.h"
#include "pw85_pack.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Pack n ellipses in a periodic rectangle (see the file
 *        description).
 *
 * @param[in] n the number of ellipses (≥ 1).
 * @param[in] semi_axes 2·n semi-axes (each > 0 and finite), any mix of
 *            sizes and shapes (how close to jamming a mixture of very
 *            different sizes gets is a measurement, as pw85_pack() says).
 * @param[in] options the options (NULL: the defaults of
 *            pw85_pack_options_init(); see the file description for the
 *            entries read).
 * @param[out] box the sides L0, L1 of the rectangle.
 * @param[out] centres 2·n doubles: the centres, in [0, L_k).
 * @param[out] angles NULL, or n doubles: the angles θ_i (radians, in
 *             [−π, π]).
 * @param[out] q 3·n doubles: the forms, pw85_2d_ellipse() of semi_axes
 *             and angles, bit for bit.
 * @param[out] phi the packing fraction of the result (as computed from
 *             box: Σπ·a0·a1 / (L0·L1)).
 * @param[out] outcome PW85_PACK_TARGET, PW85_PACK_LIMIT, PW85_PACK_JAMMED
 *             or PW85_PACK_CANCELLED.
 * @return PW85_SUCCESS (with an outcome); PW85_EFAULT if semi_axes, box,
 *         centres, q, phi or outcome is NULL; PW85_EDOM if a semi-axis,
 *         the target, aspect[0] or [1], axis[0] or [1] (aligned) or the
 *         time limit is NaN or infinite; PW85_EINVAL if n = 0, a semi-axis
 *         ≤ 0, the target not in (0, 1), aspect[0] or [1] ≤ 0, the
 *         orientation rule unknown, axis[0] and axis[1] both zero
 *         (aligned), threads < 1, the time
 *         limit < 0, progress_every = 0, options->size too small, or if
 *         the rectangle at the target cannot hold the largest ellipse (the
 *         side rule of pw85_2d_index.h with the largest semi-axis:
 *         2·a_max·(1 + 2⁻⁹) ≥ L_k for some k); PW85_ERANGE if the
 *         semi-axes span more than 2⁴⁰, or a side of the rectangle at
 *         the target, or of the rectangle of the packing returned, is
 *         above 2⁹⁹² (the bound of pw85_2d_index_create()), or the area
 *         Σa0·a1 is beyond the range of a double while a semi-axis is
 *         outside [2⁻⁵⁰⁰, 2⁵⁰¹) (inside, they are packed scaled by a
 *         power of two, and the outputs scaled back: exactly the packing
 *         of the scaled semi-axes, scaled);
 *         PW85_ENOMEM (also if 3·n doubles would not fit a size_t).
 *         Nothing is written on error.
 * @since 2.5.0
 */
PW85_API int pw85_2d_pack(size_t n, double const *semi_axes,
                          pw85_pack_options const *options,
                          double box[PW85_2D_DIM], double *centres,
                          double *angles, double *q, double *phi,
                          int *outcome) PW85_NOEXCEPT;

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* PW85_2D_PACK_H */
