// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the packer (include/pw85/pw85_pack.h and
// pw85_2d_pack.h): check the arguments, call the core (src/pack/), map
// statuses; written once for D = 3 (pw85_pack()) and D = 2
// (pw85_2d_pack(), which reads the first two entries of the options'
// aspect and axis).
#include "pw85_2d_pack.h"
#include "pw85_pack.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

#include "checks.hpp"
#include "facade.hpp"
#include "index/margins.hpp"
#include "pack/pack.hpp"

namespace core = pw85::detail;
using core::Status;
using pw85::facade::to_code;

namespace {

// The caller's callback, called with the public struct.
int call_progress(core::PackProgress const *pr, void *data) noexcept {
  auto const *o = static_cast<pw85_pack_options const *>(data);
  pw85_pack_progress const x{pr->phi,     pr->phi_trial, pr->energy,
                             pr->elapsed, pr->steps,     pr->pairs};
  return o->progress(&x, o->progress_data);
}

// v (D entries) scaled by a power of two so that its largest |entry| is
// in [1, 2) (exact; v finite, not all zero): the direction of the axis
// and the proportions of the box, whatever their scale, without overflow
// or underflow in their norm and product.
template <int D>
void scale_to_unit(double const *v, double *out) noexcept {
  double m = std::fabs(v[D - 1]);
  for (int k = D - 2; k >= 0; --k) m = std::fmax(std::fabs(v[k]), m);
  int const e = m > 0.0 ? std::ilogb(m) : 0;
  for (int k = 0; k < D; ++k) out[k] = std::scalbn(v[k], -e);
}

// The side rule at the target for semi-axes a (D·n, scaled by 2^−e for
// the packer): PW85_EINVAL if 2·a_max·(1 + 2⁻⁹) ≥ L_k for some k,
// PW85_ERANGE if a side is beyond the index's bound (at scale 2^e).
template <int D>
int side_rule(size_t n, double const *a, core::PackParams const &p,
              double amax, int e) noexcept {
  double box[D];
  if (!core::pack_box<D>(n, a, p.aspect, p.target, box)) return PW85_ERANGE;
  for (int k = 0; k < D; ++k)
    if (!(std::scalbn(box[k], e) <= pw85::detail::max_side))
      return PW85_ERANGE;
  for (int k = 0; k < D; ++k)
    if (!(2.0 * amax * core::pack_side_margin < box[k])) return PW85_EINVAL;
  return PW85_SUCCESS;
}

// Semi-axes whose volume or box is beyond the range of a double at their
// own scale are packed scaled by 2^−e (amax in [1, 2)), and the outputs
// scaled back: μ² and every decision of pw85.h are invariant under a
// scaling by a power of two, and so is every step of the packer. This
// range keeps the forms, a², and their double-double parts, normal.
constexpr int min_scaled_exp = -500, max_scaled_exp = 500;

// The arguments of pw85_pack() (D = 3) and pw85_2d_pack() (D = 2) in the
// order of their documented statuses; *params filled on success, and
// *scale_exp: 0, or the e above.
template <int D>
int check_arguments(size_t n, double const *a, pw85_pack_options const &o,
                    core::PackParams *params, int *scale_exp) noexcept {
  constexpr int S = core::sym_size(D);
  // The axis: always read in 3D; in 2D with PW85_PACK_ALIGNED only (the
  // default axis, (0, 0, 1), has no direction in the plane).
  bool const with_axis = D == 3 || o.orientation == PW85_PACK_ALIGNED;
  double const plane_x[2] = {1.0, 0.0};
  double const *const axis_in = with_axis ? o.axis : plane_x;
  // S·n doubles (the forms) must fit a size_t: no larger array exists.
  if (n > SIZE_MAX / (S * sizeof(double))) return PW85_ENOMEM;
  for (size_t k = 0; k < D * n; ++k)
    if (!std::isfinite(a[k])) return PW85_EDOM;
  if (!std::isfinite(o.target) || !core::all_finite<D>(o.aspect) ||
      !core::all_finite<D>(axis_in) || !std::isfinite(o.time_limit))
    return PW85_EDOM;
  if (n == 0 || !(o.target > 0.0 && o.target < 1.0) ||
      (o.orientation != PW85_PACK_ISOTROPIC &&
       o.orientation != PW85_PACK_ALIGNED) ||
      o.threads < 1 || o.time_limit < 0.0 || o.progress_every == 0)
    return PW85_EINVAL;
  double amin = HUGE_VAL, amax = 0.0;
  for (size_t k = 0; k < D * n; ++k) {
    if (!(a[k] > 0.0)) return PW85_EINVAL;
    amin = std::fmin(amin, a[k]);
    amax = std::fmax(amax, a[k]);
  }
  bool zero = true;
  for (int k = 0; k < D; ++k) {
    if (!(o.aspect[k] > 0.0)) return PW85_EINVAL;
    zero = zero && axis_in[k] == 0.0;
  }
  if (zero) return PW85_EINVAL;
  double axis[D], aspect[D];
  scale_to_unit<D>(axis_in, axis);
  scale_to_unit<D>(o.aspect, aspect);
  double norm2 = 0.0;
  for (int k = 0; k < D; ++k) norm2 += axis[k] * axis[k];
  double const norm = std::sqrt(norm2);
  if (amax / amin > 0x1p40) return PW85_ERANGE;
  core::PackParams &p = *params;
  p.target = o.target;
  p.seed = o.seed;
  for (int k = 0; k < 3; ++k) p.aspect[k] = p.axis[k] = 0.0;
  for (int k = 0; k < D; ++k) {
    p.aspect[k] = aspect[k];
    p.axis[k] = axis[k] / norm;
  }
  p.aligned = o.orientation == PW85_PACK_ALIGNED;
  p.threads = o.threads;
  p.time_limit = o.time_limit;
  p.step_limit = o.step_limit;
  p.progress_every = o.progress_every;
  p.callback = o.progress != nullptr ? call_progress : nullptr;
  p.data = const_cast<pw85_pack_options *>(&o);
  // The box at the target, and the side rule with the largest semi-axis
  // (the packer's own computation, core::pack_box()); beyond the range of
  // a double at the scale of the semi-axes, *scale_exp says by what to
  // scale them, and the caller checks them scaled (side_rule()).
  double box[D];
  *scale_exp = 0;
  if (!core::pack_box<D>(n, a, p.aspect, p.target, box)) {
    int const e = std::ilogb(amax);
    if (e == 0 || std::ilogb(amin) < min_scaled_exp || e > max_scaled_exp)
      return PW85_ERANGE;
    *scale_exp = e;
    return PW85_SUCCESS;
  }
  return side_rule<D>(n, a, p, amax, 0);
}

// pw85_pack() and pw85_2d_pack(): orientations are 4·n quaternions (3D)
// or n angles (2D).
template <int D>
int pack_facade(size_t n, double const *semi_axes,
                pw85_pack_options const *options, double *box,
                double *centres, double *orientations, double *q,
                double *phi, int *outcome) noexcept {
  constexpr int S = core::sym_size(D);
  if (semi_axes == nullptr || box == nullptr || centres == nullptr ||
      q == nullptr || phi == nullptr || outcome == nullptr)
    return PW85_EFAULT;
  pw85_pack_options defaults;
  pw85_pack_options_init(&defaults);
  if (options == nullptr) options = &defaults;
  if (options->size < sizeof(pw85_pack_options)) return PW85_EINVAL;
  core::PackParams params{};
  int e = 0;
  int code = check_arguments<D>(n, semi_axes, *options, &params, &e);
  if (code != PW85_SUCCESS) return code;
  double const *a = semi_axes;
  std::unique_ptr<double[]> scaled;
  if (e != 0) {  // (n·D doubles fit a size_t: check_arguments())
    scaled.reset(new (std::nothrow) double[D * n]);
    if (!scaled) return PW85_ENOMEM;
    double amax = 0.0;
    for (size_t k = 0; k < D * n; ++k) {
      scaled[k] = std::scalbn(semi_axes[k], -e);
      amax = std::fmax(amax, scaled[k]);
    }
    a = scaled.get();
    code = side_rule<D>(n, a, params, amax, e);
    if (code != PW85_SUCCESS) return code;
  }
  params.side_limit = std::scalbn(pw85::detail::max_side, -e);
  core::PackOutcome result = core::PackOutcome::limit;
  Status const s = core::pack<D>(n, a, params, box, centres, orientations, q,
                                 phi, &result);
  if (s != Status::success) return to_code(s);
  if (e != 0) {  // exact: the range of min/max_scaled_exp
    for (int k = 0; k < D; ++k) box[k] = std::scalbn(box[k], e);
    for (size_t k = 0; k < D * n; ++k) centres[k] = std::scalbn(centres[k], e);
    for (size_t k = 0; k < S * n; ++k) q[k] = std::scalbn(q[k], 2 * e);
  }
  *outcome = static_cast<int>(result);
  return PW85_SUCCESS;
}

}  // namespace

