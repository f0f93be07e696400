/* Part of the soft-sphere LAMMPS plugin; see soft_sphere_law.h. */

#include "soft_sphere_law.h"

#include "atom.h"
#include "error.h"
#include "fmt/format.h"
#include "utils.h"

#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

namespace {
struct Named {
  const char *name;
  int model;
};
const Named LAWS[] = {
    {"aa", SS_MODEL_AA},
    {"aa/luding", SS_MODEL_AA_LUDING},
    {"stateless", SS_MODEL_STATELESS},
    {"frictionless", SS_MODEL_FRICTIONLESS},
    {"hertz/aa", SS_MODEL_HERTZ_AA},
    {"hertz/aa/luding", SS_MODEL_HERTZ_AA_LUDING},
    {"hertz/stateless", SS_MODEL_HERTZ_STATELESS},
    {"hertz/frictionless", SS_MODEL_HERTZ_FRICTIONLESS},
};
}    // namespace

int SoftSphere::model(LAMMPS *lmp, const std::string &style, const std::string &law)
{
  for (const Named &named : LAWS)
    if (law == named.name) return named.model;
  lmp->error->all(FLERR,
                  "{}: unknown law '{}' (one of aa, aa/luding, stateless, frictionless, "
                  "hertz/aa, hertz/aa/luding, hertz/stateless, hertz/frictionless)",
                  style, law);
  return -1;
}

bool SoftSphere::hertz(int model)
{
  return model == SS_MODEL_HERTZ_AA || model == SS_MODEL_HERTZ_AA_LUDING ||
      model == SS_MODEL_HERTZ_STATELESS || model == SS_MODEL_HERTZ_FRICTIONLESS;
}

const char *SoftSphere::law_name(int model)
{
  for (const Named &named : LAWS)
    if (named.model == model) return named.name;
  return "?";
}

ss_coefficients_f64 SoftSphere::coefficients(LAMMPS *lmp, int model, char **arg)
{
  ss_coefficients_f64 c;
  std::memset(&c, 0, sizeof(c));
  double v[5];
  for (int k = 0; k < 5; k++) v[k] = utils::numeric(FLERR, arg[k], false, lmp);
  if (hertz(model)) {
    c.youngs_modulus = v[0];
    c.poisson_ratio = v[1];
  } else {
    c.normal_stiffness = v[0];
    c.tangential_stiffness = v[2];
  }
  c.restitution = hertz(model) ? v[2] : v[1];
  c.dashpot_ratio = v[3];
  c.friction = v[4];
  return c;
}

void SoftSphere::rolling(LAMMPS *lmp, ss_coefficients_f64 &c, char **arg)
{
  c.rolling_friction = utils::numeric(FLERR, arg[0], false, lmp);
  c.rolling_stiffness = utils::numeric(FLERR, arg[1], false, lmp);
  c.rolling_damping = utils::numeric(FLERR, arg[2], false, lmp);
}

double SoftSphere::smallest_inertia(LAMMPS *lmp)
{
  double smallest = 1e300;
  const double *rmass = lmp->atom->rmass, *radius = lmp->atom->radius;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const double inertia = 0.4 * rmass[i] * radius[i] * radius[i];
    if (inertia < smallest) smallest = inertia;
  }
  double all = smallest;
  MPI_Allreduce(&smallest, &all, 1, MPI_DOUBLE, MPI_MIN, lmp->world);
  return 0.5 * all;
}

ss_params_f64 SoftSphere::params(LAMMPS *lmp, int model, const ss_coefficients_f64 &c)
{
  ss_params_f64 p;
  std::memset(&p, 0, sizeof(p));
  p.model = model;
  p.normal_stiffness = c.normal_stiffness;
  p.restitution = c.restitution;
  p.tangential_stiffness = c.tangential_stiffness;
  p.dashpot_ratio = c.dashpot_ratio;
  p.friction = c.friction;
  if (hertz(model)) {
    ss_material_f64 m;
    m.youngs_modulus = c.youngs_modulus;
    m.poisson_ratio = c.poisson_ratio;
    const int code =
        ss_effective_moduli_f64(&m, &m, &p.effective_modulus, &p.effective_shear_modulus);
    if (code != SS_OK)
      lmp->error->all(FLERR, "{}: {} {}", law_name(model),
                      parameter_name(code == SS_ERR_POISSON_RATIO ? SS_PARAMETER_POISSON_RATIO
                                                                  : SS_PARAMETER_MODULUS,
                                     model),
                      parameter_error(code));
  }
  return p;
}

