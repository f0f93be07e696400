/* The soft-sphere LAMMPS plugin: registers pair_style soft/sphere and fix wall/soft/sphere.
 * Load it with "plugin load softsphereplugin.so".
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS); the
 * soft-sphere kernel it calls is MIT OR Apache-2.0, which a LAMMPS user takes under MIT. */

#include "lammpsplugin.h"
#include "version.h"

#include "fix_wall_soft_sphere.h"
#include "pair_soft_sphere.h"

using namespace LAMMPS_NS;

static Pair *pair_creator(LAMMPS *lmp)
{
  return new PairSoftSphere(lmp);
}

static Fix *wall_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixWallSoftSphere(lmp, narg, arg);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;

  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "soft/sphere";
  plugin.info = "soft-sphere kernel contact laws per type pair (linear and Hertz-Mindlin: aa, aa/luding, stateless, frictionless)";
  plugin.author = "the soft-sphere developers";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "wall/soft/sphere";
  plugin.info = "flat walls with the soft-sphere kernel's contact laws";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &wall_creator;
  (*register_plugin)(&plugin, lmp);
}
