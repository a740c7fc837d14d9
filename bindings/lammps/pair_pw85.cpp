// SPDX-License-Identifier: BSD-3-Clause
// Pair style pw85 (pair_pw85.h; manual: docs/lammps.rst).
#include "pair_pw85.h"

#include "atom.h"
#include "atom_vec_ellipsoid.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "utils.h"

#include <pw85/pw85.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>
#include <mpi.h>

#include "pw85_lammps_energy.h"

using namespace LAMMPS_NS;

PairPW85::PairPW85(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 0;      // the energy is not a function of r alone
  restartinfo = 0;
  one_coeff = 0;
  cut_global = 0.0;
  epsilon = cut_user = cut = nullptr;
  rbound_type = nullptr;
  forms = rbound = nullptr;
  nmax_forms = 0;
  avec = nullptr;
  // compute pair pw85: c_ID[1], the calls of pw85_contact_derivatives()
  // since the pair style was defined (all ranks); c_ID[2], the pairs with
  // μ² < 1 at the last evaluation of forces.
  nextra = 2;
  pvector = new double[nextra];
  pvector[0] = pvector[1] = 0.0;
}

PairPW85::~PairPW85()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(epsilon);
    memory->destroy(cut_user);
    memory->destroy(cut);
    memory->destroy(rbound_type);
  }
  memory->destroy(forms);
  memory->destroy(rbound);
  delete[] pvector;
}

void PairPW85::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(epsilon, n + 1, n + 1, "pair:epsilon");
  memory->create(cut_user, n + 1, n + 1, "pair:cut_user");
  memory->create(cut, n + 1, n + 1, "pair:cut");
  memory->create(rbound_type, n + 1, "pair:rbound_type");
  for (int i = 0; i <= n; i++) {
    rbound_type[i] = 0.0;
    for (int j = 0; j <= n; j++) {
      setflag[i][j] = 0;
      epsilon[i][j] = cut_user[i][j] = cut[i][j] = cutsq[i][j] = 0.0;
    }
  }
}

// pair_style pw85 [cutoff]
void PairPW85::settings(int narg, char **arg)
{
  if (narg > 1) error->all(FLERR, "Illegal pair_style pw85 command: pair_style pw85 [cutoff]");
  cut_global = 0.0;
  if (narg == 1) {
    cut_global = utils::numeric(FLERR, arg[0], false, lmp);
    if (!(cut_global > 0.0))
      error->all(FLERR, "pair_style pw85: the cut-off must be > 0 (omit it for the bounding spheres)");
  }
}

