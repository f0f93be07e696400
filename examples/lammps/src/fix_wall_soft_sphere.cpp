/* Part of the soft-sphere LAMMPS plugin; see fix_wall_soft_sphere.h. */

#include "fix_wall_soft_sphere.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "fmt/format.h"
#include "pair_soft_sphere.h"
#include "math_const.h"
#include "memory.h"
#include "neighbor.h"
#include "soft_sphere_law.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

FixWallSoftSphere::FixWallSoftSphere(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), model(-1), rolling(SS_ROLLING_NONE), table(nullptr),
    impact_speed(0.0), coarse(false), warned_inaccurate(false), history(nullptr), advance(true),
    built_radius(0.0), built_inertia(0.0), types(1), mixed(0), motion(NONE), motion_axis(0),
    amplitude(0.0), omega(0.0), shear_speed(0.0), time_origin(update->ntimestep),
    cylinder(false), cylinder_radius(0.0)
{
  const std::string style = "fix wall/soft/sphere";
  const char *usage =
      "Illegal fix wall/soft/sphere command: expected LAW and five numbers, [rolling mu_r k_r "
      "eta_r], [impact V], [coarse], xplane|yplane|zplane LO HI | zcylinder R, [wiggle x|y|z A "
      "PERIOD | shear x|y|z V]";
  // The wall and its bounds (or radius) follow the law's keywords; the wall's motion follows
  // them.
  const auto is_wall = [](const char *word) {
    return std::strcmp(word, "xplane") == 0 || std::strcmp(word, "yplane") == 0 ||
        std::strcmp(word, "zplane") == 0 || std::strcmp(word, "zcylinder") == 0;
  };
  int plane_at = 9;
  while (plane_at < narg && !is_wall(arg[plane_at])) plane_at++;
  if (narg < 10) error->all(FLERR, usage);
  cylinder = plane_at < narg && std::strcmp(arg[plane_at], "zcylinder") == 0;
  const int wall_words = cylinder ? 2 : 3;
  if (plane_at >= narg)
    error->all(FLERR, "{}: no wall given (xplane, yplane or zplane LO HI, or zcylinder R)", style);
  if (plane_at + wall_words > narg)
    error->all(FLERR, "{}: {} needs {}", style, arg[plane_at], cylinder ? "R" : "LO and HI");
  SoftSphere::require_spheres(lmp, style);
  model = SoftSphere::model(lmp, style, arg[3]);
  coefficients = SoftSphere::coefficients(lmp, model, &arg[4]);
  int k = 9;
  while (k < plane_at) {
    if (std::strcmp(arg[k], "rolling") == 0 && k + 3 < plane_at) {
      SoftSphere::rolling(lmp, coefficients, &arg[k + 1]);
      rolling = SS_ROLLING_EPSD;
      k += 4;
    } else if (std::strcmp(arg[k], "impact") == 0 && k + 1 < plane_at) {
      impact_speed = utils::numeric(FLERR, arg[k + 1], false, lmp);
      k += 2;
    } else if (std::strcmp(arg[k], "coarse") == 0) {
      coarse = true;
      k += 1;
    } else
      error->all(FLERR, "{}: unknown keyword '{}' (rolling mu_r k_r eta_r, impact V, coarse)",
                 style, arg[k]);
  }
  if (SoftSphere::hertz(model) && !(impact_speed > 0.0))
    error->all(FLERR,
               "{}: the Hertz laws check the time step against the fastest impact: give it as "
               "impact V (m/s) after the law's numbers",
               style);
  const std::string plane = arg[plane_at];
  axis = plane == "xplane" ? 0 : plane == "yplane" ? 1 : 2;
  if (cylinder) {
    // One wall, about the z axis (x = y = 0), as fix wall/gran's zcylinder.
    cylinder_radius = utils::numeric(FLERR, arg[plane_at + 1], false, lmp);
    if (!(cylinder_radius > 0.0) || !std::isfinite(cylinder_radius))
      error->all(FLERR, "{}: zcylinder R: the radius must be a positive number", style);
    present[0] = 1;
    present[1] = 0;
    position[0] = position[1] = 0.0;
  } else {
    for (int w = 0; w < WALLS; w++) {
      const char *value = arg[plane_at + 1 + w];
      present[w] = std::strcmp(value, "NULL") != 0;
      position[w] = present[w] ? utils::numeric(FLERR, value, false, lmp) : 0.0;
    }
    if (!present[0] && !present[1]) error->all(FLERR, "{}: both walls are NULL", style);
    if (present[0] && present[1] && position[0] >= position[1])
      error->all(FLERR, "{}: LO must lie below HI", style);
  }
  motion_of(style, plane_at + wall_words, narg, arg);

  // The kernel checks the law here already, so a bad parameter stops the input script at this
  // command.
  ss_table_free_f64(new_table(1.0, 1.0));

  force_reneighbor = 0;
  maxexchange = VALUES;
  restart_peratom = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

/* The keywords after the wall: wiggle DIM A PERIOD (the walls at LO + A (1 - cos(w t)),
 * moving at A w sin(w t) along DIM, w = 2 pi / PERIOD, t from the step the fix was defined at,
 * as fix wall/gran; a cylinder along its axis only) or shear DIM V (planes moving at V along
 * DIM, in their plane; a cylinder moving at V along its axis for z, turning about it at surface
 * speed V for x or y, as fix wall/gran's: clockwise seen from +z for V > 0). */
void FixWallSoftSphere::motion_of(const std::string &style, int k, int narg, char **arg)
{
  const auto direction = [&](const char *keyword, const char *word) {
    if (std::strcmp(word, "x") == 0) return 0;
    if (std::strcmp(word, "y") == 0) return 1;
    if (std::strcmp(word, "z") == 0) return 2;
    error->all(FLERR, "{}: {} {}: the direction is x, y or z", style, keyword, word);
    return 0;
  };
  while (k < narg) {
    if (motion != NONE && (std::strcmp(arg[k], "wiggle") == 0 || std::strcmp(arg[k], "shear") == 0))
      error->all(FLERR, "{}: the walls wiggle or shear, not both", style);
    if (std::strcmp(arg[k], "wiggle") == 0 && k + 3 < narg) {
      motion = WIGGLE;
      motion_axis = direction("wiggle", arg[k + 1]);
      amplitude = utils::numeric(FLERR, arg[k + 2], false, lmp);
      const double period = utils::numeric(FLERR, arg[k + 3], false, lmp);
      if (!std::isfinite(amplitude))
        error->all(FLERR, "{}: wiggle: the amplitude must be a finite number", style);
      if (!(period > 0.0) || !std::isfinite(period))
        error->all(FLERR, "{}: wiggle: the period must be a positive number", style);
      if (cylinder && motion_axis != 2)
        error->all(FLERR, "{}: wiggle {}: a zcylinder wiggles along its axis only (wiggle z)",
                   style, arg[k + 1]);
      omega = MathConst::MY_2PI / period;
      k += 4;
    } else if (std::strcmp(arg[k], "shear") == 0 && k + 2 < narg) {
      motion = SHEAR;
      motion_axis = direction("shear", arg[k + 1]);
      shear_speed = utils::numeric(FLERR, arg[k + 2], false, lmp);
      if (!std::isfinite(shear_speed))
        error->all(FLERR, "{}: shear: the speed must be a finite number", style);
      if (!cylinder && motion_axis == axis)
        error->all(FLERR,
                   "{}: shear {}: a plane shears in its own plane, not along its normal (wiggle "
                   "moves it along the normal)",
                   style, arg[k + 1]);
      k += 3;
    } else
      error->all(FLERR, "{}: unknown keyword '{}' after the wall (wiggle x|y|z A PERIOD, shear "
                        "x|y|z V)",
                 style, arg[k]);
  }
  // The wiggle's phase is kept in restart files.
  restart_global = 1;
}

FixWallSoftSphere::~FixWallSoftSphere()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(history);
  ss_table_free_f64(table);
}

