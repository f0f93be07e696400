/* fix ID GROUP wall/soft/sphere LAW five-numbers [rolling mu_r k_r eta_r] [impact V] [coarse]
 *     {x,y,z}plane LO HI | zcylinder R   [wiggle DIM A PERIOD | shear DIM V]
 * Flat walls at LO and HI (either may be NULL), or the inside of a cylinder of radius R about the
 * z axis (turning when sheared along x or y), that act on the group's spheres with the
 * soft-sphere kernel's law: a linear law (k_n e k_t eta_ratio mu) or a Hertz-Mindlin law (E nu e
 * eta_ratio mu; impact V declares the fastest impact the time step is checked for), with the
 * elastic-plastic rolling resistance when asked. The five numbers are the wall's own material:
 * under pair_style soft/sphere of the same law (and rolling resistance alike) each atom type
 * meets the wall by the kernel's mixing rule, as a pair of types of the pair style's
 * coefficients with the wall's would; otherwise every atom meets the wall with the wall's law
 * (the spheres taken of the wall's material, as LAMMPS's fix wall/gran does). The walls go to the kernel's list seam in one
 * call per step (the C ABI's walls entry). Each sphere's stored spring against each wall is
 * per-atom state of this fix, so it follows the atom between ranks and into restart files
 * (define the fix again, with the same ID, after read_restart).
 *
 * Part of the soft-sphere LAMMPS plugin. License: GPL-2.0-or-later (it links LAMMPS). */

#ifndef LMP_FIX_WALL_SOFT_SPHERE_H
#define LMP_FIX_WALL_SOFT_SPHERE_H

#include "fix.h"
#include "soft_sphere.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallSoftSphere : public Fix {
 public:
  FixWallSoftSphere(class LAMMPS *, int, char **);
  ~FixWallSoftSphere() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void reset_dt() override;
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
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  static constexpr int WALLS = 2;    // LO and HI (a zcylinder: the first only)
  enum { NONE, WIGGLE, SHEAR };
  static constexpr int STATE = 7;    // the most numbers a law keeps per contact
  static constexpr int VALUES = STATE * WALLS;
  int model;                          // SS_MODEL_*
  int rolling;                        // SS_ROLLING_*
  ss_coefficients_f64 coefficients;    // the law of a sphere with the wall
  ss_table_f64 *table;                 // one material: the spheres' and the walls'
  int axis;              // 0, 1, 2 for xplane, yplane, zplane
  int present[WALLS];    // whether LO and HI exist
  double position[WALLS];
  int motion;            // NONE, WIGGLE or SHEAR (keywords wiggle and shear)
  int motion_axis;       // the direction the walls move in
  double amplitude;      // wiggle: amplitude (m) and angular frequency (rad/s)
  double omega;
  double shear_speed;    // shear: the walls' speed (m/s)
  bigint time_origin;    // the step the wiggle starts from (kept in restart files)
  bool cylinder;         // zcylinder: one wall, the inside of a cylinder about the z axis
  double cylinder_radius;
  double impact_speed;   // Hertz laws: the declared fastest impact (m/s)
  bool coarse;           // the step taken knowingly past the accuracy limit
  bool warned_inaccurate;    // the coarse step's first inaccurate contacts reported
  double **history;      // per atom: the stored state against LO, then HI
  std::vector<int> material;    // zeros: every atom is of the table's first material
  int types;             // the table's sphere materials: the atom types, or 1 (then the wall)
  int mixed;             // each atom type meets the wall by the pair style's coefficients
  bool advance;
  double built_radius;    // the largest radius the table was made for (0: no atoms)
  double built_inertia;   // the smallest inertia the table was made for
  std::vector<double> checked_lightest;    // per sphere material, the masses the step was checked at
  void refresh(bool remake);

  void forces();
  void motion_of(const std::string &style, int k, int narg, char **arg);
  ss_table_f64 *new_table(double largest_radius, double inertia);
};

}    // namespace LAMMPS_NS

#endif
