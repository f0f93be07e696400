/* Part of the soft-sphere LAMMPS plugin; see soft_sphere_law.h. */

#include "soft_sphere_law.h"

#include "atom.h"
#include "error.h"
#include "fmt/format.h"
#include "utils.h"

#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

int SoftSphere::model(LAMMPS *lmp, const std::string &style, const std::string &law)
{
  int32_t model = -1;
  if (ss_model_of_name(law.c_str(), &model) == SS_OK) return model;
  std::string names;
  for (size_t k = 0; k < ss_model_count(); k++)
    names += std::string(k == 0 ? "" : ", ") + ss_model_name(ss_model_code(k));
  lmp->error->all(FLERR, "{}: unknown law '{}' (one of {})", style, law, names);
  return -1;
}

bool SoftSphere::hertz(int model)
{
  return ss_model_is_hertz(model) == 1;
}

const char *SoftSphere::law_name(int model)
{
  const char *name = ss_model_name(model);
  return name ? name : "?";
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
  // The kernel's words, with where a LAMMPS user sets the two the input script does not name.
  if (parameter == SS_PARAMETER_SPEED) return "the impact speed (pair_style soft/sphere impact V)";
  if (parameter == SS_PARAMETER_MASS) return "the smallest atom mass";
  return ss_parameter_name(parameter, model);
}

const char *SoftSphere::parameter_error(int code)
{
  return ss_parameter_error_text(code);
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
  return ss_contact_error_text(code);
}
