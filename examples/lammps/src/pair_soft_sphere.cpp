/* Part of the soft-sphere LAMMPS plugin; see pair_soft_sphere.h. */

#include "pair_soft_sphere.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "soft_sphere_law.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

static const char *STYLE = "pair_style soft/sphere";

PairSoftSphere::PairSoftSphere(LAMMPS *lmp) :
    PairGranHookeHistory(lmp), model(-1), style_law(0), rolling(-1), impact_speed(0.0),
    coarse(0), warned_inaccurate(0), pending(0), history_made(0),
    table(nullptr), built_radius(0.0), built_inertia(0.0)
{
  std::memset(&style_coefficients, 0, sizeof(style_coefficients));
  single_enable = 1;
  // The kernel says how a stored state looks from the other atom (a contact radius is not
  // negated).
  nondefault_history_transfer = 1;
}

PairSoftSphere::~PairSoftSphere()
{
  ss_table_free_f64(table);
}

void PairSoftSphere::settings(int narg, char **arg)
{
  int k = 0;
  // A coarse step is asked for by each pair_style command that wants it.
  coarse = 0;
  if (narg >= 6 && std::strcmp(arg[0], "impact") != 0) {
    model = SoftSphere::model(lmp, STYLE, arg[0]);
    style_coefficients = SoftSphere::coefficients(lmp, model, &arg[1]);
    style_law = 1;
    rolling = SS_ROLLING_NONE;
    k = 6;
  }
  while (k < narg) {
    if (style_law && std::strcmp(arg[k], "rolling") == 0 && k + 3 < narg) {
      SoftSphere::rolling(lmp, style_coefficients, &arg[k + 1]);
      rolling = SS_ROLLING_EPSD;
      k += 4;
    } else if (std::strcmp(arg[k], "impact") == 0 && k + 1 < narg) {
      impact_speed = utils::numeric(FLERR, arg[k + 1], false, lmp);
      if (!(impact_speed > 0.0) || !std::isfinite(impact_speed))
        error->all(FLERR, "{}: the impact speed must be a positive number", STYLE);
      k += 2;
    } else if (std::strcmp(arg[k], "coarse") == 0) {
      coarse = 1;
      k += 1;
    } else
      error->all(FLERR,
                 "Illegal pair_style soft/sphere command: expected [LAW five numbers "
                 "[rolling mu_r k_r eta_r]] [impact V] [coarse]");
  }
  // The base class's fields, for what it reports; the forces come from the kernel.
  kn = style_coefficients.normal_stiffness;
  kt = style_coefficients.tangential_stiffness;
  gamman = gammat = 0.0;
  xmu = style_coefficients.friction;
  dampflag = 1;
  limit_damping = 0;
}

void PairSoftSphere::size_tables()
{
  if (!allocated) allocate();
  const size_t n = (size_t) atom->ntypes + 1;
  if (coefficients.size() != n * n) {
    ss_coefficients_f64 zero;
    std::memset(&zero, 0, sizeof(zero));
    coefficients.assign(n * n, zero);
    given.assign(n * n, 0);
  }
}

ss_table_f64 *PairSoftSphere::new_table(int materials, double largest_effective_radius,
                                        double inertia)
{
  if (SoftSphere::hertz(model) && !(impact_speed > 0.0))
    error->all(FLERR,
               "{}: the Hertz laws check the time step against the fastest impact: give it "
               "as pair_style soft/sphere impact V (m/s)",
               STYLE);
  if (materials > SS_MATERIALS_MAX)
    error->all(FLERR, "{}: at most {} atom types", STYLE, SS_MATERIALS_MAX);
  ss_table_config_f64 config = {};
  config.model = model;
  config.materials = (size_t) materials;
  config.largest_impact_speed = impact_speed;
  config.largest_effective_radius = largest_effective_radius;
  config.rolling = rolling > 0 ? rolling : SS_ROLLING_NONE;
  config.smallest_inertia = inertia;
  ss_table_f64 *made = nullptr;
  const int code = ss_table_new_f64(&config, &made);
  if (code == SS_ERR_UNKNOWN_MODEL)
    error->all(FLERR, "{}: the frictionless laws take no rolling resistance", STYLE);
  if (code != SS_OK)
    error->all(FLERR, "{}: {} {}", STYLE,
               SoftSphere::parameter_name(
                   code == SS_ERR_NOT_POSITIVE ? SS_PARAMETER_SPEED : SS_PARAMETER_NONE, model),
               SoftSphere::parameter_error(code));
  return made;
}