// pair_coeff I J epsilon [cutoff]
void PairPW85::coeff(int narg, char **arg)
{
  if (narg < 3 || narg > 4)
    error->all(FLERR, "Incorrect args for pair coefficients: pair_coeff I J epsilon [cutoff]");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double eps = utils::numeric(FLERR, arg[2], false, lmp);
  if (!(eps >= 0.0) || !std::isfinite(eps))
    error->all(FLERR, "pair_coeff pw85: epsilon must be finite and >= 0");
  double cut_one = 0.0;
  if (narg == 4) {
    cut_one = utils::numeric(FLERR, arg[3], false, lmp);
    if (!(cut_one > 0.0)) error->all(FLERR, "pair_coeff pw85: the cut-off must be > 0");
  }
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      epsilon[i][j] = eps;
      cut_user[i][j] = cut_one;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

void PairPW85::init_style()
{
  avec = dynamic_cast<AtomVecEllipsoid *>(atom->style_match("ellipsoid"));
  if (!avec) error->all(FLERR, "Pair style pw85 requires atom style ellipsoid");
  if (!atom->torque_flag) error->all(FLERR, "Pair style pw85 requires atoms with torques");
  neighbor->request(this, instance_me);

  // The largest bounding radius (semi-axis) of each type, over all ranks;
  // an atom without a shape is refused here, before any force.
  const int n = atom->ntypes;
  std::vector<double> mine(n + 1, 0.0);
  const int *ellipsoid = atom->ellipsoid;
  const int *type = atom->type;
  tagint bad = 0;    // the largest tag of an atom without a shape
  for (int i = 0; i < atom->nlocal; i++) {
    if (ellipsoid[i] < 0) {
      bad = std::max(bad, atom->tag[i]);
      continue;
    }
    const double *a = avec->bonus[ellipsoid[i]].shape;
    mine[type[i]] = std::max(mine[type[i]], std::max(a[0], std::max(a[1], a[2])));
  }
  tagint anybad = 0;
  MPI_Allreduce(&bad, &anybad, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (anybad)
    error->all(FLERR, "Pair style pw85: atom {} is not an ellipsoid (no shape; set shape)",
               anybad);
  MPI_Allreduce(mine.data(), rbound_type, n + 1, MPI_DOUBLE, MPI_MAX, world);
}

double PairPW85::init_one(int i, int j)
{
  if (setflag[i][j] == 0) {
    // Not given: ε mixed from the pure types (mix_energy() with σ = 1 gives
    // √(ε_I·ε_J) for every pair_modify mix rule) and the cut-off of
    // pair_style.
    if (setflag[i][i] == 0 || setflag[j][j] == 0)
      error->all(FLERR, "Pair pw85: pair_coeff {} {} missing (and not mixable)", i, j);
    epsilon[i][j] = mix_energy(epsilon[i][i], epsilon[j][j], 1.0, 1.0);
    cut_user[i][j] = 0.0;
  }
  // Bounding spheres: ellipsoids whose centres are rbound_i + rbound_j or
  // more apart are disjoint (μ ≥ 1, U = 0).
  const double need = rbound_type[i] + rbound_type[j];
  double c = cut_user[i][j] > 0.0 ? cut_user[i][j] : cut_global;
  if (c > 0.0) {
    if (c < need)
      error->all(FLERR,
                 "Pair pw85: the cut-off {} of types {} {} misses overlapping pairs: "
                 "their bounding spheres need {} (omit the cut-off to use it)",
                 c, i, j, need);
  } else {
    c = need;
  }
  cut[i][j] = c;
  // A type without atoms: no pairs, but a cut-off > 0 for the neighbor lists.
  if (!(cut[i][j] > 0.0)) cut[i][j] = 1e-300;
  epsilon[j][i] = epsilon[i][j];
  cut_user[j][i] = cut_user[i][j];
  cut[j][i] = cut[i][j];
  return cut[i][j];
}

// Q = R(p)·diag(a²)·R(p)ᵀ of every local and ghost ellipsoid, and its
// bounding radius (its largest semi-axis).
void PairPW85::compute_forms()
{
  const int nall = atom->nlocal + atom->nghost;
  if (nall > nmax_forms) {
    nmax_forms = atom->nmax;
    memory->destroy(forms);
    memory->destroy(rbound);
    memory->create(forms, 6 * nmax_forms, "pair:forms");
    memory->create(rbound, nmax_forms, "pair:rbound");
  }
  const int *ellipsoid = atom->ellipsoid;
  const int *type = atom->type;
  const AtomVecEllipsoid::Bonus *bonus = avec->bonus;
  for (int i = 0; i < nall; i++) {
    if (ellipsoid[i] < 0)
      error->one(FLERR, "Pair style pw85: atom {} is not an ellipsoid (no shape)", atom->tag[i]);
    const double *a = bonus[ellipsoid[i]].shape;
    const double *p = bonus[ellipsoid[i]].quat;    // (w, x, y, z), as pw85's
    const int status = pw85_ellipsoid_quaternion(a, p, forms + 6 * i);
    if (status != PW85_SUCCESS)
      error->one(FLERR,
                 "Pair style pw85: atom {}: shape ({} {} {}) and quaternion ({} {} {} {}) "
                 "give no ellipsoid: {}",
                 atom->tag[i], a[0], a[1], a[2], p[0], p[1], p[2], p[3], pw85_strerror(status));
    rbound[i] = std::max(a[0], std::max(a[1], a[2]));
    if (rbound[i] > rbound_type[type[i]])
      error->one(FLERR,
                 "Pair style pw85: atom {} grew beyond the cut-off set at the start "
                 "of the run (bounding radius {} > {})",
                 atom->tag[i], rbound[i], rbound_type[type[i]]);
  }
}

void PairPW85::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  compute_forms();

  double **x = atom->x;
  double **f = atom->f;
  double **tor = atom->torque;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double *special_lj = force->special_lj;

  double calls = 0.0, overlapping = 0.0;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      const double factor = special_lj[sbmask(j)];
      j &= NEIGHMASK;
      const int jtype = type[j];
      // Ellipsoid 1 is i, ellipsoid 2 is j: r12 = c2 − c1.
      const double r12[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double rsq = r12[0] * r12[0] + r12[1] * r12[1] + r12[2] * r12[2];
      if (rsq >= cutsq[itype][jtype]) continue;
      const double rb = rbound[i] + rbound[j];
      if (rsq >= rb * rb) continue;    // bounding spheres apart: μ ≥ 1

      double geom[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
      const int status = pw85_contact_derivatives(r12, forms + 6 * i, forms + 6 * j, geom, d);
      if (status != PW85_SUCCESS)
        error->one(FLERR, "Pair style pw85: atoms {} {}: pw85_contact_derivatives: {}",
                   atom->tag[i], atom->tag[j], pw85_strerror(status));
      calls += 1.0;
      const double mu2 = geom[PW85_GEOM_MU2];
      if (!(mu2 < 1.0)) continue;
      // With newton off, a pair across ranks is computed on both.
      overlapping += (newton_pair || j < nlocal) ? 1.0 : 0.5;
      double du;
      const double u = factor * pw85_lammps::pw85_lammps_energy(mu2, epsilon[itype][jtype], &du);
      du *= factor;
      // pw85.h, pw85_contact_derivatives(): the force on 2 is −U′·g, that
      // on 1 is +U′·g (g = ∂μ²/∂r12); the torque on k is −U′·∂μ²/∂ωk.
      const double *g = d + PW85_DERIV_R12;
      const double fi[3] = {du * g[0], du * g[1], du * g[2]};
      f[i][0] += fi[0];
      f[i][1] += fi[1];
      f[i][2] += fi[2];
      tor[i][0] -= du * d[PW85_DERIV_ROT1 + 0];
      tor[i][1] -= du * d[PW85_DERIV_ROT1 + 1];
      tor[i][2] -= du * d[PW85_DERIV_ROT1 + 2];
      if (newton_pair || j < nlocal) {
        f[j][0] -= fi[0];
        f[j][1] -= fi[1];
        f[j][2] -= fi[2];
        tor[j][0] -= du * d[PW85_DERIV_ROT2 + 0];
        tor[j][1] -= du * d[PW85_DERIV_ROT2 + 1];
        tor[j][2] -= du * d[PW85_DERIV_ROT2 + 2];
      }
      // Virial: the force on i times x_i − x_j = −r12.
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair, u, 0.0, fi[0], fi[1], fi[2], -r12[0], -r12[1],
                     -r12[2]);
    }
  }
  if (vflag_fdotr) virial_fdotr_compute();
  pvector[0] += calls;
  pvector[1] = overlapping;
}

void *PairPW85::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "epsilon") == 0) return (void *) epsilon;
  return nullptr;
}

double PairPW85::memory_usage()
{
  return Pair::memory_usage() + 7.0 * nmax_forms * sizeof(double);
}