int FixWallSoftSphere::setmask()
{
  return POST_FORCE;
}

/* A table of the spheres' materials (the atom types with the pair style's coefficients, or one
 * of the wall's own) and the wall's, last, with this fix's law, its coefficients checked (ERROR
 * naming the rejected one). */
ss_table_f64 *FixWallSoftSphere::new_table(double largest_radius, double inertia)
{
  const std::string style = "fix wall/soft/sphere";
  ss_table_config_f64 config = {};
  std::memset(&config, 0, sizeof(config));
  config.model = model;
  config.materials = (size_t) types + 1;
  config.rolling = rolling;
  config.smallest_inertia = inertia;
  config.largest_impact_speed = impact_speed;
  // A sphere against a wall has its own radius as R*.
  config.largest_effective_radius = largest_radius;
  if (types + 1 > SS_MATERIALS_MAX)
    error->all(FLERR, "{}: at most {} atom types meet a wall of its own material", style,
               SS_MATERIALS_MAX - 1);
  ss_table_f64 *made = nullptr;
  int code = ss_table_new_f64(&config, &made);
  if (code == SS_ERR_UNKNOWN_MODEL)
    error->all(FLERR, "{}: the frictionless laws take no rolling resistance", style);
  if (code != SS_OK)
    error->all(FLERR, "{}: {} {}", style,
               SoftSphere::parameter_name(
                   code == SS_ERR_NOT_POSITIVE ? SS_PARAMETER_SPEED : SS_PARAMETER_NONE, model,
                   true),
               SoftSphere::parameter_error(code));
  const auto *pair = mixed ? dynamic_cast<PairSoftSphere *>(force->pair_match("soft/sphere", 1))
                           : nullptr;
  for (int m = 0; m <= types; m++) {
    const ss_coefficients_f64 *c = m < types && pair ? pair->own(m + 1) : &coefficients;
    if (c == nullptr) {
      ss_table_free_f64(made);
      error->all(FLERR,
                 "{}: atom type {} has no coefficients of its own to meet the wall by (pair_coeff "
                 "{} {} LAW ...)",
                 style, m + 1, m + 1, m + 1);
    }
    int parameter = SS_PARAMETER_NONE;
    code = ss_table_set_f64(made, m, m, c, &parameter);
    if (code != SS_OK) {
      ss_table_free_f64(made);
      error->all(FLERR, "{}: {} {}", style, SoftSphere::parameter_name(parameter, model, true),
                 SoftSphere::parameter_error(code));
    }
  }
  // The table evaluates the spheres against the wall alone (the wall's material with itself
  // names no pair of atoms): the spheres' pairs, and the step they need, are the pair style's.
  const uint32_t wall = (uint32_t) types;
  const uint32_t alone[2] = {wall, wall};
  if (ss_table_set_walls_f64(made, &wall, 1) != SS_OK ||
      ss_table_set_pairs_f64(made, alone, 1) != SS_OK) {
    ss_table_free_f64(made);
    error->all(FLERR, "{}: the kernel refused the wall's material", style);
  }
  return made;
}

