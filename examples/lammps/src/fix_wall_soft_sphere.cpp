/* Part of the soft-sphere LAMMPS plugin; see fix_wall_soft_sphere.h. */

#include "fix_wall_soft_sphere.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "soft_sphere_law.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

FixWallSoftSphere::FixWallSoftSphere(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), law(nullptr), bound(nullptr), impact_speed(0.0), history(nullptr),
    advance(true)
{
  const std::string style = "fix wall/soft/sphere";
  const int with_impact = narg == 14 && std::strcmp(arg[9], "impact") == 0;
  if (narg != 12 && !with_impact)
    error->all(FLERR,
               "Illegal fix wall/soft/sphere command: expected LAW and five numbers, "
               "[impact V], xplane|yplane|zplane LO HI");
  if (!atom->sphere_flag) error->all(FLERR, "fix wall/soft/sphere requires atom style sphere");
  const int model = SoftSphere::model(lmp, style, arg[3]);
  params = SoftSphere::params(lmp, model, SoftSphere::coefficients(lmp, model, &arg[4]));
  if (with_impact) impact_speed = utils::numeric(FLERR, arg[10], false, lmp);
  if (SoftSphere::hertz(model) && !with_impact)
    error->all(FLERR,
               "{}: the Hertz laws check the time step against the fastest impact: give it as "
               "impact V (m/s) after the law's numbers",
               style);
  params.largest_impact_speed = impact_speed;
  params.largest_effective_radius = 1.0;
  arg += 2 * with_impact;
  const std::string plane = arg[9];
  if (plane == "xplane")
    axis = 0;
  else if (plane == "yplane")
    axis = 1;
  else if (plane == "zplane")
    axis = 2;
  else
    error->all(FLERR, "{}: unknown wall '{}' (xplane, yplane or zplane)", style, plane);
  for (int w = 0; w < WALLS; w++) {
    const char *value = arg[10 + w];
    present[w] = std::strcmp(value, "NULL") != 0;
    position[w] = present[w] ? utils::numeric(FLERR, value, false, lmp) : 0.0;
  }
  if (!present[0] && !present[1]) error->all(FLERR, "{}: both walls are NULL", style);
  if (present[0] && present[1] && position[0] >= position[1])
    error->all(FLERR, "{}: LO must lie below HI", style);

  // The kernel checks the law here already (with a placeholder step), so a bad parameter
  // stops the input script at this command.
  ss_law_free_f64(SoftSphere::build(lmp, style, params, 1e-300, 1.0));

  force_reneighbor = 0;
  maxexchange = VALUES;
  restart_peratom = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixWallSoftSphere::~FixWallSoftSphere()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(history);
  ss_bound_law_free_f64(bound);
  ss_law_free_f64(law);
}

int FixWallSoftSphere::setmask()
{
  return POST_FORCE;
}

void FixWallSoftSphere::init()
{
  // A sphere against a wall has its own mass as effective mass, and its radius as R*.
  params.largest_effective_radius = SoftSphere::largest_radius(lmp);
  ss_bound_law_free_f64(bound);
  ss_law_free_f64(law);
  bound = nullptr;
  law = nullptr;
  law = SoftSphere::build(lmp, "fix wall/soft/sphere", params, update->dt,
                          SoftSphere::smallest_mass(lmp));
  bound = SoftSphere::bind(lmp, "fix wall/soft/sphere", law);
}

void FixWallSoftSphere::setup(int)
{
  // Forces for the first step; the history advances from the first step on.
  advance = false;
  forces();
  advance = true;
}

void FixWallSoftSphere::post_force(int)
{
  forces();
}

