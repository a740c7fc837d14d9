// SPDX-License-Identifier: BSD-3-Clause
// Registration of pair style pw85 and compute pw85/overlap into a LAMMPS
// instance, two ways (docs/lammps.rst, "Loading"):
// - as a plugin of LAMMPS's PLUGIN package: `plugin load pw85_lammps.so`
//   calls lammpsplugin_init() with LAMMPS's own registration function;
// - into a LAMMPS without PLUGIN (Debian's lmp): pw85_lammps.py, run by
//   the PYTHON package, calls pw85_lammps_register(), which calls
//   lammpsplugin_init() with register_style() below, the part of PLUGIN's
//   registration that inserts a creator into the style maps.
// Either way the host must be the LAMMPS version whose headers this file
// was compiled with (the class layouts differ between versions): checked
// through lammps_version() of the host's C library interface.
#include "compute_pw85_overlap.h"
#include "pair_pw85.h"

#include "force.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "modify.h"
#include "version.h"

#include <pw85/pw85.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <dlfcn.h>

using namespace LAMMPS_NS;

namespace {

Pair *pair_creator(LAMMPS *lmp)
{
  return new PairPW85(lmp);
}

Compute *compute_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputePW85Overlap(lmp, narg, arg);
}

// The date of version.h ("29 Sep 2021") as LAMMPS numbers versions
// (20210929, lammps_version()); 0 if unreadable.
int compiled_version()
{
  struct tm t;
  std::memset(&t, 0, sizeof t);
  const char *end = strptime(LAMMPS_VERSION, "%d %b %Y", &t);
  if (end == nullptr || *end != '\0') return 0;
  return (t.tm_year + 1900) * 10000 + (t.tm_mon + 1) * 100 + t.tm_mday;
}

// The version of the host, from its C library interface (exported by
// liblammps.so and by an lmp linked with -rdynamic, as PLUGIN needs); -1
// when it cannot be found.
int host_version(void *lmp)
{
  using version_fn = int (*)(void *);
  auto fn = reinterpret_cast<version_fn>(dlsym(RTLD_DEFAULT, "lammps_version"));
  return fn ? fn(lmp) : -1;
}

char last_error[512];

// Insert the creator into the style maps (what PLUGIN's plugin_register()
// does, without its list of loaded plugins).
void register_style(lammpsplugin_t *plugin, void *ptr)
{
  auto *lmp = static_cast<LAMMPS *>(ptr);
  if (std::strcmp(plugin->style, "pair") == 0)
    (*lmp->force->pair_map)[plugin->name] = reinterpret_cast<Force::PairCreator>(plugin->creator.v1);
  else if (std::strcmp(plugin->style, "compute") == 0)
    (*lmp->modify->compute_map)[plugin->name] =
        reinterpret_cast<Modify::ComputeCreator>(plugin->creator.v2);
}

}    // namespace

extern "C" {

// PLUGIN's entry point. On a version mismatch it registers nothing, and
// says why on stderr and in pw85_lammps_error().
__attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle,
                                                              void *regfunc)
{
  const int want = compiled_version(), have = host_version(lmp);
  if (have != -1 && have != want) {
    std::snprintf(last_error, sizeof last_error,
                  "pw85_lammps was built with the headers of LAMMPS %d (%s), not loaded into "
                  "LAMMPS %d: rebuild it against this LAMMPS's headers",
                  want, LAMMPS_VERSION, have);
    std::fprintf(stderr, "ERROR: %s\n", last_error);
    return;
  }
  last_error[0] = '\0';
  auto reg = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  lammpsplugin_t plugin;
  std::memset(&plugin, 0, sizeof plugin);
  plugin.version = LAMMPS_VERSION;
  plugin.author = "pw85 developers";
  plugin.handle = handle;

  plugin.style = "pair";
  plugin.name = "pw85";
  plugin.info = "pw85: overlap energy of ellipsoids from the exact contact function";
  plugin.creator.v1 = reinterpret_cast<lammpsplugin_factory1 *>(&pair_creator);
  reg(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "pw85/overlap";
  plugin.info = "pw85/overlap: the number of overlapping pairs of ellipsoids (pw85_overlap)";
  plugin.creator.v2 = reinterpret_cast<lammpsplugin_factory2 *>(&compute_creator);
  reg(&plugin, lmp);
}

// For a LAMMPS without PLUGIN: registers pair style pw85 and compute
// pw85/overlap into the instance lmp (a LAMMPS_NS::LAMMPS *). Returns 0,
// or 1 with the cause in pw85_lammps_error() (version mismatch, NULL).
__attribute__((visibility("default"))) int pw85_lammps_register(void *lmp)
{
  if (lmp == nullptr) {
    std::snprintf(last_error, sizeof last_error, "pw85_lammps_register: no LAMMPS instance");
    return 1;
  }
  lammpsplugin_init(lmp, nullptr, reinterpret_cast<void *>(&register_style));
  return last_error[0] != '\0';
}

// The cause of the last failed registration ("" if none).
__attribute__((visibility("default"))) const char *pw85_lammps_error(void)
{
  return last_error;
}

// The version of LAMMPS whose headers this was built with, and of libpw85.
__attribute__((visibility("default"))) const char *pw85_lammps_built_for(void)
{
#ifdef LAMMPS_UPDATE
  return LAMMPS_VERSION " " LAMMPS_UPDATE;
#else
  return LAMMPS_VERSION;
#endif
}

}    // extern "C"
