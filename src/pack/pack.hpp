// SPDX-License-Identifier: BSD-3-Clause
// The certified packer (private; include/pw85/pw85_pack.h is the
// contract, docs/packing.rst the account): a room above the index, using
// only its contract and that of the energy (index/energy.hpp).
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
// step_limit (0: none), progress_every ≥ 1.
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
};

// The largest semi-axis times the margin of the side rule the packer
// applies (pw85_pack.h: 2·a_max·(1 + 2⁻⁹) < L_k at the target).
constexpr double pack_side_margin = 1.0 + 0x1p-9;

// The box at packing fraction phi for the semi-axes a (3n) and the
// aspect; false if the volume is not finite.
bool pack_box(std::size_t n, double const *a, double const aspect[dim],
              double phi, double box[dim]) noexcept;

// pw85_pack(), arguments checked (semi-axes finite and > 0, the box at
// the target holds the largest ellipsoid). p may be null. Nothing is
// written unless it returns Status::success.
Status pack(std::size_t n, double const *a, PackParams const &params,
            double box[dim], double *c, double *p, double *q, double *phi,
            PackOutcome *outcome) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_PACK_PACK_HPP