void FixWallSoftSphere::forces()
{
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  // One wall at a time, so the bound law checks each wall once per step; each atom still
  // receives LO's force before HI's.
  for (int w = 0; w < WALLS; w++) {
    if (!present[w]) continue;
    const double outward = w == 0 ? 1.0 : -1.0;
    ss_wall_f64 wall;
    std::memset(&wall, 0, sizeof(wall));
    (&wall.point.x)[axis] = position[w];
    (&wall.normal.x)[axis] = outward;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      double *stored = &history[i][STATE * w];
      // Apart (the kernel's own test: the distance from the plane is at least the radius):
      // the kernel would reset the stored spring the same way. A position that is not finite
      // goes on to the kernel, which refuses it.
      const double distance = outward * (x[i][axis] - position[w]);
      if (distance >= radius[i] && std::isfinite(distance)) {
        if (advance)
          for (int m = 0; m < STATE; m++) stored[m] = 0.0;
        continue;
      }
      ss_sphere_f64 s;
      s.position = {x[i][0], x[i][1], x[i][2]};
      s.velocity = {v[i][0], v[i][1], v[i][2]};
      s.angular_velocity = {omega[i][0], omega[i][1], omega[i][2]};
      s.radius = radius[i];
      s.mass = atom->rmass[i];
      ss_state_f64 state;
      state.displacement = {stored[0], stored[1], stored[2]};
      state.spring_force = {stored[3], stored[4], stored[5]};
      state.contact_radius = stored[6];
      ss_forces_f64 out;
      const int code = ss_bound_sphere_wall_f64(bound, &s, &wall, &state, &out);
      if (code != SS_OK)
        error->one(FLERR, "fix wall/soft/sphere: atom {} against the wall: {}", atom->tag[i],
                   SoftSphere::contact_error(code));
      if (advance) {
        const double kept[STATE] = {state.displacement.x, state.displacement.y,
                                    state.displacement.z, state.spring_force.x,
                                    state.spring_force.y, state.spring_force.z,
                                    state.contact_radius};
        for (int m = 0; m < STATE; m++) stored[m] = kept[m];
      }
      if (!out.touching) continue;
      // The C ABI reports what the sphere receives as the force and torque on j.
      f[i][0] += out.force_on_j.x;
      f[i][1] += out.force_on_j.y;
      f[i][2] += out.force_on_j.z;
      torque[i][0] += out.torque_on_j.x;
      torque[i][1] += out.torque_on_j.y;
      torque[i][2] += out.torque_on_j.z;
    }
  }
}

double FixWallSoftSphere::memory_usage()
{
  return (double) atom->nmax * VALUES * sizeof(double);
}

void FixWallSoftSphere::grow_arrays(int nmax)
{
  memory->grow(history, nmax, VALUES, "wall/soft/sphere:history");
}

void FixWallSoftSphere::copy_arrays(int i, int j, int)
{
  for (int m = 0; m < VALUES; m++) history[j][m] = history[i][m];
}

void FixWallSoftSphere::set_arrays(int i)
{
  for (int m = 0; m < VALUES; m++) history[i][m] = 0.0;
}

int FixWallSoftSphere::pack_exchange(int i, double *buf)
{
  for (int m = 0; m < VALUES; m++) buf[m] = history[i][m];
  return VALUES;
}

int FixWallSoftSphere::unpack_exchange(int nlocal, double *buf)
{
  for (int m = 0; m < VALUES; m++) history[nlocal][m] = buf[m];
  return VALUES;
}

/* Restart files: each atom's stored states, behind their count (LAMMPS's per-atom layout). */
int FixWallSoftSphere::pack_restart(int i, double *buf)
{
  buf[0] = VALUES + 1;
  for (int m = 0; m < VALUES; m++) buf[m + 1] = history[i][m];
  return VALUES + 1;
}

void FixWallSoftSphere::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  // Skip the values of the fixes stored before this one.
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int v = 0; v < VALUES; v++) history[nlocal][v] = extra[nlocal][m++];
}

int FixWallSoftSphere::size_restart(int)
{
  return VALUES + 1;
}

int FixWallSoftSphere::maxsize_restart()
{
  return VALUES + 1;
}
