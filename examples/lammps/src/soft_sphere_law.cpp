/* Part of the soft-sphere LAMMPS plugin; see soft_sphere_law.h. */

#include "soft_sphere_law.h"

#include "atom.h"
#include "error.h"
#include "fmt/format.h"
#include "utils.h"

#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

ss_params_f64 SoftSphere::parse(LAMMPS *lmp, const std::string &style, char **arg)
{
  ss_params_f64 p;
  std::memset(&p, 0, sizeof(p));
  const std::string law = arg[0];
  if (law == "aa")
    p.model = SS_MODEL_AA;
  else if (law == "aa/luding")
    p.model = SS_MODEL_AA_LUDING;
  else if (law == "stateless")
    p.model = SS_MODEL_STATELESS;
  else if (law == "frictionless")
    p.model = SS_MODEL_FRICTIONLESS;
  else
    lmp->error->all(FLERR,
                    "{}: unknown law '{}' (one of aa, aa/luding, stateless, frictionless)",
                    style, law);
  p.normal_stiffness = utils::numeric(FLERR, arg[1], false, lmp);
  p.restitution = utils::numeric(FLERR, arg[2], false, lmp);
  p.tangential_stiffness = utils::numeric(FLERR, arg[3], false, lmp);
  p.dashpot_ratio = utils::numeric(FLERR, arg[4], false, lmp);
  p.friction = utils::numeric(FLERR, arg[5], false, lmp);
  return p;
}

static const char *parameter_name(int parameter)
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
    default:
      return "the law";
  }
}

static const char *parameter_error(int code)
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
  lmp->error->all(FLERR, "{}: {} {}", style, parameter_name(parameter), parameter_error(code));
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
             "the timestep)";
    default:
      return "the contact was rejected";
  }
}