void PairSoftSphere::coeff(int narg, char **arg)
{
  int law = model, rolls = rolling;
  ss_coefficients_f64 c = style_coefficients;
  const int with_rolling = narg == 12 && std::strcmp(arg[8], "rolling") == 0;
  if (narg == 3 && std::strcmp(arg[2], "mix") == 0) {
    mix(arg[0], arg[1]);
    return;
  }
  if (narg == 2) {
    if (!style_law)
      error->all(FLERR,
                 "pair_coeff {} {}: no law: give pair_coeff I J LAW and five numbers, or the "
                 "law to pair_style soft/sphere",
                 arg[0], arg[1]);
  } else if (narg == 8 || with_rolling) {
    law = SoftSphere::model(lmp, "pair_coeff", arg[2]);
    if (model >= 0 && law != model)
      error->all(FLERR,
                 "pair_coeff {} {}: law '{}' differs from '{}' given before: one law per "
                 "pair_style soft/sphere (friction 0 makes a pair frictionless)",
                 arg[0], arg[1], arg[2], SoftSphere::law_name(model));
    c = SoftSphere::coefficients(lmp, law, &arg[3]);
    rolls = with_rolling ? SS_ROLLING_EPSD : SS_ROLLING_NONE;
    if (with_rolling) SoftSphere::rolling(lmp, c, &arg[9]);
    if (rolling >= 0 && rolls != rolling)
      error->all(FLERR,
                 "pair_coeff {} {}: rolling resistance given to some pairs and not to others: "
                 "one law per pair_style soft/sphere (mu_r 0 makes a pair roll freely)",
                 arg[0], arg[1]);
  } else
    error->all(FLERR,
               "Illegal pair_coeff command for soft/sphere: expected I J LAW and five numbers "
               "[rolling mu_r k_r eta_r] (or I J alone, with the law given to pair_style, or "
               "I J mix)");
  model = law;
  rolling = rolls;
  size_tables();

  // The kernel checks the coefficients now, so a bad one stops the input at this command.
  ss_table_f64 *probe = new_table(1, 1.0, 1.0);
  int parameter = SS_PARAMETER_NONE;
  const int code = ss_table_set_f64(probe, 0, 0, &c, &parameter);
  ss_table_free_f64(probe);
  if (code != SS_OK)
    error->all(FLERR, "pair_coeff {} {}: {} {}", arg[0], arg[1],
               SoftSphere::parameter_name(parameter, model), SoftSphere::parameter_error(code));

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const int n = atom->ntypes + 1;
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = (jlo > i ? jlo : i); j <= jhi; j++) {
      coefficients[i * n + j] = coefficients[j * n + i] = c;
      given[i * n + j] = given[j * n + i] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
  // Every pair is "set" for LAMMPS: the kernel's mixing rule makes the rest, and a type with
  // nothing to mix from gets this style's own ERROR when the run starts.
  for (int i = 1; i < n; i++)
    for (int j = i; j < n; j++) setflag[i][j] = 1;
}

/* pair_coeff I J mix: the pairs of types I and J take the law the kernel's mixing rule makes
 * from each type's own coefficients, as pairs not given their own do. For pair_style
 * hybrid/overlay, under which LAMMPS mixes no pair: each cross pair is given to the style. */
