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
    Fix(lmp, narg, arg), law(nullptr), bound(nullptr), history(nullptr), advance(true)
{
  const std::string style = "fix wall/soft/sphere";
  if (narg != 12)
    error->all(FLERR,
               "Illegal fix wall/soft/sphere command: expected LAW k_n e k_t eta_ratio mu "
               "xplane|yplane|zplane LO HI");
  if (!atom->sphere_flag) error->all(FLERR, "fix wall/soft/sphere requires atom style sphere");
  params = SoftSphere::parse(lmp, style, &arg[3]);
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
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixWallSoftSphere::~FixWallSoftSphere()
{
  atom->delete_callback(id, Atom::GROW);
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
  // A sphere against a wall has its own mass as effective mass.
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
      double *spring = &history[i][3 * w];
      // Apart (the kernel's own test: the distance from the plane is at least the radius):
      // the kernel would reset the stored spring the same way. A position that is not finite
      // goes on to the kernel, which refuses it.
      const double distance = outward * (x[i][axis] - position[w]);
      if (distance >= radius[i] && std::isfinite(distance)) {
        if (advance) spring[0] = spring[1] = spring[2] = 0.0;
        continue;
      }
      ss_sphere_f64 s;
      s.position = {x[i][0], x[i][1], x[i][2]};
      s.velocity = {v[i][0], v[i][1], v[i][2]};
      s.angular_velocity = {omega[i][0], omega[i][1], omega[i][2]};
      s.radius = radius[i];
      s.mass = atom->rmass[i];
      ss_state_f64 state;
      state.displacement = {spring[0], spring[1], spring[2]};
      ss_forces_f64 out;
      const int code = ss_bound_sphere_wall_f64(bound, &s, &wall, &state, &out);
      if (code != SS_OK)
        error->one(FLERR, "fix wall/soft/sphere: atom {} against the wall: {}", atom->tag[i],
                   SoftSphere::contact_error(code));
      if (advance) {
        spring[0] = state.displacement.x;
        spring[1] = state.displacement.y;
        spring[2] = state.displacement.z;
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
