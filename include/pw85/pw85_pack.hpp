// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pw85_pack.hpp
 * @brief pw85::pack(): the certified packer of pw85_pack.h, its outputs
 *        owned by std::vector, its progress through any callable.
 *
 * Header-only over the C ABI of pw85_pack.h, whose description is the
 * contract here (method, certification, determinism, statuses); link the
 * same -lpw85. C++11. Every function returns the PW85_* status of
 * pw85_pack() and none throws; on error the output is unchanged.
 *
 * @since 2.4.0
 */
#ifndef PW85_PACK_HPP
#define PW85_PACK_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "pw85.hpp"
#include "pw85_pack.h"

namespace pw85 {

/** pw85_pack_options with the defaults of pw85_pack_options_init().
 *  @since 2.4.0 */
struct PackOptions : pw85_pack_options {
  /** The defaults of pw85_pack_options_init(); set the members that
   *  differ. */
  PackOptions() noexcept : pw85_pack_options() {
    pw85_pack_options_init(this);
  }
};

/** The result of pack(): the box, and per ellipsoid its centre (3
 *  doubles), quaternion (4) and form (6), row by row.
 *  @since 2.4.0 */
struct Packing {
  std::array<double, 3> box{};    ///< the sides L0, L1, L2
  std::vector<double> centres;    ///< 3·n, in [0, L_k)
  std::vector<double> quaternions;  ///< 4·n, (w, x, y, z)
  std::vector<double> forms;      ///< 6·n
  double phi = 0.0;               ///< the packing fraction
  int outcome = PW85_PACK_LIMIT;  ///< PW85_PACK_TARGET, ..._LIMIT, ...
};

/// @cond PW85_INTERNAL
// The implementation of pack() (not part of the API).
namespace detail_pack {

using detail_vector::resize;  // pw85.hpp

template <typename F>
int call_progress(pw85_pack_progress const *p, void *data) noexcept {
  F &f = *static_cast<F *>(data);
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
  try {
    return f(*p) ? 0 : 1;
  } catch (...) {
    return 1;
  }
#else
  return f(*p) ? 0 : 1;
#endif
}

// pw85_pack() (D = 3, O = 4 doubles of a quaternion, S = 6) or
// pw85_2d_pack() (2, 1 angle, 3) as `fn`, its outputs in a Result (Packing
// or d2::Packing; `orientations` names its member of O·n doubles).
template <std::size_t D, std::size_t O, std::size_t S, typename Result,
          typename Fn>
int run(Fn fn, std::vector<double> Result::*orientations,
        std::vector<double> const &semi_axes,
        pw85_pack_options const &options, Result &out) noexcept {
  if (semi_axes.size() % D != 0) return PW85_EINVAL;
  std::size_t const n = semi_axes.size() / D;
  Result r;
  int status = resize(r.centres, D * n);
  if (status == PW85_SUCCESS) status = resize(r.*orientations, O * n);
  if (status == PW85_SUCCESS) status = resize(r.forms, S * n);
  if (status != PW85_SUCCESS) return status;
  status = fn(n, semi_axes.data(), &options, r.box.data(), r.centres.data(),
              (r.*orientations).data(), r.forms.data(), &r.phi, &r.outcome);
  if (status != PW85_SUCCESS) return status;
  out.box = r.box;
  out.centres.swap(r.centres);
  (out.*orientations).swap(r.*orientations);
  out.forms.swap(r.forms);
  out.phi = r.phi;
  out.outcome = r.outcome;
  return PW85_SUCCESS;
}

// run() with a progress callable as the callback of a copy of the options.
template <std::size_t D, std::size_t O, std::size_t S, typename Result,
          typename Fn, typename F>
int run_with(Fn fn, std::vector<double> Result::*orientations,
             std::vector<double> const &semi_axes,
             pw85_pack_options const &options, F &&progress,
             Result &out) noexcept {
  // A function named as progress is held by a pointer (pw85_index.hpp,
  // Index::energy()); any other callable by reference.
  using H = typename std::remove_reference<F>::type;
  typename std::conditional<std::is_function<H>::value, H *, H &>::type
      held = progress;
  using G = typename std::remove_reference<decltype(held)>::type;
  pw85_pack_options o = options;
  o.progress = &call_progress<G>;
  o.progress_data = const_cast<void *>(static_cast<void const *>(&held));
  return run<D, O, S>(fn, orientations, semi_axes, o, out);
}

}  // namespace detail_pack
/// @endcond

/**
 * @brief Pack the ellipsoids of `semi_axes` (3 per ellipsoid) with the
 *        options (pw85_pack()); the callback of the options is used as
 *        set there.
 * @return the statuses of pw85_pack(); PW85_EINVAL also if the size of
 *         semi_axes is not a multiple of 3; PW85_ENOMEM if a vector cannot
 *         grow. `out` is unchanged on error.
 * @since 2.4.0
 */
inline int pack(std::vector<double> const &semi_axes,
                PackOptions const &options, Packing &out) noexcept {
  return detail_pack::run<3, 4, 6>(pw85_pack, &Packing::quaternions,
                                   semi_axes, options, out);
}

/**
 * @brief pack() with a progress callable `bool progress(pw85_pack_progress
 *        const &)`, called every options.progress_every steps in the
 *        calling thread: false (or an exception, not rethrown) stops the
 *        packer (outcome PW85_PACK_CANCELLED).
 * @since 2.4.0
 */
template <typename F>
int pack(std::vector<double> const &semi_axes, PackOptions const &options,
         F &&progress, Packing &out) noexcept {
  return detail_pack::run_with<3, 4, 6>(pw85_pack, &Packing::quaternions,
                                        semi_axes, options, progress, out);
}

}  // namespace pw85

#endif  // PW85_PACK_HPP
