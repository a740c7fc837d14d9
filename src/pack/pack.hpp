// SPDX-License-Identifier: BSD-3-Clause
// The certified packer (private; include/pw85/pw85_pack.h and
// pw85_2d_pack.h are the contract, docs/packing.rst the account): a room
// above the index, using only its contract and that of the energy
// (index/energy.hpp). Written once for D = 3 (ellipsoids) and D = 2
// (ellipses).
#ifndef PW85_SRC_PACK_PACK_HPP
#define PW85_SRC_PACK_PACK_HPP

#include <cstddef>
#include <cstdint>

#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// pw85_pack_progress, member for member.
struct PackProgress {
  double phi;
  double phi_trial;
  double energy;
  double elapsed;
  std::size_t steps;
  std::size_t pairs;
};

using PackCallback = int (*)(PackProgress const *progress, void *data);

enum class PackOutcome { target = 0, limit = 1, jammed = 2, cancelled = 3 };

// The options, checked by the facade (pw85_pack.h): target in (0, 1),
// aspect > 0, axis a unit vector, threads ≥ 1, time_limit ≥ 0 (0: none),
// step_limit (0: none), progress_every ≥ 1. In 2D only the first two
// entries of aspect and axis are read.
struct PackParams {
  double target;
  std::uint64_t seed;
  double aspect[dim];
  bool aligned;
  double axis[dim];
  int threads;
  double time_limit;
  std::size_t step_limit;
  std::size_t progress_every;
  PackCallback callback;
  void *data;
  double side_limit;  // the largest side of a box returned (else ERANGE)
};

// The largest semi-axis times the margin of the side rule the packer
// applies (pw85_pack.h: 2·a_max·(1 + 2⁻⁹) < L_k at the target).
constexpr double pack_side_margin = 1.0 + 0x1p-9;

// The box (D sides) at packing fraction phi for the semi-axes a (D·n)
// and the aspect; false if the volume (area) is not finite.
template <int D>
bool pack_box(std::size_t n, double const *a, double const *aspect,
              double phi, double *box) noexcept;

// pw85_pack() (D = 3) and pw85_2d_pack() (D = 2), arguments checked
// (semi-axes finite and > 0, the box at the target holds the largest
// ellipsoid). Outputs: box D, c D·n, p (orientations: 4·n quaternions in
// 3D, n angles in 2D; may be null), q sym_size(D)·n. Nothing is written
// unless it returns Status::success.
template <int D>
Status pack(std::size_t n, double const *a, PackParams const &params,
            double *box, double *c, double *p, double *q, double *phi,
            PackOutcome *outcome) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_PACK_PACK_HPP
