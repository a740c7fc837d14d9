// SPDX-License-Identifier: BSD-3-Clause
// Compute pw85/overlap (compute_pw85_overlap.h; manual: docs/lammps.rst).
#include "compute_pw85_overlap.h"

#include "atom.h"
#include "atom_vec_ellipsoid.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <pw85/pw85.h>

#include <algorithm>
#include <mpi.h>

using namespace LAMMPS_NS;

ComputePW85Overlap::ComputePW85Overlap(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), list(nullptr), avec(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal compute pw85/overlap command: compute ID group pw85/overlap");
  scalar_flag = 1;
  extscalar = 0;    // a count of pairs, not divided by the number of atoms
}

ComputePW85Overlap::~ComputePW85Overlap() = default;

void ComputePW85Overlap::init()
{
  avec = dynamic_cast<AtomVecEllipsoid *>(atom->style_match("ellipsoid"));
  if (!avec) error->all(FLERR, "Compute pw85/overlap requires atom style ellipsoid");
  if (force->pair == nullptr || force->pair_match("pw85", 1, 0) == nullptr)
    error->all(FLERR,
               "Compute pw85/overlap requires pair style pw85 (its cut-offs cover every pair "
               "whose bounding spheres meet)");
  const int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->compute = 1;
  neighbor->requests[irequest]->occasional = 1;
}

void ComputePW85Overlap::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

double ComputePW85Overlap::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  neighbor->build_one(list);

  double **x = atom->x;
  const int *mask = atom->mask;
  const int *ellipsoid = atom->ellipsoid;
  const AtomVecEllipsoid::Bonus *bonus = avec->bonus;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  double count = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      if (ellipsoid[i] < 0 || ellipsoid[j] < 0)
        error->one(FLERR, "Compute pw85/overlap: atom {} is not an ellipsoid (no shape)",
                   atom->tag[ellipsoid[i] < 0 ? i : j]);
      const double *ai = bonus[ellipsoid[i]].shape, *aj = bonus[ellipsoid[j]].shape;
      const double r12[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      // Bounding spheres apart: disjoint.
      const double rb = std::max(ai[0], std::max(ai[1], ai[2])) +
          std::max(aj[0], std::max(aj[1], aj[2]));
      if (r12[0] * r12[0] + r12[1] * r12[1] + r12[2] * r12[2] >= rb * rb) continue;
      double qi[6], qj[6];
      int status = pw85_ellipsoid_quaternion(ai, bonus[ellipsoid[i]].quat, qi);
      if (status == PW85_SUCCESS)
        status = pw85_ellipsoid_quaternion(aj, bonus[ellipsoid[j]].quat, qj);
      int result = 1;
      if (status == PW85_SUCCESS) status = pw85_overlap(r12, qi, qj, &result);
      if (status != PW85_SUCCESS)
        error->one(FLERR, "Compute pw85/overlap: atoms {} {}: {}", atom->tag[i], atom->tag[j],
                   pw85_strerror(status));
      // A half list: with newton off, a pair across ranks is on both.
      if (result < 0) count += (newton_pair || j < nlocal) ? 1.0 : 0.5;
    }
  }
  MPI_Allreduce(&count, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  return scalar;
}
