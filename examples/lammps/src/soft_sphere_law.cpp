/* Part of the soft-sphere LAMMPS plugin; see soft_sphere_law.h. */

#include "soft_sphere_law.h"

#include "atom.h"
#include "error.h"
#include "fmt/format.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
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

const char *SoftSphere::parameter_name(int parameter, int model, bool wall)
{
  // The kernel's words, with where a LAMMPS user sets the two the input script does not name.
  if (parameter == SS_PARAMETER_SPEED)
    return wall ? "the impact speed (impact V after the law's numbers)"
                : "the impact speed (pair_style soft/sphere impact V)";
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

SoftSphere::Present SoftSphere::present(LAMMPS *lmp, const std::string &style, int types,
                                        const int *kind, int first)
{
  const Atom *atom = lmp->atom;
  // One reduction: the largest radius, then the negated smallest inertia, then each kind's
  // negated lightest mass (a maximum of negatives is a minimum), then the count of bad atoms.
  std::vector<double> local(types + 3, -HUGE_VAL), all(types + 3, 0.0);
  local[types + 2] = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double r = atom->radius[i], m = atom->rmass[i];
    if (!(r > 0.0) || !(m > 0.0) || !std::isfinite(r) || !std::isfinite(m)) {
      local[types + 2] += 1.0;
      continue;
    }
    const int k = kind ? kind[i] - first : 0;
    local[0] = std::max(local[0], r);
    local[1] = std::max(local[1], -0.2 * m * r * r);
    if (k >= 0 && k < types) local[2 + k] = std::max(local[2 + k], -m);
  }
  MPI_Allreduce(local.data(), all.data(), types + 3, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (all[types + 2] > 0.0)
    lmp->error->all(FLERR,
                    "{}: an atom's radius or mass is not a positive number (a contact law "
                    "needs spheres of finite size and mass)",
                    style);
  Present p;
  p.largest_radius = all[0] > 0.0 ? all[0] : 0.0;
  // Half the smallest 2/5 m R^2: two of the smallest in contact.
  p.smallest_inertia = all[1] < 0.0 && std::isfinite(all[1]) ? -all[1] : 0.0;
  p.lightest.resize(types);
  for (int k = 0; k < types; k++) p.lightest[k] = std::isfinite(all[2 + k]) ? -all[2 + k] : 0.0;
  return p;
}

void SoftSphere::require_spheres(LAMMPS *lmp, const std::string &style)
{
  const Atom *atom = lmp->atom;
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    lmp->error->all(FLERR,
                    "{} requires the atom attributes radius, rmass, omega and torque (atom_style "
                    "sphere)",
                    style);
}

const char *SoftSphere::contact_error(int code)
{
  return ss_contact_error_text(code);
}