void PairSoftSphere::mix(const char *first, const char *second)
{
  size_tables();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, first, 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, second, 1, atom->ntypes, jlo, jhi, error);
  const int n = atom->ntypes + 1;
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = (jlo > i ? jlo : i); j <= jhi; j++) {
      if (i == j)
        error->all(FLERR,
                   "pair_coeff {} {} mix: type {} has nothing to mix with itself: give it its "
                   "own (pair_coeff {} {} LAW ...)",
                   first, second, i, i, i);
      given[i * n + j] = given[j * n + i] = 0;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

const ss_coefficients_f64 *PairSoftSphere::own(int t) const
{
  const int n = atom->ntypes + 1;
  if (t < 1 || t >= n || coefficients.size() != (size_t) (n * n) || !given[t * n + t])
    return nullptr;
  return &coefficients[t * n + t];
}

void PairSoftSphere::init_style()
{
  SoftSphere::require_spheres(lmp, STYLE);
  if (model < 0) error->all(FLERR, "{}: no law given (pair_coeff)", STYLE);
  size_tables();
  // The pairs this style evaluates are known once LAMMPS has asked init_one for each (under
  // pair_style hybrid, only for the pairs mapped to this style): the step is checked then, at
  // setup. This table gives the history's size.
  owned.assign(given.size(), 0);
  make_table(SoftSphere::present(lmp, STYLE, atom->ntypes, atom->type, 1));
  checked_lightest.clear();
  pending = 1;
  const size_t values = ss_table_state_values_f64(table);
  size_history = values > 0 ? (int) values : 1;
  if (history_made && history_made != size_history)
    error->all(FLERR,
               "{}: the law '{}' keeps {} numbers per contact, the history was made for {}: "
               "use a new pair_style",
               STYLE, SoftSphere::law_name(model), size_history, history_made);
  PairGranHookeHistory::init_style();
  history_made = size_history;
}

double PairSoftSphere::init_one(int i, int j)
{
  const int n = atom->ntypes + 1;
  // Sized by init_style; a caller that asks before (pair_write) finds it sized here.
  if (owned.size() != (size_t) (n * n)) owned.assign((size_t) (n * n), 0);
  owned[i * n + j] = owned[j * n + i] = 1;
  return PairGranHookeHistory::init_one(i, j);
}

void PairSoftSphere::setup()
{
  PairGranHookeHistory::setup();
  refresh(true);
  pending = 0;
}

void PairSoftSphere::reset_dt()
{
  PairGranHookeHistory::reset_dt();
  if (table && !pending) prepare(checked_lightest);
}

/* A table for the atoms present (its largest radius and smallest inertia), with every type
 * pair's coefficients given, and the type pairs this style evaluates when not every pair
 * (pair_style hybrid): the step is then checked for those alone, and the others refused. */
void PairSoftSphere::make_table(const SoftSphere::Present &now)
{
  const bool inertia = rolling > 0;
  ss_table_free_f64(table);
  table = nullptr;
  // The largest pair of spheres has R* = R / 2.
  table = new_table(atom->ntypes, 0.5 * now.table_radius(), inertia ? now.table_inertia() : 1.0);
  built_radius = now.largest_radius;
  built_inertia = now.table_inertia();
  const int n = atom->ntypes + 1;
  std::vector<uint32_t> pairs;
  bool every = true;
  for (int i = 1; i < n; i++)
    for (int j = i; j < n; j++) {
      if (owned.size() == given.size() && owned[i * n + j]) {
        pairs.push_back((uint32_t) (i - 1));
        pairs.push_back((uint32_t) (j - 1));
      } else
        every = false;
      if (!given[i * n + j]) continue;
      int parameter = SS_PARAMETER_NONE;
      const int code = ss_table_set_f64(table, i - 1, j - 1, &coefficients[i * n + j], &parameter);
      if (code != SS_OK)
        error->all(FLERR, "pair_coeff {} {}: {} {}", i, j,
                   SoftSphere::parameter_name(parameter, model),
                   SoftSphere::parameter_error(code));
    }
  // Before init_one has named any pair (init_style), every pair.
  if (!every && !pairs.empty() &&
      ss_table_set_pairs_f64(table, pairs.data(), pairs.size() / 2) != SS_OK)
    error->all(FLERR, "{}: the kernel refused the type pairs this style evaluates", STYLE);
}

/* Makes the table for the atoms present (remade when asked, or when atoms larger or of
 * smaller inertia than it was made for have arrived) and checks the step at the lightest atom
 * of each type present (again when a lighter atom or a new type has arrived). A deck that
 * starts empty (fix pour) gets a table for no atoms, which checks nothing, and the real one
 * when its atoms arrive. Collective. */
void PairSoftSphere::refresh(bool remake)
{
  const SoftSphere::Present now = SoftSphere::present(lmp, STYLE, atom->ntypes, atom->type, 1);
  if (remake || table == nullptr || now.outgrows(built_radius, built_inertia, rolling > 0)) {
    make_table(now);
    checked_lightest.clear();
  }
  if (now.lightest != checked_lightest) prepare(now.lightest);
}

void PairSoftSphere::prepare(const std::vector<double> &lightest)
{
  // The lightest atom of each type over all ranks (0 for a type with no atoms).
  checked_lightest = lightest;
  ss_table_report_f64 report;
  const int code = coarse ? ss_table_prepare_coarse_f64(table, update->dt, lightest.data(), &report)
                          : ss_table_prepare_f64(table, update->dt, lightest.data(), &report);
  if (code == SS_OK) return;
  const long a = report.materials[0] + 1, b = report.materials[1] + 1;
  if (code == SS_ERR_MATERIAL)
    error->all(FLERR,
               "{}: no coefficients for types {} and {}: give each type its own (pair_coeff "
               "I I LAW ...), from which pairs mix, or the pair its own (pair_coeff {} {} LAW "
               "...)",
               STYLE, a, b, a, b);
  if (code == SS_ERR_UNSTABLE_TIME_STEP)
    error->all(FLERR,
               "{}: the time step {} s is at or past the kernel's stability limit {} s for "
               "types {} and {} (their lightest atoms)",
               STYLE, update->dt, report.limit, a, b);
  if (code == SS_ERR_INACCURATE_TIME_STEP)
    error->all(FLERR,
               "{}: the time step {} s is at or past the kernel's accuracy limit {} s for "
               "types {} and {} (their lightest atoms): a contact could rebound faster than "
               "its restitution allows (add the keyword coarse to the pair_style to take "
               "such a step knowingly)",
               STYLE, update->dt, report.limit, a, b);
  if (code == SS_ERR_NON_FINITE_INPUT)
    error->all(FLERR, "{}: an atom mass is not finite", STYLE);
  error->all(FLERR, "{}: types {} and {}: {} {}", STYLE, a, b,
             SoftSphere::parameter_name(report.parameter, model),
             SoftSphere::parameter_error(code));
}

void PairSoftSphere::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // Atoms arrive (fix pour, deposit) on the steps the lists are rebuilt: the table and the
  // step are checked again for them there.
  // A run that skipped setup (rerun) checks the step here.
  if (pending) {
    refresh(true);
    pending = 0;
  } else if (neighbor->ago == 0 && !update->setupflag)
    refresh(false);
  // The setup evaluation (before the first step) gives forces without advancing the history.
  const int advance = update->setupflag ? 0 : 1;

  ss_atoms_f64 atoms;
  atoms.count = (size_t) (atom->nlocal + atom->nghost);
  atoms.owned = (size_t) atom->nlocal;
  atoms.position = atoms.count ? atom->x[0] : nullptr;
  atoms.velocity = atoms.count ? atom->v[0] : nullptr;
  atoms.angular_velocity = atoms.count ? atom->omega[0] : nullptr;
  atoms.radius = atom->radius;
  atoms.mass = atom->rmass;
  atoms.types = atom->type;
  atoms.first_type = 1;

  ss_neighbours neighbours;
  neighbours.count = (size_t) list->inum;
  neighbours.atoms = list->ilist;
  neighbours.neighbour_counts = list->numneigh;
  neighbours.first_neighbour = (const int32_t *const *) list->firstneigh;
  neighbours.index_mask = NEIGHMASK;

  ss_history_f64 history;
  history.values = (size_t) size_history;
  history.first_value = fix_history->firstvalue;
  history.first_touch = fix_history->firstflag;

  ss_loads_f64 loads;
  loads.force = atoms.count ? atom->f[0] : nullptr;
  loads.torque = atoms.count ? atom->torque[0] : nullptr;
  loads.newton = force->newton_pair ? 1 : 0;
  loads.pair_force = nullptr;
  if (evflag) {
    size_t pairs = 0;
    for (int ii = 0; ii < list->inum; ii++) pairs += (size_t) list->numneigh[list->ilist[ii]];
    pair_force.resize(3 * pairs);
    loads.pair_force = pair_force.data();
  }

  ss_list_report report;
  const int code =
      ss_table_evaluate_f64(table, &atoms, &neighbours, &history, &loads, advance, &report);
  if (code != SS_OK) {
    const auto tag = [this](long k) -> long { return k >= 0 ? (long) atom->tag[k] : -1L; };
    if (report.atoms[1] >= 0)
      error->one(FLERR, "{}: contact of atoms {} and {}: {}", STYLE, tag(report.atoms[0]),
                 tag(report.atoms[1]), SoftSphere::contact_error(code));
    if (report.atoms[0] >= 0)
      error->one(FLERR, "{}: atom {}: {}", STYLE, tag(report.atoms[0]),
                 SoftSphere::contact_error(code));
    error->one(FLERR, "{}: {}", STYLE, SoftSphere::contact_error(code));
  }
  if (report.inaccurate > 0 && !warned_inaccurate) {
    warned_inaccurate = 1;
    error->warning(FLERR,
                   "{}: coarse step: contacts past the kernel's accuracy limit on this rank "
                   "at step {}: {} (they may rebound faster than their restitution allows); "
                   "reported once",
                   STYLE, update->ntimestep, report.inaccurate);
  }

  if (evflag) {
    double **x = atom->x;
    const int nlocal = atom->nlocal;
    const int newton_pair = force->newton_pair;
    size_t k = 0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++, k++) {
        const double *fi = &pair_force[3 * k];
        if (fi[0] == 0.0 && fi[1] == 0.0 && fi[2] == 0.0) continue;
        const int j = jlist[jj] & NEIGHMASK;
        ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fi[0], fi[1], fi[2], x[i][0] - x[j][0],
                     x[i][1] - x[j][1], x[i][2] - x[j][2]);
      }
    }
  }
}