void FixWallSoftSphere::init()
{
  const std::string style = "fix wall/soft/sphere";
  // Under pair_style soft/sphere with the wall's law (and rolling resistance alike), each atom
  // type meets the wall by mixing; with another law there is nothing to mix with, and every
  // atom meets the wall with the wall's law.
  const auto *pair = dynamic_cast<PairSoftSphere *>(force->pair_match("soft/sphere", 1));
  mixed = pair != nullptr && pair->law() == model && (pair->law_rolling() > 0) == (rolling > 0);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   mixed ? "{}: each atom type meets the wall by mixing its pair_style "
                           "soft/sphere coefficients with the wall's\n"
                         : "{}: every atom meets the wall with the wall's law (no pair_style "
                           "soft/sphere of the same law to mix with)\n",
                   style);
  types = mixed ? atom->ntypes : 1;
  // Checked at each run's start: a change_box may have made x or y periodic since.
  if (cylinder && (domain->xperiodic || domain->yperiodic))
    error->all(FLERR, "{}: zcylinder needs x and y not periodic", style);
  refresh(true);
}

/* Makes the table for the atoms present (remade when asked, or when larger atoms or atoms of
 * smaller inertia than it was made for have arrived) and checks the step at the lightest atom
 * (again when a lighter one has arrived). A deck that starts empty (fix pour) gets a table for
 * no atoms, which checks nothing, and the real one when its atoms arrive. Collective. */
