/* SPDX-License-Identifier: BSD-3-Clause */
/* LAMMPS pair style pw85: the overlap energy of ellipsoids through the
 * exact contact function of Perram and Wertheim (libpw85), for
 * atom_style ellipsoid. docs/lammps.rst is its manual.
 *
 *   pair_style pw85 [cutoff]
 *   pair_coeff I J epsilon [cutoff]
 *
 * U = ε_IJ·(1 − μ)² for μ < 1 (pw85_lammps_energy.h); forces and torques
 * from pw85_contact_derivatives(). The cut-off of a pair of types is, by
 * default, the sum of the largest bounding radii (largest semi-axis) of
 * the ellipsoids of the two types; a cut-off given below it is refused
 * (it would miss overlapping pairs). Built against the headers of ONE
 * LAMMPS version (the per-atom record of ellipsoids changes between
 * versions): pw85_lammps.cpp refuses to register into another. */
#ifndef PW85_LAMMPS_PAIR_PW85_H
#define PW85_LAMMPS_PAIR_PW85_H

#include "pair.h"

namespace LAMMPS_NS {

class PairPW85 : public Pair {
 public:
  PairPW85(class LAMMPS *);
  ~PairPW85() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

 protected:
  double cut_global;    // the cut-off of pair_style; 0: from bounding spheres
  double **epsilon;     // ε per pair of types (energy)
  double **cut_user;    // the cut-off of pair_coeff; 0: cut_global
  double **cut;         // the cut-off in use (init_one)
  double *rbound_type;  // largest bounding radius of each type (init_style)
  double *forms;        // 6 doubles per atom, local and ghost: Q
  double *rbound;       // the bounding radius of each atom
  int nmax_forms;
  class AtomVecEllipsoid *avec;

  void allocate();
  void compute_forms();
};

}    // namespace LAMMPS_NS

#endif