/* The kernel's force on i of the pair (i, j), its state read from the history and not changed:
 * fforce is the normal part over r (LAMMPS multiplies it by x_i - x_j), svector the
 * tangential force on i, its magnitude, and the normal and tangential relative velocities, as
 * gran/hooke/history reports them. */
double PairSoftSphere::single(int i, int j, int itype, int jtype, double rsq, double, double,
                              double &fforce)
{
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  fforce = 0.0;
  // A contact is its atoms' motion and stored springs, not r alone: single() answers for two
  // atoms of a built neighbour list (compute pair/local), never for pair_write's table.
  const int all = atom->nlocal + atom->nghost;
  const auto apart_sq = [this, i, j]() {
    double sum = 0.0;
    for (int c = 0; c < 3; c++) {
      const double d = atom->x[i][c] - atom->x[j][c];
      sum += d * d;
    }
    return sum;
  };
  if (i < 0 || j < 0 || i >= all || j >= all || list == nullptr || list->numneigh == nullptr ||
      std::fabs(apart_sq() - rsq) > 1e-12 * rsq)
    error->one(FLERR,
               "{}: single() answers for two atoms of a built neighbour list at their own "
               "distance (pair_write cannot tabulate a granular contact, which depends on the "
               "atoms' motion)",
               STYLE);
  const double radsum = atom->radius[i] + atom->radius[j];
  if (rsq >= radsum * radsum || table == nullptr) return 0.0;

  // The pair's stored state: under i in the pair style's list, or under j when j is owned (a
  // list asked for by a compute may hold the pair the other way round), seen from i.
  double mirrored[8];
  const auto find = [this](int a, int b) -> const double * {
    const int jnum = list->numneigh[a];
    const int *jlist = list->firstneigh[a];
    for (int jj = 0; jj < jnum; jj++) {
      neighprev++;
      if (neighprev >= jnum) neighprev = 0;
      if ((jlist[neighprev] & NEIGHMASK) == b)
        return &fix_history->firstvalue[a][size_history * neighprev];
    }
    return nullptr;
  };
  const double *values = find(i, j);
  if (values == nullptr && j < atom->nlocal) {
    const double *other = find(j, i);
    if (other != nullptr && ss_table_mirror_state_f64(table, other, mirrored) == SS_OK)
      values = mirrored;
  }
  const auto sphere = [this](int k) {
    ss_sphere_f64 s;
    s.position = {atom->x[k][0], atom->x[k][1], atom->x[k][2]};
    s.velocity = {atom->v[k][0], atom->v[k][1], atom->v[k][2]};
    s.angular_velocity = {atom->omega[k][0], atom->omega[k][1], atom->omega[k][2]};
    s.radius = atom->radius[k];
    s.mass = atom->rmass[k];
    return s;
  };
  const ss_sphere_f64 si = sphere(i), sj = sphere(j);
  ss_forces_f64 out;
  const int code = ss_table_pair_f64(table, itype - 1, jtype - 1, &si, &sj, values, &out);
  if (code != SS_OK)
    error->one(FLERR, "{}: single() for atoms {} and {}: {}", STYLE, atom->tag[i], atom->tag[j],
               SoftSphere::contact_error(code));
  if (!out.touching) return 0.0;

  const double del[3] = {si.position.x - sj.position.x, si.position.y - sj.position.y,
                         si.position.z - sj.position.z};
  const double on_i[3] = {-out.force_on_j.x, -out.force_on_j.y, -out.force_on_j.z};
  fforce = (on_i[0] * del[0] + on_i[1] * del[1] + on_i[2] * del[2]) / rsq;
  double fs = 0.0;
  for (int c = 0; c < 3; c++) {
    svector[c] = on_i[c] - fforce * del[c];
    fs += svector[c] * svector[c];
  }
  svector[3] = std::sqrt(fs);
  const double vr[3] = {atom->v[i][0] - atom->v[j][0], atom->v[i][1] - atom->v[j][1],
                        atom->v[i][2] - atom->v[j][2]};
  const double vnnr = (vr[0] * del[0] + vr[1] * del[1] + vr[2] * del[2]) / rsq;
  for (int c = 0; c < 3; c++) {
    svector[4 + c] = del[c] * vnnr;
    svector[7 + c] = vr[c] - del[c] * vnnr;
  }
  return 0.0;
}