const char *SoftSphere::parameter_name(int parameter, int model)
{
  switch (parameter) {
    case SS_PARAMETER_NORMAL_STIFFNESS:
      return "k_n (normal stiffness)";
    case SS_PARAMETER_RESTITUTION:
      return "e (restitution)";
    case SS_PARAMETER_TANGENTIAL_STIFFNESS:
      return "k_t (tangential stiffness)";
    case SS_PARAMETER_DASHPOT_RATIO:
      return "eta_ratio (tangential over normal dashpot)";
    case SS_PARAMETER_FRICTION:
      return "mu (friction)";
    case SS_PARAMETER_TIME_STEP:
      return "the time step";
    case SS_PARAMETER_MASS:
      return "the smallest atom mass";
    case SS_PARAMETER_MODULUS:
      return hertz(model) ? "E (Young's modulus)" : "the modulus";
    case SS_PARAMETER_POISSON_RATIO:
      return "nu (Poisson's ratio)";
    case SS_PARAMETER_SPEED:
      return "the impact speed (pair_style soft/sphere impact V)";
    case SS_PARAMETER_RADIUS:
      return "the largest radius";
    case SS_PARAMETER_ROLLING_FRICTION:
      return "mu_r (rolling friction)";
    case SS_PARAMETER_ROLLING_STIFFNESS:
      return "k_r (rolling stiffness)";
    case SS_PARAMETER_ROLLING_DAMPING:
      return "eta_r (rolling dashpot)";
    case SS_PARAMETER_WALL:
      return "the wall";
    case SS_PARAMETER_DAMPING_FACTOR:
      return "alpha (Hertz damping factor)";
    case SS_PARAMETER_INERTIA:
      return "the smallest moment of inertia";
    default:
      return "the law";
  }
}

const char *SoftSphere::parameter_error(int code)
{
  switch (code) {
    case SS_ERR_NON_FINITE_PARAMETER:
      return "is not finite";
    case SS_ERR_NOT_POSITIVE:
      return "must be positive";
    case SS_ERR_NEGATIVE:
      return "must not be negative";
    case SS_ERR_RESTITUTION:
      return "must lie in [0, 1]";
    case SS_ERR_POISSON_RATIO:
      return "must lie in (-1, 0.5]";
    case SS_ERR_UNSTABLE_TIME_STEP:
      return "is at or past the stability limit";
    default:
      return "is invalid";
  }
}

ss_law_f64 *SoftSphere::build(LAMMPS *lmp, const std::string &style, ss_params_f64 params,
                              double dt, double smallest_effective_mass)
{
  params.time_step = dt;
  params.smallest_effective_mass = smallest_effective_mass;
  ss_law_f64 *law = nullptr;
  const int code = ss_law_new_f64(&params, &law);
  if (code == SS_OK) return law;
  const int parameter = ss_rejected_parameter_f64(&params);
  if (code == SS_ERR_UNSTABLE_TIME_STEP) {
    double limit = 0.0;
    ss_stability_limit_f64(&params, &limit);
    lmp->error->all(FLERR,
                    "{}: the time step {} s is at or past the kernel's stability limit {} s "
                    "for the smallest pair (effective mass {} kg)",
                    style, dt, limit, smallest_effective_mass);
  }
  lmp->error->all(FLERR, "{}: {} {}", style, parameter_name(parameter, params.model),
                  parameter_error(code));
  return nullptr;
}

ss_bound_law_f64 *SoftSphere::bind(LAMMPS *lmp, const std::string &style, const ss_law_f64 *law)
{
  ss_bound_law_f64 *bound = nullptr;
  if (ss_bound_law_new_f64(law, &bound) != SS_OK)
    lmp->error->all(FLERR, "{}: the kernel could not bind its law to the time step", style);
  return bound;
}

double SoftSphere::smallest_mass(LAMMPS *lmp)
{
  double smallest = 1e300;
  const double *rmass = lmp->atom->rmass;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (rmass[i] < smallest) smallest = rmass[i];
  double all = smallest;
  MPI_Allreduce(&smallest, &all, 1, MPI_DOUBLE, MPI_MIN, lmp->world);
  return all;
}

double SoftSphere::largest_radius(LAMMPS *lmp)
{
  double largest = 0.0;
  const double *radius = lmp->atom->radius;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (radius[i] > largest) largest = radius[i];
  double all = largest;
  MPI_Allreduce(&largest, &all, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  return all;
}

const char *SoftSphere::contact_error(int code)
{
  switch (code) {
    case SS_ERR_NON_FINITE_INPUT:
      return "a position, velocity, radius or mass is not finite";
    case SS_ERR_NON_POSITIVE_RADIUS:
      return "a radius is not positive";
    case SS_ERR_NON_POSITIVE_MASS:
      return "a mass is not positive";
    case SS_ERR_COINCIDENT_CENTRES:
      return "the two centres coincide";
    case SS_ERR_NON_FINITE_RESULT:
      return "the contact force overflowed";
    case SS_ERR_PAST_STABLE_STEP:
      return "the contact is stiffer than the time step was checked for (unstable: shorten "
             "the timestep, or for a Hertz law declare a faster impact)";
    case SS_ERR_LENGTH:
      return "a neighbour count or the history size is wrong";
    case SS_ERR_INDEX:
      return "a neighbour index is past the atoms";
    case SS_ERR_MATERIAL:
      return "an atom type is past the pair style's types";
    case SS_ERR_NULL:
      return "an array is missing";
    case SS_ERR_NOT_PREPARED:
      return "the pair style was not initialised";
    default:
      return "the contact was rejected";
  }
}
