/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85_image.h
 * @brief The voxel image of a set of ellipsoids, each voxel centre decided
 *        exactly, for FFT solvers and viewers; and its phase fraction.
 *
 * Conventions of pw85.h (vectors `double[3]`, symmetric forms `double[6]`,
 * an ellipsoid {m : (m − c)ᵀ Q⁻¹ (m − c) ≤ 1}, surface included); arrays
 * of n vectors or forms contiguous, row by row (`centres[3·p + k]`,
 * `q[6·p + k]`), as pw85_index.h. Narrative: docs, "Microstructures for
 * FFT solvers and viewers".
 *
 * The grid. The box [o, o + L] (o = `origin`, L = `sides`) is cut into
 * dims[0] × dims[1] × dims[2] voxels; voxel (i, j, k) stands for the point
 *     m = (o0 + (i + ½)·L0/dims[0], o1 + (j + ½)·L1/dims[1],
 *          o2 + (k + ½)·L2/dims[2]),
 * the exact real number (not its rounding to doubles). The image is stored
 * in C order, first index along x: voxel (i, j, k) is
 * `image[(i·dims[1] + j)·dims[2] + k]`, as a NumPy array `image[i, j, k]`.
 *
 * Values. A voxel holds the position p (0 ≤ p < n, in the caller's arrays)
 * of the ellipsoid that contains its point, −1 if none does (the matrix).
 * Overlapping ellipsoids are valid input: a point in several holds the
 * least of their positions. Periodic: ellipsoid p stands for all its images
 * c + t∘L, t ∈ ℤ³, and a point in any image of p is in p (an ellipsoid may
 * be wider than the box). Open: only the ellipsoids themselves; the part of
 * an ellipsoid outside the box is not drawn.
 *
 * Exactness. Whether m is in an ellipsoid is the sign of
 * (m − c)ᵀ Q⁻¹ (m − c) − 1 for the exact m, c and Q given, decided without
 * any tolerance: a floating-point filter with a certified error bound, and
 * where it cannot decide (points on or within about 2⁻⁴⁶ of a surface, in
 * relative terms) an exact computation in integers. A point on a surface
 * to the last bit is inside. This assumes the default floating-point
 * environment (no flush-to-zero nor denormals-are-zero mode); the caller's
 * exception flags (all of them, on success and on error) are left as they
 * were.
 *
 * Cost and memory. The work is proportional to the voxels of the
 * ellipsoids' bounding boxes (each row of voxels is decided by a few
 * certified tests at its ends, the voxels between by convexity), plus one
 * pass over the image; in a periodic box a bounding box wider than the box
 * is walked whole (an ellipsoid k times as wide as the box costs k³ times
 * the image); nothing is allocated: the memory is the caller's
 * image (4 bytes per voxel). Threads: `threads` OpenMP threads when
 * libpw85 was built with OpenMP (pw85_index_openmp()), 1 runs in the
 * calling thread, 0 is OpenMP's default; at most dims[0] threads, one
 * per 4096 voxels, and 1024, are started (none for an image of fewer than 4096
 * voxels); the image is the same, bit for bit, for any number. Reentrant: concurrent calls on different images are
 * safe.
 *
 * @since 2.4.0
 */
#ifndef PW85_IMAGE_H
#define PW85_IMAGE_H

#include <stddef.h>
#include <stdint.h>

#include "pw85.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The largest dims[k] of an image: 2²⁰.
 *  @since 2.4.0 */
#define PW85_IMAGE_MAX_DIM ((size_t)1 << 20)
/** The value of a voxel of the matrix (in no ellipsoid).
 *  @since 2.4.0 */
#define PW85_IMAGE_MATRIX (-1)

/**
 * @brief The voxel image of n ellipsoids, in a periodic box or an open
 *        domain (the file description gives the grid and the values).
 *
 * @param[in] n the number of ellipsoids (0 gives an image of −1), at most
 *            INT32_MAX.
 * @param[in] centres their centres (3·n doubles; may be NULL if n = 0).
 *            Each must satisfy |c_k − o_k| + √Q_kk ≤ 2²⁹·L_k, the left
 *            side finite (the reach rule).
 * @param[in] q their quadratic forms (6·n doubles), positive definite.
 * @param[in] origin the corner o of the box, or NULL for (0, 0, 0).
 * @param[in] sides the sides L of the box (each > 0 and finite).
 * @param[in] periodic nonzero: the box is periodic; 0: an open domain.
 * @param[in] dims the number of voxels along each axis, each from 1 to
 *            PW85_IMAGE_MAX_DIM.
 * @param[out] image dims[0]·dims[1]·dims[2] int32 values, written whole.
 * @param[in] threads 1, 0 (OpenMP's default) or k > 1 threads.
 * @return PW85_SUCCESS; PW85_EFAULT if sides, dims or image is NULL, or
 *         n > 0 and centres or q is NULL; PW85_EDOM if an entry of origin,
 *         sides, a centre or a form is not finite; PW85_ENOTPOSDEF if a
 *         form is not positive definite; PW85_EINVAL if a side is not > 0,
 *         a dims[k] is 0 or above PW85_IMAGE_MAX_DIM, n > INT32_MAX,
 *         threads < 0, or an ellipsoid breaks the reach rule above;
 *         PW85_ERANGE if the image's size in bytes does not fit a size_t.
 *         The image is written on success only.
 * @since 2.4.0
 */
PW85_API int pw85_image_voxels(size_t n, double const *centres,
                               double const *q, double const origin[PW85_DIM],
                               double const sides[PW85_DIM], int periodic,
                               size_t const dims[PW85_DIM], int32_t *image,
                               int threads) PW85_NOEXCEPT;

/**
 * @brief The phase fraction of an image: the number of voxels that hold a
 *        position (≥ 0), and their fraction of all voxels.
 *
 * @param[in] dims the image's dimensions (each ≥ 1, product fitting a
 *            size_t of bytes as for pw85_image_voxels()).
 * @param[in] image the image.
 * @param[out] count the number of voxels whose value is ≥ 0 (may be NULL).
 * @param[out] fraction count / (dims[0]·dims[1]·dims[2]), correctly
 *             rounded (may be NULL).
 * @return PW85_SUCCESS; PW85_EFAULT if dims or image is NULL; PW85_EINVAL
 *         if a dims[k] is 0; PW85_ERANGE if the size overflows. Outputs
 *         are written on success only.
 * @since 2.4.0
 */
PW85_API int pw85_image_fraction(size_t const dims[PW85_DIM],
                                 int32_t const *image, size_t *count,
                                 double *fraction) PW85_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif /* PW85_IMAGE_H */
