// SPDX-License-Identifier: BSD-3-Clause
// Energy, forces and torques summed over the pairs of an index (private;
// include/pw85/pw85_index.h, pw85_index_energy(), and pw85_2d_index.h,
// pw85_2d_index_energy(), are the contract; docs/packing.rst the
// account). Written once for D = 3 and D = 2: in 2D a torque is one
// number per ellipse (∂/∂θ, pw85_2d.h), in 3D a vector of 3. A query of
// the index: the all-pairs query gives the pairs (i, j, n) in the order
// (i, j, n), each pair's derivatives are computed alone (on threads),
// then summed serially in that order, so that the sums are the same, bit
// for bit, for any number of threads.
#ifndef PW85_SRC_INDEX_ENERGY_HPP
#define PW85_SRC_INDEX_ENERGY_HPP

#include <cstddef>

#include "index.hpp"
#include "status.hpp"

namespace pw85::detail {

// The pair energies of pw85_index_energy().
enum class EnergyKind { overlap = 0, user = 1 };

// A caller's pair energy: out[0] = U(μ²), out[1] = dU/dμ²; non-zero stops.
using EnergyFn = int (*)(double mu2, void *data, double out[2]);

struct EnergySpec {
  EnergyKind kind;
  double param;  // overlap: ε > 0; user: the threshold t > 0 on μ²
  EnergyFn fn;   // user only
  void *data;
};

// The sums of the pairs of `index` (pw85_index_energy(),
// pw85_2d_index_energy()): *energy, and, when not null, forces (D·n
// doubles) and torques (Outputs<D>::rot_size·n doubles, geometry.hpp),
// rows by id, n > every stored id; zero rows for ellipsoids in no pair.
// Nothing is
// written on error. The spec and n are checked here: Status::
// invalid_argument for an unknown kind, ε or t ≤ 0, a user kind without
// a function, threads < 1, n ≤ the largest stored id; not_finite for a
// parameter, or a value returned by the function, not finite; cancelled
// when the function returns non-zero; no_memory when forces or torques
// is given and D·n doubles would not fit a size_t; out_of_range when the
// energy, or a force or torque asked for, is not finite. *npairs, when
// not null: the number of pairs summed.
template <int D>
Status assembly_energy(spatial::Index<D> const &index,
                       EnergySpec const &spec, int threads, std::size_t n,
                       double *energy, double *forces, double *torques,
                       std::size_t *npairs = nullptr) noexcept;
extern template Status assembly_energy<2>(spatial::Index<2> const &,
                                          EnergySpec const &, int,
                                          std::size_t, double *, double *,
                                          double *, std::size_t *) noexcept;
extern template Status assembly_energy<3>(spatial::Index<3> const &,
                                          EnergySpec const &, int,
                                          std::size_t, double *, double *,
                                          double *, std::size_t *) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_ENERGY_HPP