extern "C" {

void pw85_pack_options_init(pw85_pack_options *options) noexcept {
  if (options == nullptr) return;
  *options = pw85_pack_options{};
  options->size = sizeof(pw85_pack_options);
  options->target = 0.5;
  options->seed = 0;
  for (int k = 0; k < 3; ++k) options->aspect[k] = 1.0;
  options->orientation = PW85_PACK_ISOTROPIC;
  options->axis[0] = options->axis[1] = 0.0;
  options->axis[2] = 1.0;
  options->threads = 1;
  options->time_limit = 0.0;
  options->step_limit = 0;
  options->progress_every = 100;
  options->progress = nullptr;
  options->progress_data = nullptr;
}

int pw85_pack(size_t n, double const *semi_axes,
              pw85_pack_options const *options, double box[PW85_DIM],
              double *centres, double *quaternions, double *q, double *phi,
              int *outcome) noexcept {
  return pack_facade<3>(n, semi_axes, options, box, centres, quaternions, q,
                        phi, outcome);
}

int pw85_2d_pack(size_t n, double const *semi_axes,
                 pw85_pack_options const *options, double box[PW85_2D_DIM],
                 double *centres, double *angles, double *q, double *phi,
                 int *outcome) noexcept {
  return pack_facade<2>(n, semi_axes, options, box, centres, angles, q, phi,
                        outcome);
}

}  // extern "C"
