/* Part of the soft-sphere LAMMPS plugin; see pair_soft_sphere.h. */

#include "pair_soft_sphere.h"

#include "atom.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "soft_sphere_law.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

PairSoftSphere::PairSoftSphere(LAMMPS *lmp) : PairGranHookeHistory(lmp), law(nullptr), bound(nullptr)
{
  single_enable = 0;
}

PairSoftSphere::~PairSoftSphere()
{
  ss_bound_law_free_f64(bound);
  ss_law_free_f64(law);
}

void PairSoftSphere::settings(int narg, char **arg)
{
  if (narg != 6)
    error->all(FLERR, "Illegal pair_style soft/sphere command: expected LAW k_n e k_t eta_ratio mu");
  params = SoftSphere::parse(lmp, "pair_style soft/sphere", arg);
  // The base class's fields, for what it reports and writes; the forces come from the kernel.
  kn = params.normal_stiffness;
  kt = params.tangential_stiffness;
  gamman = gammat = 0.0;
  xmu = params.friction;
  dampflag = 1;
  limit_damping = 0;
}

void PairSoftSphere::init_style()
{
  PairGranHookeHistory::init_style();
  // The lightest pair of atoms has the smallest effective mass, m/2.
  const double pair_mass = 0.5 * SoftSphere::smallest_mass(lmp);
  ss_bound_law_free_f64(bound);
  ss_law_free_f64(law);
  bound = nullptr;
  law = nullptr;
  law = SoftSphere::build(lmp, "pair_style soft/sphere", params, update->dt, pair_mass);
  bound = SoftSphere::bind(lmp, "pair_style soft/sphere", law);
}

static ss_sphere_f64 sphere_of(Atom *atom, int i, const double *position)
{
  ss_sphere_f64 s;
  s.position = {position[0], position[1], position[2]};
  s.velocity = {atom->v[i][0], atom->v[i][1], atom->v[i][2]};
  s.angular_velocity = {atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]};
  s.radius = atom->radius[i];
  s.mass = atom->rmass[i];
  return s;
}

void PairSoftSphere::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // The setup evaluation (before the first step) gives forces without advancing the history.
  const bool advance = !update->setupflag;

  double **x = atom->x;
  double **f = atom->f;
  double **torque = atom->torque;
  double *radius = atom->radius;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  int **firsttouch = fix_history->firstflag;
  double **firstshear = fix_history->firstvalue;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int *touch = firsttouch[i];
    double *allshear = firstshear[i];
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    const ss_sphere_f64 sphere_i = sphere_of(atom, i, x[i]);

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double *shear = &allshear[3 * jj];
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radius[i] + radius[j];
      if (rsq >= radsum * radsum) {
        // Apart: the kernel would reset the state the same way.
        touch[jj] = 0;
        shear[0] = shear[1] = shear[2] = 0.0;
        continue;
      }
      const ss_sphere_f64 sphere_j = sphere_of(atom, j, x[j]);
      ss_state_f64 state;
      state.displacement = {shear[0], shear[1], shear[2]};
      ss_forces_f64 out;
      const int code = ss_bound_sphere_sphere_f64(bound, &sphere_i, &sphere_j, &state, &out);
      if (code != SS_OK)
        error->one(FLERR, "pair_style soft/sphere: contact of atoms {} and {}: {}",
                   atom->tag[i], atom->tag[j], SoftSphere::contact_error(code));
      touch[jj] = 1;
      if (advance) {
        shear[0] = state.displacement.x;
        shear[1] = state.displacement.y;
        shear[2] = state.displacement.z;
      }
      // The kernel's force acts on j; i receives its negative.
      const double fx = -out.force_on_j.x, fy = -out.force_on_j.y, fz = -out.force_on_j.z;
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      torque[i][0] += out.torque_on_i.x;
      torque[i][1] += out.torque_on_i.y;
      torque[i][2] += out.torque_on_i.z;
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        torque[j][0] += out.torque_on_j.x;
        torque[j][1] += out.torque_on_j.y;
        torque[j][2] += out.torque_on_j.z;
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
}

double PairSoftSphere::single(int, int, int, int, double, double, double, double &)
{
  error->all(FLERR, "pair_style soft/sphere does not support single()");
  return 0.0;
}
