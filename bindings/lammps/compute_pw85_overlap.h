/* SPDX-License-Identifier: BSD-3-Clause */
/* LAMMPS compute pw85/overlap: the number of pairs of ellipsoids of the
 * group that overlap, as pw85_overlap() decides it (result −1; tangent
 * pairs, within 4 ulps of μ² = 1, are not counted). A global scalar, the
 * same on every rank. Needs pair style pw85 (its cut-offs and neighbor
 * lists cover every pair whose bounding spheres meet).
 *
 *   compute ID group pw85/overlap
 */
#ifndef PW85_LAMMPS_COMPUTE_PW85_OVERLAP_H
#define PW85_LAMMPS_COMPUTE_PW85_OVERLAP_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePW85Overlap : public Compute {
 public:
  ComputePW85Overlap(class LAMMPS *, int, char **);
  ~ComputePW85Overlap() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  double compute_scalar() override;

 private:
  class NeighList *list;
  class AtomVecEllipsoid *avec;
};

}    // namespace LAMMPS_NS

#endif
