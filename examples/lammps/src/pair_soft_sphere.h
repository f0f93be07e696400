/* pair_style soft/sphere LAW k_n e k_t eta_ratio mu: the soft-sphere kernel's contact laws as a
 * LAMMPS granular pair style. The stored spring of aa and aa/luding lives in LAMMPS's own
 * per-pair history (fix neigh/history, through gran/hooke/history's machinery), so it follows
 * atoms across ranks and neighbour-list rebuilds; every contact is evaluated by the kernel.
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS). */

#ifndef LMP_PAIR_SOFT_SPHERE_H
#define LMP_PAIR_SOFT_SPHERE_H

#include "pair_gran_hooke_history.h"
#include "soft_sphere.h"

namespace LAMMPS_NS {

class PairSoftSphere : public PairGranHookeHistory {
 public:
  PairSoftSphere(class LAMMPS *);
  ~PairSoftSphere() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void init_style() override;
  double single(int, int, int, int, double, double, double, double &) override;

 private:
  ss_params_f64 params;
  ss_law_f64 *law;
  ss_bound_law_f64 *bound;    // the law bound to the run's step, for this rank's loop
};

}    // namespace LAMMPS_NS

#endif
