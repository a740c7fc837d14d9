// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the packer (include/pw85/pw85_pack.h): check
// the arguments, call the core (src/pack/), map statuses.
#include "pw85_pack.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

#include "checks.hpp"
#include "facade.hpp"
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

// v scaled by a power of two so that its largest |entry| is in [1, 2)
// (exact; v finite, not all zero): the direction of the axis and the
// proportions of the box, whatever their scale, without overflow or
// underflow in their norm and product.
void scale_to_unit(double const v[3], double out[3]) noexcept {
  double const m = std::fmax(std::fabs(v[0]),
                             std::fmax(std::fabs(v[1]), std::fabs(v[2])));
  int const e = m > 0.0 ? std::ilogb(m) : 0;
  for (int k = 0; k < 3; ++k) out[k] = std::scalbn(v[k], -e);
}

// The side rule at the target for semi-axes a (3n, scaled by 2^−e for
// the packer): PW85_EINVAL if 2·a_max·(1 + 2⁻⁹) ≥ L_k for some k,
// PW85_ERANGE if the box is beyond the range of a double (at scale 2^e).
int side_rule(size_t n, double const *a, core::PackParams const &p,
              double amax, int e) noexcept {
  double box[3];
  if (!core::pack_box(n, a, p.aspect, p.target, box)) return PW85_ERANGE;
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(std::scalbn(box[k], e))) return PW85_ERANGE;
  for (int k = 0; k < 3; ++k)
    if (!(2.0 * amax * core::pack_side_margin < box[k])) return PW85_EINVAL;
  return PW85_SUCCESS;
}

// Semi-axes whose volume or box is beyond the range of a double at their
// own scale are packed scaled by 2^−e (amax in [1, 2)), and the outputs
// scaled back: μ² and every decision of pw85.h are invariant under a
// scaling by a power of two, and so is every step of the packer. This
// range keeps the forms, a², and their double-double parts, normal.
constexpr int min_scaled_exp = -500, max_scaled_exp = 500;

// The arguments of pw85_pack() in the order of its documented statuses;
// *params filled on success, and *scale_exp: 0, or the e above.
int check_arguments(size_t n, double const *a, pw85_pack_options const &o,
                    core::PackParams *params, int *scale_exp) noexcept {
  // 6·n doubles (the forms) must fit a size_t: no larger array exists.
  if (n > SIZE_MAX / (6 * sizeof(double))) return PW85_ENOMEM;
  for (size_t k = 0; k < 3 * n; ++k)
    if (!std::isfinite(a[k])) return PW85_EDOM;
  if (!std::isfinite(o.target) || !core::all_finite<3>(o.aspect) ||
      !core::all_finite<3>(o.axis) || !std::isfinite(o.time_limit))
    return PW85_EDOM;
  if (n == 0 || !(o.target > 0.0 && o.target < 1.0) ||
      (o.orientation != PW85_PACK_ISOTROPIC &&
       o.orientation != PW85_PACK_ALIGNED) ||
      o.threads < 1 || o.time_limit < 0.0 || o.progress_every == 0)
    return PW85_EINVAL;
  double amin = HUGE_VAL, amax = 0.0;
  for (size_t k = 0; k < 3 * n; ++k) {
    if (!(a[k] > 0.0)) return PW85_EINVAL;
    amin = std::fmin(amin, a[k]);
    amax = std::fmax(amax, a[k]);
  }
  for (int k = 0; k < 3; ++k)
    if (!(o.aspect[k] > 0.0)) return PW85_EINVAL;
  if (o.axis[0] == 0.0 && o.axis[1] == 0.0 && o.axis[2] == 0.0)
    return PW85_EINVAL;
  double axis[3], aspect[3];
  scale_to_unit(o.axis, axis);
  scale_to_unit(o.aspect, aspect);
  double const norm =
      std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (amax / amin > 0x1p40) return PW85_ERANGE;
  core::PackParams &p = *params;
  p.target = o.target;
  p.seed = o.seed;
  for (int k = 0; k < 3; ++k) {
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
  double box[3];
  *scale_exp = 0;
  if (!core::pack_box(n, a, p.aspect, p.target, box)) {
    int const e = std::ilogb(amax);
    if (e == 0 || std::ilogb(amin) < min_scaled_exp || e > max_scaled_exp)
      return PW85_ERANGE;
    *scale_exp = e;
    return PW85_SUCCESS;
  }
  return side_rule(n, a, p, amax, 0);
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
  if (semi_axes == nullptr || box == nullptr || centres == nullptr ||
      q == nullptr || phi == nullptr || outcome == nullptr)
    return PW85_EFAULT;
  pw85_pack_options defaults;
  pw85_pack_options_init(&defaults);
  if (options == nullptr) options = &defaults;
  if (options->size < sizeof(pw85_pack_options)) return PW85_EINVAL;
  core::PackParams params{};
  int e = 0;
  int code = check_arguments(n, semi_axes, *options, &params, &e);
  if (code != PW85_SUCCESS) return code;
  double const *a = semi_axes;
  std::unique_ptr<double[]> scaled;
  if (e != 0) {  // (n·3 doubles fit a size_t: check_arguments())
    scaled.reset(new (std::nothrow) double[3 * n]);
    if (!scaled) return PW85_ENOMEM;
    double amax = 0.0;
    for (size_t k = 0; k < 3 * n; ++k) {
      scaled[k] = std::scalbn(semi_axes[k], -e);
      amax = std::fmax(amax, scaled[k]);
    }
    a = scaled.get();
    code = side_rule(n, a, params, amax, e);
    if (code != PW85_SUCCESS) return code;
  }
  core::PackOutcome result = core::PackOutcome::limit;
  Status const s = core::pack(n, a, params, box, centres, quaternions, q, phi,
                              &result);
  if (s != Status::success) return to_code(s);
  if (e != 0) {  // exact: the range of min/max_scaled_exp
    for (int k = 0; k < 3; ++k) box[k] = std::scalbn(box[k], e);
    for (size_t k = 0; k < 3 * n; ++k) centres[k] = std::scalbn(centres[k], e);
    for (size_t k = 0; k < 6 * n; ++k) q[k] = std::scalbn(q[k], 2 * e);
  }
  *outcome = static_cast<int>(result);
  return PW85_SUCCESS;
}

}  // extern "C"
