/* The soft-sphere contact laws as LAMMPS styles see them: a law's name and its five numbers
 * ("aa k_n e k_t eta_ratio mu", "hertz/aa E nu e eta_ratio mu"), the kernel's laws built and
 * checked through its C ABI, and clear ERRORs naming what the kernel rejects.
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS);
 * the kernel it calls is MIT OR Apache-2.0. */

#ifndef SOFT_SPHERE_LAW_H
#define SOFT_SPHERE_LAW_H

#include "soft_sphere.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;

namespace SoftSphere {

  /* The kernel's model code of a law's name; ERROR on an unknown one. */
  int model(LAMMPS *lmp, const std::string &style, const std::string &law);

  /* Whether a model is one of the Hertz-Mindlin laws (material form: E nu e eta_ratio mu). */
  bool hertz(int model);

  /* A law's name, as the input script writes it. */
  const char *law_name(int model);

  /* The five numbers after a law's name (arg[0] .. arg[4]) as kernel coefficients. */
  ss_coefficients_f64 coefficients(LAMMPS *lmp, int model, char **arg);

  /* The rolling resistance's three numbers (arg[0] .. arg[2]: mu_r k_r eta_r) into `c`. */
  void rolling(LAMMPS *lmp, ss_coefficients_f64 &c, char **arg);

  /* The one-law parameters of `model` with coefficients `c` for a contact between two bodies
   * of that material (Hertz: E* and G* of the material with itself); the time step, masses and
   * declared impact are filled in by build(). */
  ss_params_f64 params(LAMMPS *lmp, int model, const ss_coefficients_f64 &c);

  /* The kernel's law for `params` at time step `dt`, checked for contacts of effective mass
   * down to `smallest_effective_mass`. ERROR (on all ranks) naming the rejected parameter. */
  ss_law_f64 *build(LAMMPS *lmp, const std::string &style, ss_params_f64 params, double dt,
                    double smallest_effective_mass);

  /* `law` bound to its time step for this rank's loop over its contacts. Free it with
   * ss_bound_law_free_f64 before the law. */
  ss_bound_law_f64 *bind(LAMMPS *lmp, const std::string &style, const ss_law_f64 *law);

  /* What the atoms present on all ranks ask of a law table: the largest radius (0 when there
   * are no atoms), the smallest effective moment of inertia of a pair (half the
   * smallest 2/5 m R^2; 0 when there are no atoms) and the lightest atom of each of `types` kinds (0 for a kind
   * with no atoms; atom i's is `kind[i] - first`, or 0 with no `kind`). ERROR (on all ranks) when an atom's
   * radius or mass is not positive. Collective: every rank calls it at the same point. */
  struct Present {
    double largest_radius;
    double smallest_inertia;
    std::vector<double> lightest;

    /* The radius and inertia a law table is made for: the atoms', or any (1) with no atoms,
     * which the table checks nothing against. */
    double table_radius() const { return largest_radius > 0.0 ? largest_radius : 1.0; }
    double table_inertia() const { return smallest_inertia > 0.0 ? smallest_inertia : 1.0; }

    /* Whether a table made for `radius` and `inertia` (read only with `rolling`) must be made
     * again for these atoms: a larger one, or one of smaller inertia, has arrived. */
    bool outgrows(double radius, double inertia, bool rolling) const
    {
      return largest_radius > radius || (rolling && smallest_inertia < inertia);
    }
  };
  Present present(LAMMPS *lmp, const std::string &style, int types, const int *kind,
                  int first);

  /* ERROR unless the atom style carries what a contact law reads (radius, rmass, omega,
   * torque: atom_style sphere). */
  void require_spheres(LAMMPS *lmp, const std::string &style);

  /* What a parameter code names, for a law of `model` in the pair style (or the wall fix,
   * `wall`). */
  const char *parameter_name(int parameter, int model, bool wall = false);

  /* What a parameter error code means. */
  const char *parameter_error(int code);

  /* What a contact or list error code means. */
  const char *contact_error(int code);

}    // namespace SoftSphere
}    // namespace LAMMPS_NS

#endif