void FixWallSoftSphere::refresh(bool remake)
{
  const std::string style = "fix wall/soft/sphere";
  const SoftSphere::Present now =
      SoftSphere::present(lmp, style, types, mixed ? atom->type : nullptr, 1);
  const bool inertia = rolling > 0;
  if (remake || table == nullptr || now.outgrows(built_radius, built_inertia, inertia)) {
    ss_table_free_f64(table);
    table = nullptr;
    table = new_table(now.table_radius(), inertia ? now.table_inertia() : 1.0);
    built_radius = now.largest_radius;
    built_inertia = now.table_inertia();
    checked_lightest.clear();
  }
  if (now.lightest == checked_lightest) return;
  checked_lightest = now.lightest;
  // The wall's material has no atoms: the table checks each material present against it at
  // its lightest atom's mass (a sphere against a wall), and the spheres' pairs as well.
  std::vector<double> lightest = now.lightest;
  lightest.push_back(0.0);
  ss_table_report_f64 report;
  const int code =
      coarse ? ss_table_prepare_coarse_f64(table, update->dt, lightest.data(), &report)
             : ss_table_prepare_f64(table, update->dt, lightest.data(), &report);
  // What the refused pair of materials is: atom types (or all atoms) and the wall.
  const auto named = [this](long m) {
    if (m == types) return std::string("the wall");
    return mixed ? fmt::format("atom type {}", m + 1) : std::string("the atoms");
  };
  const std::string which = named(report.materials[0]) + " and " + named(report.materials[1]);
  if (code == SS_ERR_UNSTABLE_TIME_STEP)
    error->all(FLERR,
               "{}: the time step {} s is at or past the kernel's stability limit {} s for {} "
               "(their lightest atoms)",
               style, update->dt, report.limit, which);
  if (code == SS_ERR_INACCURATE_TIME_STEP)
    error->all(FLERR,
               "{}: the time step {} s is at or past the kernel's accuracy limit {} s for {} "
               "(their lightest atoms): a contact could rebound faster than its restitution "
               "allows (add the keyword coarse to take such a step knowingly)",
               style, update->dt, report.limit, which);
  if (code != SS_OK)
    error->all(FLERR, "{}: {} {}", style, SoftSphere::parameter_name(report.parameter, model, true),
               SoftSphere::parameter_error(code));
}

/* fix dt/reset changed the step within a run: the walls' laws are made again at the new step,
 * which is checked as at a run's start. Collective, as fix dt/reset calls it on every rank. */
void FixWallSoftSphere::reset_dt()
{
  if (table == nullptr) return;
  checked_lightest.clear();
  refresh(false);
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
  // Atoms arrive (fix pour, deposit) on the steps the lists are rebuilt: the table and the
  // step are checked again for them there.
  if (neighbor->ago == 0) refresh(false);
  forces();
}

