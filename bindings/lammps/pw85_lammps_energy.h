/* SPDX-License-Identifier: BSD-3-Clause */
/* The pair energy of pair style pw85, in one place: U(μ²) and dU/dμ².
 *
 * U = ε·(1 − μ)² for μ < 1, 0 for μ ≥ 1 (docs/lammps.rst, "Energy"), where
 * μ² is the Perram–Wertheim contact function (pw85_contact_function()):
 * U and dU/dμ are continuous at μ = 1 (both 0), so forces are continuous
 * at first contact. With μ = √(μ²):
 *   dU/dμ² = (dU/dμ)·(dμ/dμ²) = −2ε(1 − μ)·1/(2μ) = −ε(1 − μ)/μ.
 * Forces and torques are −(dU/dμ²)·∂μ²/∂(...) (pw85_contact_derivatives()).
 * At μ = 0 (coincident centres) dU/dμ² is infinite while every ∂μ²/∂(...)
 * is 0: the energy has a cusp there, and its force is taken as 0.
 *
 * This is the file to change for another energy: the pair style reads the
 * formula only through pw85_lammps_energy() (the tests recompute it
 * independently, in Python). */
#ifndef PW85_LAMMPS_ENERGY_H
#define PW85_LAMMPS_ENERGY_H

#include <cmath>

namespace pw85_lammps {

/* The energy of a pair whose contact function is mu2 (≥ 0), with
 * strength eps (an energy): returns U and writes dU/dμ² to *du_dmu2
 * (0 where μ² ≥ 1 and at μ² = 0). */
inline double pw85_lammps_energy(double mu2, double eps, double *du_dmu2)
{
  if (!(mu2 < 1.0)) {
    *du_dmu2 = 0.0;
    return 0.0;
  }
  const double mu = std::sqrt(mu2);
  const double gap = 1.0 - mu;
  *du_dmu2 = mu2 > 0.0 ? -eps * gap / mu : 0.0;
  return eps * gap * gap;
}

} // namespace pw85_lammps

#endif