void PairSoftSphere::transfer_history(double *source, double *target)
{
  if (ss_table_state_values_f64(table) == 0) {
    for (int m = 0; m < size_history; m++) target[m] = 0.0;
    return;
  }
  ss_table_mirror_state_f64(table, source, target);
}

/* Restart files: the law, the declared impact and every type pair's coefficients; not the
 * keyword coarse (a restarted run asks for a coarse step again, or stops at the accuracy
 * limit). The stored springs are the history fix's, which writes its own. */
void PairSoftSphere::write_restart_settings(FILE *fp)
{
  fwrite(&model, sizeof(int), 1, fp);
  fwrite(&style_law, sizeof(int), 1, fp);
  fwrite(&rolling, sizeof(int), 1, fp);
  fwrite(&style_coefficients, sizeof(style_coefficients), 1, fp);
  fwrite(&impact_speed, sizeof(double), 1, fp);
}

void PairSoftSphere::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &model, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &style_law, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &rolling, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &style_coefficients, sizeof(style_coefficients), 1, fp, nullptr, error);
    utils::sfread(FLERR, &impact_speed, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&model, 1, MPI_INT, 0, world);
  MPI_Bcast(&style_law, 1, MPI_INT, 0, world);
  MPI_Bcast(&rolling, 1, MPI_INT, 0, world);
  MPI_Bcast(&style_coefficients, sizeof(style_coefficients), MPI_BYTE, 0, world);
  MPI_Bcast(&impact_speed, 1, MPI_DOUBLE, 0, world);
}

void PairSoftSphere::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  const int n = atom->ntypes + 1;
  for (int i = 1; i < n; i++)
    for (int j = i; j < n; j++) {
      fwrite(&given[i * n + j], sizeof(int), 1, fp);
      fwrite(&coefficients[i * n + j], sizeof(ss_coefficients_f64), 1, fp);
    }
}

void PairSoftSphere::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  size_tables();
  const int n = atom->ntypes + 1;
  for (int i = 1; i < n; i++)
    for (int j = i; j < n; j++) {
      int flag = 0;
      ss_coefficients_f64 c;
      if (comm->me == 0) {
        utils::sfread(FLERR, &flag, sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &c, sizeof(c), 1, fp, nullptr, error);
      }
      MPI_Bcast(&flag, 1, MPI_INT, 0, world);
      MPI_Bcast(&c, sizeof(c), MPI_BYTE, 0, world);
      given[i * n + j] = given[j * n + i] = flag;
      coefficients[i * n + j] = coefficients[j * n + i] = c;
      setflag[i][j] = 1;
    }
}
