/* The soft-sphere contact law as LAMMPS styles see it: parsing of
 * "LAW k_n e k_t eta_ratio mu" and the checked construction of the kernel's law
 * through its C ABI, with a clear ERROR naming the parameter the kernel rejects.
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS);
 * the kernel it calls is MIT OR Apache-2.0. */

#ifndef SOFT_SPHERE_LAW_H
#define SOFT_SPHERE_LAW_H

#include "soft_sphere.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;

namespace SoftSphere {

  /* The law's parameters from five numbers after the law's name (arg[0] .. arg[5]);
   * the time step and mass are filled in by build(). ERROR on an unknown law. */
  ss_params_f64 parse(LAMMPS *lmp, const std::string &style, char **arg);

  /* The kernel's law for `params` at time step `dt`, checked for contacts of effective mass
   * down to `smallest_effective_mass`. ERROR (on all ranks) naming the rejected parameter. */
  ss_law_f64 *build(LAMMPS *lmp, const std::string &style, ss_params_f64 params, double dt,
                    double smallest_effective_mass);

  /* `law` bound to its time step for this rank's loop over its contacts (the kernel reuses
   * each pair's derived oscillator and the wall's check between calls). Free it with
   * ss_bound_law_free_f64 before the law. */
  ss_bound_law_f64 *bind(LAMMPS *lmp, const std::string &style, const ss_law_f64 *law);

  /* The smallest per-atom mass over all ranks (atom style sphere). */
  double smallest_mass(LAMMPS *lmp);

  /* What a contact error code means. */
  const char *contact_error(int code);

}    // namespace SoftSphere
}    // namespace LAMMPS_NS

#endif
