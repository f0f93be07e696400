/* fix ID GROUP wall/soft/sphere LAW five-numbers [impact V] {x,y,z}plane LO HI: flat walls at
 * LO and HI (either may be NULL) that act on the group's spheres with the soft-sphere kernel's
 * law: a linear law (k_n e k_t eta_ratio mu) or a Hertz-Mindlin law (E nu e eta_ratio mu; the
 * wall is of the same material as the spheres, as LAMMPS's fix wall/gran takes it, and impact V
 * declares the fastest impact the time step is checked for). Each sphere's stored spring
 * against each wall is per-atom state of this fix, so it follows the atom between ranks and
 * into restart files (define the fix again, with the same ID, after read_restart).
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS). */

#ifndef LMP_FIX_WALL_SOFT_SPHERE_H
#define LMP_FIX_WALL_SOFT_SPHERE_H

#include "fix.h"
#include "soft_sphere.h"

namespace LAMMPS_NS {

class FixWallSoftSphere : public Fix {
 public:
  FixWallSoftSphere(class LAMMPS *, int, char **);
  ~FixWallSoftSphere() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 private:
  static constexpr int WALLS = 2;    // LO and HI
  static constexpr int STATE = 7;    // an ss_state_f64: displacement, spring force, radius
  static constexpr int VALUES = STATE * WALLS;
  ss_params_f64 params;
  ss_law_f64 *law;
  ss_bound_law_f64 *bound;    // the law bound to the run's step, for this rank's loop
  int axis;              // 0, 1, 2 for xplane, yplane, zplane
  int present[WALLS];    // whether LO and HI exist
  double position[WALLS];
  double impact_speed;   // Hertz laws: the declared fastest impact (m/s)
  double **history;      // per atom: the stored state against LO, then HI
  bool advance;

  void forces();
};

}    // namespace LAMMPS_NS

#endif
