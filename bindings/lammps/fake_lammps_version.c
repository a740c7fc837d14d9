/* SPDX-License-Identifier: BSD-3-Clause */
/* For test_lammps.py (errors): preloaded into lmp, makes the host answer
 * lammps_version() with another version than the headers pw85_lammps.so
 * was built with, so that its refusal to load is tested. */
int lammps_version(void *lmp);

int lammps_version(void *lmp)
{
  (void) lmp;
  return 20230802;
}