void FixWallSoftSphere::forces()
{
  const int nlocal = atom->nlocal;
  // Each atom type is a material of the table, or every atom the first.
  if (!mixed && (int) material.size() < nlocal) material.resize(nlocal, 0);
  // Where the walls are and how fast they move this step (fix wall/gran's convention).
  double offset = 0.0, speed = 0.0;
  if (motion == WIGGLE) {
    const double phase = omega * (double) (update->ntimestep - time_origin) * update->dt;
    if (motion_axis == axis) offset = amplitude - amplitude * std::cos(phase);
    speed = amplitude * omega * std::sin(phase);
  } else if (motion == SHEAR)
    speed = shear_speed;
  // The kernel's cylinder has one side: an atom whose centre is past it is inside the wall and
  // would be pushed in by its whole depth (fix wall/gran's thin shell would push it out).
  if (cylinder) {
    const double r2 = cylinder_radius * cylinder_radius;
    for (int i = 0; i < nlocal; i++) {
      if (!(atom->mask[i] & groupbit)) continue;
      const double *x = atom->x[i];
      const double rho2 = x[0] * x[0] + x[1] * x[1];
      if (rho2 > r2)
        error->one(FLERR,
                   "fix wall/soft/sphere: atom {} is outside the zcylinder (its centre {} from "
                   "the axis, the radius {}): the wall holds atoms inside it",
                   atom->tag[i], std::sqrt(rho2), cylinder_radius);
    }
  }
  ss_wall_f64 walls[WALLS];
  int count = 0, first = -1;
  for (int w = 0; w < WALLS; w++) {
    if (!present[w]) continue;
    if (first < 0) first = w;
    std::memset(&walls[count], 0, sizeof(ss_wall_f64));
    if (cylinder) {
      // The axis along z through x = y = 0; shear x or y turns it (V = -spin R).
      walls[count].direction.z = 1.0;
      walls[count].radius = cylinder_radius;
      if (motion == SHEAR && motion_axis != 2)
        walls[count].spin = -shear_speed / cylinder_radius;
      else
        walls[count].velocity.z = speed;
    } else {
      (&walls[count].point.x)[axis] = position[w] + offset;
      (&walls[count].direction.x)[axis] = w == 0 ? 1.0 : -1.0;
      (&walls[count].velocity.x)[motion_axis] = speed;
    }
    count++;
  }
  ss_atoms_f64 atoms;
  atoms.count = (size_t) nlocal;
  atoms.owned = (size_t) nlocal;
  atoms.position = nlocal ? atom->x[0] : nullptr;
  atoms.velocity = nlocal ? atom->v[0] : nullptr;
  atoms.angular_velocity = nlocal ? atom->omega[0] : nullptr;
  atoms.radius = atom->radius;
  atoms.mass = atom->rmass;
  atoms.types = mixed ? atom->type : material.data();
  atoms.first_type = mixed ? 1 : 0;
  ss_walls_f64 set;
  set.count = (size_t) count;
  set.walls = walls;
  set.material = (uint32_t) types;
  // LO's state first, then HI's, in each atom's row.
  set.states = nlocal ? &history[0][STATE * first] : nullptr;
  set.stride = VALUES;
  set.wall_stride = STATE;
  set.selected = atom->mask;
  set.bit = groupbit;
  ss_loads_f64 loads;
  loads.force = nlocal ? atom->f[0] : nullptr;
  loads.torque = nlocal ? atom->torque[0] : nullptr;
  loads.newton = 0;
  loads.pair_force = nullptr;
  ss_list_report report;
  const int code =
      ss_table_evaluate_walls_f64(table, &atoms, &set, &loads, advance ? 1 : 0, &report);
  if (code != SS_OK) {
    if (report.atoms[0] >= 0)
      error->one(FLERR, "fix wall/soft/sphere: atom {} against the wall: {}",
                 atom->tag[report.atoms[0]], SoftSphere::contact_error(code));
    error->one(FLERR, "fix wall/soft/sphere: {}", SoftSphere::contact_error(code));
  }
  if (report.inaccurate > 0 && !warned_inaccurate) {
    warned_inaccurate = true;
    error->warning(FLERR,
                   "fix wall/soft/sphere: coarse step: contacts past the kernel's accuracy "
                   "limit on this rank at step {}: {} (they may rebound faster than their "
                   "restitution allows); reported once",
                   update->ntimestep, report.inaccurate);
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

/* Restart files (global): the step the wiggle started from, so that a run read back goes on
 * with the walls where they were. */
void FixWallSoftSphere::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double origin = (double) time_origin;
  const int size = sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(&origin, sizeof(double), 1, fp);
}

void FixWallSoftSphere::restart(char *buf)
{
  double origin;
  std::memcpy(&origin, buf, sizeof(double));
  time_origin = (bigint) origin;
}
