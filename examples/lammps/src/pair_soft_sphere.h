/* pair_style soft/sphere [LAW five-numbers [rolling mu_r k_r eta_r]] [impact V]: the
 * soft-sphere kernel's contact laws as a LAMMPS granular pair style, a law per pair of atom types.
 *
 *   pair_coeff I J LAW k_n e k_t eta_ratio mu     linear laws: aa, aa/luding, stateless,
 *                                                 frictionless
 *   pair_coeff I J LAW E nu e eta_ratio mu        Hertz-Mindlin laws: hertz/aa, hertz/aa/luding,
 *                                                 hertz/stateless, hertz/frictionless
 *   ... rolling mu_r k_r eta_r                    with the elastic-plastic rolling resistance
 *   pair_coeff * *                                the law given to pair_style
 *
 * I I gives type I's own coefficients; a pair of types not given its own gets the kernel's
 * mixing rule (geometric means; Hertz's E* and Mindlin's G* from both types' E and nu). One law
 * per pair style. The Hertz laws check the time step against the declared fastest impact
 * (impact V, m/s). The whole neighbour list goes to the kernel in one call per compute(); the
 * stored springs live in LAMMPS's per-pair history (fix neigh/history), so they follow atoms
 * across ranks, neighbour-list rebuilds and restart files.
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS). */

#ifndef LMP_PAIR_SOFT_SPHERE_H
#define LMP_PAIR_SOFT_SPHERE_H

#include "pair_gran_hooke_history.h"
#include "soft_sphere.h"
#include "soft_sphere_law.h"

#include <vector>

namespace LAMMPS_NS {

class PairSoftSphere : public PairGranHookeHistory {
 public:
  PairSoftSphere(class LAMMPS *);
  ~PairSoftSphere() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void setup() override;
  void reset_dt() override;
  double single(int, int, int, int, double, double, double, double &) override;
  void transfer_history(double *, double *) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;

  /* The law (SS_MODEL_*, -1 before any) and rolling resistance (SS_ROLLING_*) of this style,
   * and type t's own coefficients (pair_coeff t t, or the style's law for all), null when it
   * has none: what a wall of its own material mixes with. */
  int law() const { return model; }
  int law_rolling() const { return rolling; }
  const ss_coefficients_f64 *own(int t) const;

 private:
  int model;                           // the kernel's SS_MODEL_*, -1 before any law is given
  int style_law;                       // pair_style gave a law for pair_coeff * *
  int rolling;                         // SS_ROLLING_*, -1 before any law is given
  ss_coefficients_f64 style_coefficients;
  double impact_speed;                 // Hertz laws: the declared fastest impact (m/s)
  int coarse;                          // the step taken knowingly past the accuracy limit
  int warned_inaccurate;               // the coarse step's first inaccurate contacts reported
  std::vector<ss_coefficients_f64> coefficients;    // (ntypes + 1)^2, by type pair
  std::vector<int> given;                           // whether a type pair was given its own
  std::vector<int> owned;              // (ntypes + 1)^2: the type pairs this style evaluates
  int pending;                         // owned pairs known only after init_one: check at setup
  int history_made;                    // the history size the history fix was made with
  ss_table_f64 *table;
  double built_radius;                 // the largest radius the table was made for (0: no atoms)
  double built_inertia;                // the smallest inertia the table was made for
  std::vector<double> checked_lightest;    // per type, the masses the step was checked at
  std::vector<double> pair_force;      // per neighbour, for the virial

  void size_tables();
  ss_table_f64 *new_table(int materials, double largest_effective_radius, double inertia);
  void mix(const char *first, const char *second);
  void make_table(const SoftSphere::Present &now);
  void refresh(bool remake);
  void prepare(const std::vector<double> &lightest);
};

}    // namespace LAMMPS_NS

#endif
