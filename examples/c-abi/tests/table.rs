//! The list entry (`ss_table_evaluate_*`) as LAMMPS calls it: flat atom arrays, a half
//! neighbour list of per-atom runs, per-neighbour history and touch flags, forces added with the
//! `newton_pair` rule. Each contact must give the bits of one `ss_sphere_sphere_*` call with the
//! law the mixing rule makes (geometric means; Hertz's and Mindlin's moduli), the forces summed
//! in list order; every bad count, index and value must be an error code that leaves every
//! array as it was.

use std::ptr::{null, null_mut};

use host_tests::random::Xorshift;
use soft_sphere_ffi::*;

const MODELS: [i32; 8] = [
    SS_MODEL_STATELESS,
    SS_MODEL_AA,
    SS_MODEL_AA_LUDING,
    SS_MODEL_FRICTIONLESS,
    SS_MODEL_HERTZ_FRICTIONLESS,
    SS_MODEL_HERTZ_STATELESS,
    SS_MODEL_HERTZ_AA,
    SS_MODEL_HERTZ_AA_LUDING,
];

const DT: f64 = 1.0e-7;
const SPEED: f64 = 10.0;
const RADIUS: f64 = 1.2e-3;

/// Three materials (soft, for the Hertz laws: the overlaps are the linear laws'), and a rough
/// pair given its own.
fn material(m: usize) -> ss_coefficients<f64> {
    [
        ss_coefficients {
            normal_stiffness: 1.0e4,
            restitution: 0.9,
            tangential_stiffness: 2.9e3,
            dashpot_ratio: 0.5,
            friction: 0.3,
            youngs_modulus: 5.0e6,
            poisson_ratio: 0.2,
            rolling_friction: 0.1,
            rolling_stiffness: 2.0e-6,
            rolling_damping: 1.0e-10,
        },
        ss_coefficients {
            normal_stiffness: 4.0e4,
            restitution: 0.7,
            tangential_stiffness: 1.1e4,
            dashpot_ratio: 0.4,
            friction: 0.5,
            youngs_modulus: 2.0e7,
            poisson_ratio: 0.3,
            rolling_friction: 0.3,
            rolling_stiffness: 8.0e-6,
            rolling_damping: 4.0e-10,
        },
        ss_coefficients {
            normal_stiffness: 2.0e4,
            restitution: 0.8,
            tangential_stiffness: 6.0e3,
            dashpot_ratio: 0.3,
            friction: 0.8,
            youngs_modulus: 1.0e7,
            poisson_ratio: 0.25,
            rolling_friction: 0.2,
            rolling_stiffness: 4.0e-6,
            rolling_damping: 0.0,
        },
    ][m]
}

/// Materials 0, 1 and 2 with their own coefficients, except that the pair (0, 2) is given its
/// own rough ones.
fn rough() -> ss_coefficients<f64> {
    ss_coefficients {
        friction: 0.9,
        restitution: 0.5,
        ..material(2)
    }
}

/// The coefficients a pair's law is made of, by the rule, computed here: `(a, b)`'s geometric
/// means, or Hertz's `E*` and Mindlin's `G*` from both materials.
fn reference_params(model: i32, a: usize, b: usize) -> ss_params<f64> {
    let (p, q) = if (a, b) == (0, 2) || (a, b) == (2, 0) {
        (rough(), rough())
    } else {
        (material(a), material(b))
    };
    let mean = |x: f64, y: f64| if x == y { x } else { (x * y).sqrt() };
    let mut params = ss_params {
        model,
        normal_stiffness: mean(p.normal_stiffness, q.normal_stiffness),
        restitution: mean(p.restitution, q.restitution),
        tangential_stiffness: mean(p.tangential_stiffness, q.tangential_stiffness),
        dashpot_ratio: mean(p.dashpot_ratio, q.dashpot_ratio),
        friction: mean(p.friction, q.friction),
        time_step: DT,
        smallest_effective_mass: 5.0e-6,
        largest_impact_speed: SPEED,
        largest_effective_radius: RADIUS,
        ..Default::default()
    };
    let (pm, qm) = (
        ss_material {
            youngs_modulus: p.youngs_modulus,
            poisson_ratio: p.poisson_ratio,
        },
        ss_material {
            youngs_modulus: q.youngs_modulus,
            poisson_ratio: q.poisson_ratio,
        },
    );
    // SAFETY: valid pointers.
    let code = unsafe {
        ss_effective_moduli_f64(
            &pm,
            &qm,
            &mut params.effective_modulus,
            &mut params.effective_shear_modulus,
        )
    };
    assert_eq!(code, SS_OK);
    if model == SS_MODEL_FRICTIONLESS {
        params.tangential_stiffness = 1.0;
    }
    params
}

fn table(model: i32) -> *mut ss_table<f64> {
    table_of(&ss_table_config {
        model,
        materials: 3,
        largest_impact_speed: SPEED,
        largest_effective_radius: RADIUS,
        ..Default::default()
    })
}

/// A table made from `config`, with the three materials and the rough pair set.
fn table_of(config: &ss_table_config<f64>) -> *mut ss_table<f64> {
    let mut table = null_mut();
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(ss_table_new_f64(config, &mut table), SS_OK);
        for m in 0..3 {
            assert_eq!(
                ss_table_set_f64(table, m, m, &material(m), null_mut()),
                SS_OK
            );
        }
        assert_eq!(ss_table_set_f64(table, 2, 0, &rough(), null_mut()), SS_OK);
    }
    table
}

fn prepare(table: *mut ss_table<f64>, masses: [f64; 3]) -> (i32, ss_table_report<f64>) {
    let mut report = ss_table_report::<f64>::default();
    // SAFETY: valid pointers.
    let code = unsafe { ss_table_prepare_f64(table, DT, masses.as_ptr(), &mut report) };
    (code, report)
}

/// What LAMMPS hands a pair style: atoms owned then ghost, a half list of per-atom runs, and
/// the history beside it.
#[derive(Clone, Debug, PartialEq)]
struct Host {
    owned: usize,
    position: Vec<f64>,
    velocity: Vec<f64>,
    spin: Vec<f64>,
    radius: Vec<f64>,
    mass: Vec<f64>,
    types: Vec<i32>,
    list: Vec<i32>,
    counts: Vec<i32>,
    neighbours: Vec<Vec<i32>>,
    values: usize,
    history: Vec<Vec<f64>>,
    touch: Vec<Vec<i32>>,
    force: Vec<f64>,
    torque: Vec<f64>,
    /// Each pair's force on its i, when asked for.
    pair_force: Option<Vec<f64>>,
}

/// Pointers into a host's arrays, built just before a call.
struct Views {
    first_neighbour: Vec<*const i32>,
    first_value: Vec<*mut f64>,
    first_touch: Vec<*mut i32>,
}

impl Host {
    /// 60 atoms (45 owned) of three types jittered on a lattice tighter than their diameters,
    /// so that most neighbours touch; random velocities, spins and stored values.
    fn new(seed: u64, values: usize) -> Self {
        let mut random = Xorshift::new(seed);
        let n = 60;
        let mut host = Host {
            owned: 45,
            position: Vec::new(),
            velocity: Vec::new(),
            spin: Vec::new(),
            radius: Vec::new(),
            mass: Vec::new(),
            types: Vec::new(),
            list: Vec::new(),
            counts: vec![0; n],
            neighbours: vec![Vec::new(); n],
            values,
            history: vec![Vec::new(); n],
            touch: vec![Vec::new(); n],
            force: (0..3 * n).map(|_| random.unit() - 0.5).collect(),
            torque: (0..3 * n).map(|_| 1e-3 * (random.unit() - 0.5)).collect(),
            pair_force: None,
        };
        for k in 0..n {
            let cell = [k % 4, (k / 4) % 4, k / 16].map(|c| c as f64 * 1.9e-3);
            for c in cell {
                host.position.push(c + 0.04e-3 * (random.unit() - 0.5));
                host.velocity.push(0.2 * (random.unit() - 0.5));
                host.spin.push(100.0 * (random.unit() - 0.5));
            }
            let r = 1.0e-3 * (1.0 + 0.1 * random.unit());
            host.radius.push(r);
            host.mass
                .push(2500.0 * 4.0 / 3.0 * std::f64::consts::PI * r * r * r);
            host.types.push(1 + (k % 3) as i32);
        }
        for i in 0..host.owned {
            host.list.push(i as i32);
            for j in i + 1..n {
                let d: f64 = (0..3)
                    .map(|c| host.position[3 * i + c] - host.position[3 * j + c])
                    .map(|x| x * x)
                    .sum::<f64>()
                    .sqrt();
                if d < host.radius[i] + host.radius[j] + 0.2e-3 {
                    host.neighbours[i].push(j as i32);
                    host.touch[i].push(0);
                    for _ in 0..values {
                        host.history[i].push(1e-6 * (random.unit() - 0.5));
                    }
                }
            }
            host.counts[i] = host.neighbours[i].len() as i32;
        }
        host
    }

    fn views(&mut self) -> Views {
        Views {
            first_neighbour: self.neighbours.iter().map(|v| v.as_ptr()).collect(),
            first_value: self.history.iter_mut().map(|v| v.as_mut_ptr()).collect(),
            first_touch: self.touch.iter_mut().map(|v| v.as_mut_ptr()).collect(),
        }
    }

    /// Calls the list entry over this host's arrays.
    fn evaluate(
        &mut self,
        table: *mut ss_table<f64>,
        newton: i32,
        advance: i32,
        edit: impl FnOnce(&mut ss_atoms<f64>, &mut ss_neighbours, &mut ss_history<f64>),
    ) -> (i32, ss_list_report) {
        let views = self.views();
        let mut atoms = self.atoms();
        let mut list = ss_neighbours {
            count: self.list.len(),
            atoms: self.list.as_ptr(),
            neighbour_counts: self.counts.as_ptr(),
            first_neighbour: views.first_neighbour.as_ptr(),
            index_mask: 0x1FFF_FFFF,
        };
        let mut history = ss_history::<f64> {
            values: self.values,
            first_value: views.first_value.as_ptr(),
            first_touch: views.first_touch.as_ptr(),
        };
        edit(&mut atoms, &mut list, &mut history);
        let loads = ss_loads {
            force: self.force.as_mut_ptr(),
            torque: self.torque.as_mut_ptr(),
            newton,
            pair_force: self
                .pair_force
                .as_mut()
                .map_or(null_mut(), |p| p.as_mut_ptr()),
        };
        let mut report = ss_list_report::default();
        // SAFETY: every pointer into this host's arrays, as long as they say.
        let code = unsafe {
            ss_table_evaluate_f64(table, &atoms, &list, &history, &loads, advance, &mut report)
        };
        (code, report)
    }

    /// The atoms as the C ABI reads them, types from 1.
    fn atoms(&self) -> ss_atoms<f64> {
        ss_atoms {
            count: self.radius.len(),
            owned: self.owned,
            position: self.position.as_ptr(),
            velocity: self.velocity.as_ptr(),
            angular_velocity: self.spin.as_ptr(),
            radius: self.radius.as_ptr(),
            mass: self.mass.as_ptr(),
            types: self.types.as_ptr(),
            first_type: 1,
        }
    }

    fn sphere(&self, k: usize) -> ss_sphere<f64> {
        let v = |a: &[f64]| ss_vec3 {
            x: a[3 * k],
            y: a[3 * k + 1],
            z: a[3 * k + 2],
        };
        ss_sphere {
            position: v(&self.position),
            velocity: v(&self.velocity),
            angular_velocity: v(&self.spin),
            radius: self.radius[k],
            mass: self.mass[k],
        }
    }

    /// The same step one pair at a time through `ss_sphere_sphere_f64`, each pair's law made
    /// from `reference_params`: forces summed from zero in list order, then added where the
    /// `newton_pair` rule sends them.
    fn one_at_a_time(&mut self, model: i32, newton: i32) -> usize {
        let n = self.radius.len();
        let (mut force, mut torque) = (vec![0.0; 3 * n], vec![0.0; 3 * n]);
        let mut touching = 0;
        let mut pair_force = Vec::new();
        for &i in &self.list.clone() {
            let i = i as usize;
            for (jj, &j) in self.neighbours[i].clone().iter().enumerate() {
                let j = (j & 0x1FFF_FFFF) as usize;
                let (a, b) = (self.types[i] as usize - 1, self.types[j] as usize - 1);
                let params = reference_params(model, a, b);
                let mut law = null_mut();
                let mut state =
                    state_of(&self.history[i][jj * self.values..(jj + 1) * self.values]);
                let mut out = ss_forces::default();
                // SAFETY: valid pointers.
                unsafe {
                    assert_eq!(ss_law_new_f64(&params, &mut law), SS_OK);
                    let code = ss_sphere_sphere_f64(
                        law,
                        &self.sphere(i),
                        &self.sphere(j),
                        &mut state,
                        &mut out,
                    );
                    assert_eq!(code, SS_OK);
                    ss_law_free_f64(law);
                }
                store(
                    &state,
                    &mut self.history[i][jj * self.values..(jj + 1) * self.values],
                );
                // A neighbour touches, for the host's history, when it keeps a state.
                let stored = &self.history[i][jj * self.values..(jj + 1) * self.values];
                let keeps = values_of(model) > 0 && stored.iter().any(|x| *x != 0.0);
                self.touch[i][jj] = i32::from(keeps);
                let f = out.force_on_j;
                pair_force.extend([-f.x, -f.y, -f.z]);
                touching += out.touching as usize;
                if out.touching == 1 {
                    let on_j = [out.force_on_j.x, out.force_on_j.y, out.force_on_j.z];
                    let (t_i, t_j) = (out.torque_on_i, out.torque_on_j);
                    for (c, (ti, tj)) in [(t_i.x, t_j.x), (t_i.y, t_j.y), (t_i.z, t_j.z)]
                        .into_iter()
                        .enumerate()
                    {
                        force[3 * i + c] -= on_j[c];
                        force[3 * j + c] += on_j[c];
                        torque[3 * i + c] += ti;
                        torque[3 * j + c] += tj;
                    }
                }
            }
        }
        if self.pair_force.is_some() {
            self.pair_force = Some(pair_force);
        }
        let receivers = if newton == 1 { n } else { self.owned };
        for k in 0..3 * receivers {
            self.force[k] += force[k];
            self.torque[k] += torque[k];
        }
        touching
    }
}

/// The C ABI state of a contact from its flat history numbers (3: Model AA's displacement; 4:
/// Mindlin's spring force and contact radius; none for the laws that keep nothing).
fn state_of(stored: &[f64]) -> ss_state<f64> {
    let mut state = ss_state::default();
    match stored.len() {
        3 => {
            state.displacement = ss_vec3 {
                x: stored[0],
                y: stored[1],
                z: stored[2],
            }
        }
        4 => {
            state.spring_force = ss_vec3 {
                x: stored[0],
                y: stored[1],
                z: stored[2],
            };
            state.contact_radius = stored[3];
        }
        _ => {}
    }
    state
}

/// `state` back into its flat history numbers.
fn store(state: &ss_state<f64>, stored: &mut [f64]) {
    let (d, f) = (state.displacement, state.spring_force);
    match stored.len() {
        3 => stored.copy_from_slice(&[d.x, d.y, d.z]),
        4 => stored.copy_from_slice(&[f.x, f.y, f.z, state.contact_radius]),
        _ => {}
    }
}

fn values_of(model: i32) -> usize {
    match model {
        SS_MODEL_AA | SS_MODEL_AA_LUDING => 3,
        SS_MODEL_HERTZ_AA | SS_MODEL_HERTZ_AA_LUDING => 4,
        _ => 0,
    }
}

fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn a_list_gives_the_bits_of_one_pair_at_a_time_for_every_law_and_newton_rule() {
    for model in MODELS {
        let table = table(model);
        assert_eq!(
            prepare(table, [1e-5; 3]),
            (
                SS_OK,
                ss_table_report {
                    materials: [-1, -1],
                    ..Default::default()
                }
            ),
            "model {model}"
        );
        // SAFETY: a valid table.
        let values = unsafe { ss_table_state_values_f64(table) };
        assert_eq!(values, values_of(model), "model {model}");
        for newton in [0, 1] {
            let mut host = Host::new(11 + model as u64, values.max(1));
            // Per-pair forces asked for with newton on (as LAMMPS does on virial steps).
            let pairs: usize = host.neighbours.iter().map(Vec::len).sum();
            if newton == 1 {
                host.pair_force = Some(vec![f64::NAN; 3 * pairs]);
            }
            let mut expected = host.clone();
            let mut touching = 0;
            // Three steps, so that stored springs carry from one to the next.
            for _ in 0..3 {
                let (code, report) = host.evaluate(table, newton, 1, |_, _, _| {});
                assert_eq!(code, SS_OK, "model {model}");
                touching = expected.one_at_a_time(model, newton);
                assert_eq!(report.contacts, touching, "model {model}");
            }
            assert!(touching > 40, "the scene must have contacts: {touching}");
            assert_eq!(bits(&host.force), bits(&expected.force), "model {model}");
            assert_eq!(bits(&host.torque), bits(&expected.torque), "model {model}");
            assert_eq!(host.touch, expected.touch, "model {model}");
            if let (Some(got), Some(wanted)) = (&host.pair_force, &expected.pair_force) {
                assert_eq!(bits(got), bits(wanted), "model {model}");
            }
            for (a, b) in host.history.iter().zip(&expected.history) {
                assert_eq!(bits(a), bits(b), "model {model}");
            }
            if newton == 0 {
                // Ghosts receive nothing.
                let start = Host::new(11 + model as u64, values.max(1));
                assert_eq!(bits(&host.force[3 * 45..]), bits(&start.force[3 * 45..]));
            }
        }
        // SAFETY: from ss_table_new_f64.
        unsafe { ss_table_free_f64(table) };
    }
}

#[test]
fn the_setup_evaluation_leaves_the_history_and_flags_the_neighbours_that_keep_a_state() {
    let table = table(SS_MODEL_AA);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    let mut host = Host::new(5, 3);
    // One neighbour with no stored state: it does not touch, for the history.
    host.history[0][..3].fill(0.0);
    let before = host.history.clone();
    let (code, report) = host.evaluate(table, 0, 0, |_, _, _| {});
    assert_eq!(code, SS_OK);
    assert_eq!(host.history, before);
    assert!(report.contacts > 40);
    for (flags, values) in host.touch.iter().zip(&host.history) {
        let kept: Vec<i32> = values
            .chunks(3)
            .map(|s| i32::from(s.iter().any(|x| *x != 0.0)))
            .collect();
        assert_eq!(flags, &kept);
    }
    assert_eq!(host.touch[0][0], 0);
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// A coarse step is taken only when asked for (`ss_table_prepare_coarse_f64`): within the
/// stability limit, its contacts past the accuracy limit are evaluated and counted; the plain
/// prepare refuses the same step, and neither takes one past the stability limit.
#[test]
fn a_coarse_step_is_taken_when_asked_and_its_inaccurate_contacts_counted() {
    let table = table(SS_MODEL_AA);
    let mut host = Host::new(5, 3);
    let mut lightest = [f64::INFINITY; 3];
    for (&m, &t) in host.mass.iter().zip(&host.types) {
        let l = &mut lightest[(t - 1) as usize];
        *l = l.min(m);
    }
    let mut report = ss_table_report::<f64>::default();
    // SAFETY: valid pointers.
    let prepare = |dt: f64, coarse: bool, report: &mut ss_table_report<f64>| unsafe {
        if coarse {
            ss_table_prepare_coarse_f64(table, dt, lightest.as_ptr(), report)
        } else {
            ss_table_prepare_f64(table, dt, lightest.as_ptr(), report)
        }
    };
    // Far past every limit: both refuse it as unstable, and report the first pair's stability
    // limit; 0.9 of the lowest of them is stable for every pair.
    let mut coarse = 1.0;
    assert_eq!(
        prepare(coarse, false, &mut report),
        SS_ERR_UNSTABLE_TIME_STEP
    );
    while prepare(coarse, true, &mut report) == SS_ERR_UNSTABLE_TIME_STEP {
        coarse = 0.9 * report.limit;
    }
    assert!(coarse < 1.0);
    // That step: taken by the coarse prepare, inaccurate for the plain one.
    assert_eq!(prepare(coarse, true, &mut report), SS_OK);
    assert_eq!(
        prepare(coarse, false, &mut report),
        SS_ERR_INACCURATE_TIME_STEP
    );
    let accurate = report.limit;
    assert!(accurate < 0.5 * coarse, "{accurate} {coarse}");
    assert_eq!(prepare(coarse, true, &mut report), SS_OK);
    let (code, coarse_report) = host.clone().evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!(code, SS_OK);
    assert!(coarse_report.contacts > 40, "{coarse_report:?}");
    assert!(
        coarse_report.inaccurate > 0 && coarse_report.inaccurate <= coarse_report.contacts,
        "{coarse_report:?}"
    );
    // An accurate step (below every pair's accuracy limit), prepared either way, counts none.
    let mut fine = accurate;
    while prepare(fine, false, &mut report) == SS_ERR_INACCURATE_TIME_STEP {
        fine = 0.9 * report.limit;
    }
    for asked in [false, true] {
        assert_eq!(prepare(fine, asked, &mut report), SS_OK);
        let (code, report) = host.evaluate(table, 1, 0, |_, _, _| {});
        assert_eq!((code, report.inaccurate), (SS_OK, 0), "{report:?}");
        assert!(report.contacts > 40);
    }
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// Every bad input: its code, the atoms it names, and nothing changed.
#[test]
fn bad_lists_are_refused_with_nothing_changed() {
    type Edit = fn(&mut ss_atoms<f64>, &mut ss_neighbours, &mut ss_history<f64>);
    let cases: [(&str, Edit, i32, [i64; 2]); 8] = [
        (
            "null positions",
            |a, _, _| a.position = null(),
            SS_ERR_NULL,
            [-1, -1],
        ),
        (
            "owned past the atoms",
            |a, _, _| a.owned = a.count + 1,
            SS_ERR_LENGTH,
            [-1, -1],
        ),
        (
            "list longer than the atoms",
            |a, l, _| l.count = a.count + 1,
            SS_ERR_LENGTH,
            [-1, -1],
        ),
        (
            "too few history values",
            |_, _, h| h.values = 2,
            SS_ERR_LENGTH,
            [-1, -1],
        ),
        (
            "a type past the table",
            |a, _, _| a.first_type = 2,
            SS_ERR_MATERIAL,
            [0, -1],
        ),
        (
            "null first neighbour",
            |_, l, _| l.first_neighbour = null(),
            SS_ERR_NULL,
            [-1, -1],
        ),
        (
            "the list truncated (mask)",
            |_, l, _| l.index_mask = 0,
            SS_ERR_OK_MARKER,
            [-1, -1],
        ),
        (
            "null touch flags",
            |_, _, h| h.first_touch = null(),
            SS_ERR_NULL,
            [-1, -1],
        ),
    ];
    let table = table(SS_MODEL_AA);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    for (name, edit, code, atoms) in cases {
        let mut host = Host::new(3, 3);
        let before = host.clone();
        let (got, report) = host.evaluate(table, 0, 1, edit);
        if code == SS_ERR_OK_MARKER {
            // Every neighbour masked to atom 0: pairs (0, 0) coincide.
            assert_eq!(got, SS_ERR_COINCIDENT_CENTRES, "{name}");
            assert_eq!(report.atoms, [0, 0], "{name}");
        } else {
            assert_eq!(got, code, "{name}");
            assert_eq!(report.atoms, atoms, "{name}");
        }
        assert_eq!(host, before, "{name}: nothing may change");
    }
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// A marker for the case whose code depends on the data (see its comment).
const SS_ERR_OK_MARKER: i32 = -1;

#[test]
fn bad_atoms_and_indices_name_the_atoms() {
    let table = table(SS_MODEL_HERTZ_AA);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    // A neighbour past the atoms.
    let mut host = Host::new(9, 4);
    host.neighbours[7][1] = 60;
    let before = host.clone();
    let (code, report) = host.evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!((code, report.atoms), (SS_ERR_INDEX, [7, 60]));
    assert_eq!(host, before);
    // An atom of the list past the atoms, and a negative count.
    let mut host = Host::new(9, 4);
    host.list[3] = -2;
    let (code, report) = host.evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!((code, report.atoms), (SS_ERR_INDEX, [-2, -1]));
    let mut host = Host::new(9, 4);
    host.counts[4] = -1;
    let (code, report) = host.evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!((code, report.atoms), (SS_ERR_LENGTH, [4, -1]));
    // A NaN velocity and a mass that is not positive: the atom named, nothing changed.
    let mut host = Host::new(9, 4);
    host.velocity[3 * 12 + 1] = f64::NAN;
    let before = host.clone();
    let (code, report) = host.evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!((code, report.atoms), (SS_ERR_NON_FINITE_INPUT, [12, -1]));
    assert_eq!(bits(&host.force), bits(&before.force));
    // A NaN or an infinity already in a force or torque the contacts would be added to (it
    // passed through every sum): the atom named, nothing changed. A ghost's is not added to
    // without Newton's third law, and not read.
    for (newton, at, code) in [
        (1, 3 * 20 + 2, SS_ERR_NON_FINITE_INPUT),
        (0, 3 * 50, SS_OK),
        (1, 3 * 50, SS_ERR_NON_FINITE_INPUT),
    ] {
        for torque in [false, true] {
            let mut host = Host::new(9, 4);
            if torque {
                host.torque[at] = f64::INFINITY;
            } else {
                host.force[at] = f64::NAN;
            }
            let before = host.clone();
            let (got, report) = host.evaluate(table, newton, 1, |_, _, _| {});
            assert_eq!(got, code, "newton {newton}, at {at}");
            if code != SS_OK {
                assert_eq!(report.atoms, [at as i64 / 3, -1]);
                assert_eq!(bits(&host.force), bits(&before.force));
                assert_eq!(bits(&host.torque), bits(&before.torque));
            }
        }
    }
    // At every place of the loads, each kind of bad number, and a pair that cancels in a sum
    // (an infinity and its negative): the first atom that receives loads named (all 60 with
    // Newton's third law, the 45 owned without). Finite loads whose sum overflows are not
    // refused.
    for (newton, receivers) in [(1, 60), (0, 45)] {
        for at in 0..3 * 60 {
            for (first, second) in [
                (f64::NAN, 0.0),
                (f64::NEG_INFINITY, 0.0),
                (f64::INFINITY, f64::NEG_INFINITY),
            ] {
                let mut host = Host::new(9, 4);
                let places = [at, 3 * 60 - 1 - at, (at + 7) % (3 * 60)];
                host.force[places[0]] = first;
                host.torque[places[1]] = second;
                host.torque[places[2]] = second;
                let bad = if second == 0.0 {
                    &places[..1]
                } else {
                    &places[..]
                };
                let named = bad.iter().map(|&p| p / 3).filter(|&k| k < receivers).min();
                let (code, report) = host.evaluate(table, newton, 1, |_, _, _| {});
                match named {
                    Some(k) => assert_eq!(
                        (code, report.atoms),
                        (SS_ERR_NON_FINITE_INPUT, [k as i64, -1])
                    ),
                    None => assert_eq!(code, SS_OK),
                }
            }
        }
    }
    let mut host = Host::new(9, 4);
    host.force.iter_mut().step_by(2).for_each(|f| *f = f64::MAX);
    assert_eq!(host.evaluate(table, 1, 1, |_, _, _| {}).0, SS_OK);
    let mut host = Host::new(9, 4);
    host.mass[50] = 0.0;
    let (code, report) = host.evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!((code, report.atoms), (SS_ERR_NON_POSITIVE_MASS, [50, -1]));
    // A pair lighter than the step was checked for: past the stable step, both atoms named.
    let light = table_for_heavy_atoms();
    let mut host = Host::new(9, 4);
    let before = host.clone();
    let (code, report) = host.evaluate(light, 1, 1, |_, _, _| {});
    assert_eq!(code, SS_ERR_PAST_STABLE_STEP);
    assert!(report.atoms[0] >= 0 && report.atoms[1] >= 0);
    assert_eq!(host, before);
    // SAFETY: from ss_table_new_f64.
    unsafe {
        ss_table_free_f64(light);
        ss_table_free_f64(table);
    }
}

/// A stiff linear table whose step is checked for atoms far heavier than the host's.
fn table_for_heavy_atoms() -> *mut ss_table<f64> {
    let table = table(SS_MODEL_AA);
    let mut report = ss_table_report::<f64>::default();
    // SAFETY: valid pointers.
    unsafe {
        for (a, b) in [(0, 0), (1, 1), (2, 2), (0, 2)] {
            let stiff = ss_coefficients {
                normal_stiffness: 1.0e11,
                ..material(a)
            };
            assert_eq!(ss_table_set_f64(table, a, b, &stiff, null_mut()), SS_OK);
        }
        let heavy = [1.0; 3];
        assert_eq!(
            ss_table_prepare_f64(table, DT, heavy.as_ptr(), &mut report),
            SS_OK
        );
    }
    table
}

/// The Model AA table with material 1 made 100 times stiffer than material 0 (`k_n` 1e6).
fn table_with_stiff_material_1() -> *mut ss_table<f64> {
    let table = table(SS_MODEL_AA);
    let stiff = ss_coefficients {
        normal_stiffness: 1.0e6,
        ..material(1)
    };
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { ss_table_set_f64(table, 1, 1, &stiff, null_mut()) },
        SS_OK
    );
    table
}

#[test]
fn the_step_is_checked_against_the_stiffest_pair_present() {
    // Material 1 made 100 times stiffer than material 0 (its mixed pairs 10 times): with equal
    // masses, its pair with itself binds. Undamped, the limit is 2 / omega = 2 sqrt(m* / k)
    // (m* = m / 2); damping only lowers it.
    let table = table_with_stiff_material_1();
    let m = 1.0e-9;
    let undamped = 2.0 * (m / 2.0 / 1.0e6_f64).sqrt();
    let mut report = ss_table_report::<f64>::default();
    // Material 1 alone: past its stability limit, refused as unstable with that limit.
    // SAFETY: valid pointers.
    let code =
        unsafe { ss_table_prepare_f64(table, 1.5 * undamped, [0.0, m, 0.0].as_ptr(), &mut report) };
    assert_eq!(code, SS_ERR_UNSTABLE_TIME_STEP);
    assert_eq!(report.materials, [1, 1]);
    assert_eq!(report.parameter, SS_PARAMETER_TIME_STEP);
    assert!(report.limit < undamped && report.limit > 0.5 * undamped);
    // Below it but past its accuracy limit: refused as inaccurate, with the accurate step.
    let stable = report.limit;
    // SAFETY: valid pointers.
    let code =
        unsafe { ss_table_prepare_f64(table, 0.9 * stable, [0.0, m, 0.0].as_ptr(), &mut report) };
    assert_eq!(code, SS_ERR_INACCURATE_TIME_STEP);
    assert_eq!(report.materials, [1, 1]);
    assert!(report.limit < 0.5 * stable && report.limit > 0.0);
    // Just past that limit: refused with material 1's atoms present, passed without them
    // (every other pair is softer).
    let just_past = 1.01 * report.limit;
    // SAFETY: valid pointers.
    let code = unsafe { ss_table_prepare_f64(table, just_past, [m; 3].as_ptr(), &mut report) };
    assert_eq!(
        (code, report.materials),
        (SS_ERR_INACCURATE_TIME_STEP, [1, 1])
    );
    // SAFETY: valid pointers.
    let code = unsafe { ss_table_prepare_f64(table, just_past, [m, 0.0, m].as_ptr(), null_mut()) };
    assert_eq!(code, SS_OK);
    // A table refused is not evaluated.
    // SAFETY: valid pointers.
    let code = unsafe { ss_table_prepare_f64(table, 1.5 * undamped, [m; 3].as_ptr(), null_mut()) };
    assert_ne!(code, SS_OK);
    let mut host = Host::new(1, 3);
    let before = host.clone();
    assert_eq!(
        host.evaluate(table, 1, 1, |_, _, _| {}).0,
        SS_ERR_NOT_PREPARED
    );
    assert_eq!(host, before);
    // A mass that is not a number is refused, not taken for an absent material.
    let mut report = ss_table_report {
        materials: [7, 7],
        ..Default::default()
    };
    // SAFETY: valid pointers.
    let code = unsafe { ss_table_prepare_f64(table, DT, [m, f64::NAN, m].as_ptr(), &mut report) };
    assert_eq!(
        (code, report.materials),
        (SS_ERR_NON_FINITE_INPUT, [-1, -1])
    );
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

#[test]
fn the_step_is_checked_against_the_walls_materials() {
    // Against material 0's spheres a wall of the stiff material 1 has the mixed
    // k = sqrt(1e4 1e6) = 1e5 at the sphere's own mass m, a pair of material 0's spheres 1e4 at
    // m / 2. Undamped, the limits are 2 sqrt(m* / k), the wall's sqrt(5) times the shorter;
    // damping only lowers them.
    let table = table_with_stiff_material_1();
    let m = 1.0e-9;
    let wall_undamped = 2.0 * (m / 1.0e5_f64).sqrt();
    let dt = 1.5 * wall_undamped;
    let lightest = [m, 0.0, 0.0];
    let prepare = |report: &mut ss_table_report<f64>| {
        // SAFETY: valid pointers.
        unsafe { ss_table_prepare_coarse_f64(table, dt, lightest.as_ptr(), report) }
    };
    let mut report = ss_table_report::<f64>::default();
    // No walls: only the pair of material 0 is checked, and that step is stable for it.
    assert_eq!(prepare(&mut report), SS_OK);
    // A wall of material 1: refused at the wall's limit, naming material 0 with the wall's.
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { ss_table_set_walls_f64(table, [1].as_ptr(), 1) },
        SS_OK
    );
    let mut host = Host::new(1, 3);
    let before = host.clone();
    assert_eq!(
        host.evaluate(table, 1, 1, |_, _, _| {}).0,
        SS_ERR_NOT_PREPARED,
        "a table is prepared again after its walls change"
    );
    assert_eq!(host, before);
    assert_eq!(prepare(&mut report), SS_ERR_UNSTABLE_TIME_STEP);
    assert_eq!(report.materials, [0, 1]);
    assert!(report.limit < wall_undamped && report.limit > 0.5 * wall_undamped);
    // Bad input changes nothing: an id past the table, a null table or null ids.
    // SAFETY: valid pointers, or null where the test says.
    unsafe {
        assert_eq!(
            ss_table_set_walls_f64(table, [0, 3].as_ptr(), 2),
            SS_ERR_MATERIAL
        );
        assert_eq!(
            ss_table_set_walls_f64(null_mut(), [0].as_ptr(), 1),
            SS_ERR_NULL
        );
        assert_eq!(ss_table_set_walls_f64(table, null(), 1), SS_ERR_NULL);
    }
    assert_eq!(
        prepare(&mut report),
        SS_ERR_UNSTABLE_TIME_STEP,
        "the walls given before are kept"
    );
    assert_eq!(report.materials, [0, 1]);
    // A wall of material 0's own: its k is 1e4 at m, as stable as the pair.
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { ss_table_set_walls_f64(table, [0].as_ptr(), 1) },
        SS_OK
    );
    assert_eq!(prepare(&mut report), SS_OK);
    // None again (null with no ids is allowed).
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_table_set_walls_f64(table, null(), 0) }, SS_OK);
    assert_eq!(prepare(&mut report), SS_OK);
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// A still floor at `z = -0.9 mm`, which the hosts' lowest atoms reach.
fn floor() -> ss_wall<f64> {
    ss_wall {
        point: ss_vec3 {
            x: 0.0,
            y: 0.0,
            z: -0.9e-3,
        },
        direction: ss_vec3 {
            x: 0.0,
            y: 0.0,
            z: 1.0,
        },
        ..ss_wall::default()
    }
}

/// Model AA, three materials.
fn three_aa() -> ss_table_config<f64> {
    ss_table_config {
        model: SS_MODEL_AA,
        materials: 3,
        ..Default::default()
    }
}

/// A Model AA table of three materials, coefficients given to those named alone.
fn three_aa_materials(given: &[usize]) -> *mut ss_table<f64> {
    let mut table = null_mut();
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(ss_table_new_f64(&three_aa(), &mut table), SS_OK);
        for &m in given {
            assert_eq!(
                ss_table_set_f64(table, m, m, &material(m), null_mut()),
                SS_OK
            );
        }
    }
    table
}

/// Under `pair_style hybrid` another style owns some pairs of types: a table evaluates the pairs
/// it is given alone. Material 2 has no coefficients here and is in none of them.
#[test]
fn a_table_evaluates_only_the_pairs_it_is_given() {
    let table = three_aa_materials(&[0, 1]);
    // Every pair: material 2, present, has nothing to mix from.
    assert_eq!(
        prepare(table, [1e-5; 3]),
        (SS_ERR_MATERIAL, report_of([0, 2]))
    );
    // SAFETY: valid pointers.
    let set = |ids: &[u32]| unsafe { ss_table_set_pairs_f64(table, ids.as_ptr(), ids.len() / 2) };
    assert_eq!(set(&[0, 0, 1, 0, 1, 1]), SS_OK);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);

    // The pairs given give the bits of a table of every pair; a pair of material 2 is refused
    // with its atoms named, nothing changed.
    let full = table_of(&three_aa());
    assert_eq!(prepare(full, [1e-5; 3]).0, SS_OK);
    let mut host = Host::new(3, 3);
    let mut reference = host.clone();
    let before = host.clone();
    let (code, report_3) = host.evaluate(table, 1, 1, |_, _, _| {});
    assert_eq!(code, SS_ERR_MATERIAL);
    let first_foreign = (host.list.iter())
        .flat_map(|&i| host.neighbours[i as usize].iter().map(move |&j| [i, j]))
        .find(|pair| pair.iter().any(|&k| host.types[k as usize] == 3))
        .expect("a pair with an atom of type 3");
    assert_eq!(report_3.atoms, first_foreign.map(i64::from));
    assert_eq!(host, before);
    for t in [&mut host.types, &mut reference.types] {
        t.iter_mut().filter(|t| **t == 3).for_each(|t| *t = 1);
    }
    assert_eq!(host.evaluate(table, 1, 1, |_, _, _| {}).0, SS_OK);
    assert_eq!(reference.evaluate(full, 1, 1, |_, _, _| {}).0, SS_OK);
    assert_eq!(bits(&host.force), bits(&reference.force));
    assert_eq!(bits(&host.torque), bits(&reference.torque));
    assert_eq!(host.history, reference.history);

    // One pair at a time: the same answer.
    let (si, sj) = (host.sphere(0), host.sphere(1));
    let mut out = ss_forces::default();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(
            ss_table_pair_f64(table, 0, 1, &si, &sj, null(), &mut out),
            SS_OK
        );
        assert_eq!(
            ss_table_pair_f64(table, 0, 2, &si, &sj, null(), &mut out),
            SS_ERR_MATERIAL
        );
        assert_eq!(
            ss_table_pair_f64(table, 2, 2, &si, &sj, null(), &mut out),
            SS_ERR_MATERIAL
        );
    }

    // The step is checked for the pairs given alone: material 2 made too stiff for the step is
    // another style's business, until every pair is the table's again.
    let stiff = ss_coefficients {
        normal_stiffness: 1.0e11,
        ..material(2)
    };
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { ss_table_set_f64(table, 2, 2, &stiff, null_mut()) },
        SS_OK
    );
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    // And a pair given that is too stiff is refused, naming it.
    assert_eq!(set(&[0, 0, 2, 2]), SS_OK);
    let (code, refused) = prepare(table, [1e-5; 3]);
    assert_eq!(
        (code, refused.materials),
        (SS_ERR_UNSTABLE_TIME_STEP, [2, 2])
    );
    // Not with material 2 absent.
    assert_eq!(prepare(table, [1e-5, 1e-5, 0.0]).0, SS_OK);

    // Every material present is checked against the walls, whichever pairs the table
    // evaluates: a wall of the stiff material 2 against material 0 (k sqrt(1e4 1e11)) at
    // its lightest atom's mass.
    assert_eq!(set(&[0, 0]), SS_OK);
    assert_eq!(prepare(table, [1e-6, 0.0, 0.0]).0, SS_OK);
    // SAFETY: valid pointers.
    assert_eq!(
        unsafe { ss_table_set_walls_f64(table, [2].as_ptr(), 1) },
        SS_OK
    );
    let (code, refused) = prepare(table, [1e-6, 0.0, 0.0]);
    assert_eq!(
        (code, refused.materials),
        (SS_ERR_INACCURATE_TIME_STEP, [0, 2])
    );
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_table_set_walls_f64(table, null(), 0) }, SS_OK);
    assert_eq!(set(&[0, 0, 2, 2]), SS_OK);

    // Bad input changes nothing: an id past the table, a null table, null ids, a count past
    // memory. A table whose pairs change is prepared again before it evaluates.
    // SAFETY: valid pointers, or null where the test says.
    unsafe {
        assert_eq!(set(&[0, 0, 0, 3]), SS_ERR_MATERIAL);
        assert_eq!(
            ss_table_set_pairs_f64(null_mut(), [0, 0].as_ptr(), 1),
            SS_ERR_NULL
        );
        assert_eq!(ss_table_set_pairs_f64(table, null(), 1), SS_ERR_NULL);
        assert_eq!(
            ss_table_set_pairs_f64(table, [0, 0].as_ptr(), usize::MAX / 2 + 1),
            SS_ERR_LENGTH
        );
    }
    let (code, refused) = prepare(table, [1e-5; 3]);
    assert_eq!(
        (code, refused.materials),
        (SS_ERR_UNSTABLE_TIME_STEP, [2, 2]),
        "the pairs given before are kept"
    );
    assert_eq!(set(&[0, 1]), SS_OK);
    let before = host.clone();
    assert_eq!(
        host.evaluate(table, 1, 1, |_, _, _| {}).0,
        SS_ERR_NOT_PREPARED
    );
    assert_eq!(host, before);
    // None: every pair again (null with no ids is allowed).
    // SAFETY: valid pointers.
    assert_eq!(unsafe { ss_table_set_pairs_f64(table, null(), 0) }, SS_OK);
    // The first pair of material 2 refuses: with material 0 (k sqrt(1e4 1e11)), inaccurate.
    let report = prepare(table, [1e-5; 3]).1;
    assert_eq!(
        (prepare(table, [1e-5; 3]).0, report.materials),
        (SS_ERR_INACCURATE_TIME_STEP, [0, 2])
    );
    assert_eq!(report.parameter, SS_PARAMETER_TIME_STEP);
    // SAFETY: from ss_table_new_f64.
    unsafe {
        ss_table_free_f64(table);
        ss_table_free_f64(full);
    }
}

/// A table of some pairs still meets the walls with every material present: a material with
/// no coefficients to meet a wall by is refused, naming it and the wall, rather than meeting
/// it by another pair's law.
#[test]
fn a_material_present_meets_the_walls_by_its_own_law() {
    let table = three_aa_materials(&[0, 2]);
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(ss_table_set_pairs_f64(table, [0, 0].as_ptr(), 1), SS_OK);
        assert_eq!(ss_table_set_walls_f64(table, [2].as_ptr(), 1), SS_OK);
    }
    // Material 1 absent: its pairs are nobody's, and it needs no coefficients.
    assert_eq!(prepare(table, [1e-5, 0.0, 0.0]).0, SS_OK);
    // Present: it meets the wall of material 2, and has nothing to mix with it.
    assert_eq!(
        prepare(table, [1e-5, 1e-5, 0.0]),
        (SS_ERR_MATERIAL, report_of([1, 2]))
    );
    // Absent at the prepare, an atom of material 1 (type 2) that comes to the walls is refused,
    // named, nothing written; the others meet the floor.
    assert_eq!(prepare(table, [1e-5, 0.0, 0.0]).0, SS_OK);
    let mut host = Host::new(7, 1);
    let n = host.radius.len();
    let floor = [floor()];
    let mut states = vec![0.0; 7 * n];
    let every = vec![1; n];
    let but_type_2: Vec<i32> = host.types.iter().map(|&t| i32::from(t != 2)).collect();
    let atoms = host.atoms();
    let loads = ss_loads {
        force: host.force.as_mut_ptr(),
        torque: host.torque.as_mut_ptr(),
        newton: 0,
        pair_force: null_mut(),
    };
    let evaluate = |atoms: &ss_atoms<f64>, selected: &[i32], states: &mut [f64]| {
        let walls = ss_walls {
            count: 1,
            walls: floor.as_ptr(),
            material: 2,
            states: states.as_mut_ptr(),
            stride: 7,
            wall_stride: 7,
            selected: selected.as_ptr(),
            bit: 1,
        };
        let mut report = ss_list_report::default();
        // SAFETY: valid pointers, as long as they say.
        let code =
            unsafe { ss_table_evaluate_walls_f64(table, atoms, &walls, &loads, 1, &mut report) };
        (code, report.atoms)
    };
    // SAFETY: the forces, `3 n` numbers.
    let forces = || bits(unsafe { std::slice::from_raw_parts(loads.force, 3 * n) });
    let before = forces();
    assert_eq!(
        evaluate(&atoms, &every, &mut states),
        (SS_ERR_MATERIAL, [1, -1])
    );
    assert_eq!(states, vec![0.0; 7 * n]);
    assert_eq!(forces(), before);
    assert_eq!(evaluate(&atoms, &but_type_2, &mut states).0, SS_OK);
    assert!(states.iter().any(|&v| v != 0.0), "the floor must touch");
    // A type below the first, past the table, or past any table (no bit of the walls' mask):
    // the first atom is named, nothing written.
    let (kept, before) = (bits(&states), forces());
    let mut selected = but_type_2.clone();
    selected[0] = 1;
    for bad in [0, 4, 17, 40, i32::MAX] {
        let mut types = host.types.clone();
        types[0] = bad;
        let atoms = ss_atoms {
            types: types.as_ptr(),
            ..atoms
        };
        let refused = evaluate(&atoms, &selected, &mut states);
        assert_eq!(refused, (SS_ERR_MATERIAL, [0, -1]), "type {bad}");
        assert_eq!((bits(&states), forces()), (kept.clone(), before.clone()));
    }
    // Given its coefficients, material 1 meets the walls of material 2 by its own law.
    // SAFETY: valid pointers.
    let code = unsafe { ss_table_set_f64(table, 1, 1, &material(1), null_mut()) };
    assert_eq!(code, SS_OK);
    assert_eq!(prepare(table, [1e-5, 1e-5, 0.0]).0, SS_OK);
    assert_eq!(evaluate(&atoms, &every, &mut states), (SS_OK, [-1, -1]));
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// A report naming materials `materials` and no parameter.
fn report_of(materials: [i64; 2]) -> ss_table_report<f64> {
    ss_table_report {
        materials,
        ..Default::default()
    }
}

/// A material id past the table's count is refused one pair at a time, as in a list.
#[test]
fn a_single_pair_past_the_table_is_refused() {
    let table = table(SS_MODEL_AA);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    let host = Host::new(4, 3);
    let (si, sj) = (host.sphere(0), host.sphere(1));
    let mut out = ss_forces::default();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(
            ss_table_pair_f64(table, 0, 1, &si, &sj, null(), &mut out),
            SS_OK
        );
        for (a, b) in [(3, 0), (0, 3), (SS_MATERIALS_MAX, 0), (usize::MAX, 1)] {
            assert_eq!(
                ss_table_pair_f64(table, a, b, &si, &sj, null(), &mut out),
                SS_ERR_MATERIAL,
                "materials {a} and {b}"
            );
        }
        ss_table_free_f64(table);
    }
}

#[test]
fn tables_refuse_bad_coefficients_and_missing_materials() {
    let config = ss_table_config {
        model: SS_MODEL_HERTZ_AA,
        materials: 2,
        largest_impact_speed: SPEED,
        largest_effective_radius: RADIUS,
        ..Default::default()
    };
    let mut table = null_mut();
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(ss_table_new_f64(&config, &mut table), SS_OK);
        let mut parameter = 0;
        let bad = ss_coefficients {
            poisson_ratio: 0.7,
            ..material(0)
        };
        assert_eq!(
            ss_table_set_f64(table, 0, 0, &bad, &mut parameter),
            SS_ERR_POISSON_RATIO
        );
        assert_eq!(parameter, SS_PARAMETER_POISSON_RATIO);
        let bad = ss_coefficients {
            restitution: 1.5,
            ..material(0)
        };
        assert_eq!(
            ss_table_set_f64(table, 0, 0, &bad, &mut parameter),
            SS_ERR_RESTITUTION
        );
        assert_eq!(parameter, SS_PARAMETER_RESTITUTION);
        assert_eq!(
            ss_table_set_f64(table, 0, 2, &material(0), &mut parameter),
            SS_ERR_MATERIAL
        );
        // Material 1 has no coefficients and no pair of its own: the pair (0, 1) has no law.
        assert_eq!(
            ss_table_set_f64(table, 0, 0, &material(0), null_mut()),
            SS_OK
        );
        let mut report = ss_table_report::<f64>::default();
        let code = ss_table_prepare_f64(table, DT, [1e-5; 2].as_ptr(), &mut report);
        assert_eq!((code, report.materials), (SS_ERR_MATERIAL, [0, 1]));
        ss_table_free_f64(table);
        // Unknown models, no materials, too many, a bad declared impact.
        for (model, materials, speed, code) in [
            (99, 1, SPEED, SS_ERR_UNKNOWN_MODEL),
            (SS_MODEL_AA, 0, SPEED, SS_ERR_MATERIAL),
            (SS_MODEL_AA, SS_MATERIALS_MAX + 1, SPEED, SS_ERR_MATERIAL),
            (SS_MODEL_HERTZ_AA, 1, -1.0, SS_ERR_NOT_POSITIVE),
        ] {
            let config = ss_table_config {
                model,
                materials,
                largest_impact_speed: speed,
                largest_effective_radius: RADIUS,
                ..Default::default()
            };
            let mut table = null_mut();
            assert_eq!(ss_table_new_f64(&config, &mut table), code);
            assert!(table.is_null());
        }
    }
}

/// The state seen from the other body gives the opposite force: action and reaction, and the
/// torques swapped, for a contact with a stored spring.
#[test]
fn a_mirrored_state_with_the_bodies_swapped_gives_the_reaction() {
    for model in [SS_MODEL_AA, SS_MODEL_HERTZ_AA_LUDING] {
        let table = table(model);
        assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
        let mut host = Host::new(21, values_of(model));
        // A few steps so the springs are the kernel's own.
        for _ in 0..5 {
            assert_eq!(host.evaluate(table, 1, 1, |_, _, _| {}).0, SS_OK);
        }
        let (i, jj) = (0..45)
            .flat_map(|i| (0..host.neighbours[i].len()).map(move |jj| (i, jj)))
            .find(|&(i, jj)| {
                host.history[i][jj * host.values..][..3]
                    .iter()
                    .any(|x| *x != 0.0)
            })
            .expect("a stored spring");
        let j = host.neighbours[i][jj] as usize;
        let (a, b) = (host.types[i] as usize - 1, host.types[j] as usize - 1);
        let state = host.history[i][jj * host.values..(jj + 1) * host.values].to_vec();
        let mut mirrored = vec![0.0; state.len()];
        let (mut forward, mut backward) = (ss_forces::default(), ss_forces::default());
        // SAFETY: valid pointers throughout.
        unsafe {
            assert_eq!(
                ss_table_mirror_state_f64(table, state.as_ptr(), mirrored.as_mut_ptr()),
                SS_OK
            );
            let (si, sj) = (host.sphere(i), host.sphere(j));
            assert_eq!(
                ss_table_pair_f64(table, a, b, &si, &sj, state.as_ptr(), &mut forward),
                SS_OK
            );
            assert_eq!(
                ss_table_pair_f64(table, b, a, &sj, &si, mirrored.as_ptr(), &mut backward),
                SS_OK
            );
        }
        assert_eq!(forward.touching, 1);
        let scale = forward.normal_force.abs();
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * scale;
        let (f, g) = (forward.force_on_j, backward.force_on_j);
        assert!(
            close(f.x, -g.x) && close(f.y, -g.y) && close(f.z, -g.z),
            "{f:?} {g:?}"
        );
        let (t, u) = (forward.torque_on_i, backward.torque_on_j);
        assert!(close(t.x, u.x) && close(t.y, u.y) && close(t.z, u.z));
        if model == SS_MODEL_HERTZ_AA_LUDING {
            assert_eq!(mirrored[3], state[3], "the contact radius is kept");
        }
        // Either pointer null: refused, nothing written.
        let before = mirrored.clone();
        // SAFETY: null pointers are refused before anything is read.
        unsafe {
            assert_eq!(
                ss_table_mirror_state_f64(table, null(), mirrored.as_mut_ptr()),
                SS_ERR_NULL
            );
            assert_eq!(
                ss_table_mirror_state_f64(table, state.as_ptr(), null_mut()),
                SS_ERR_NULL
            );
        }
        assert_eq!(mirrored, before);
        // SAFETY: from ss_table_new_f64.
        unsafe { ss_table_free_f64(table) };
    }
}

/// The f32 entry: three spheres in a row, the middle one of the stiffer material, each contact
/// the bits of `ss_sphere_sphere_f32` with the mixed law, forces summed in list order.
#[test]
fn the_f32_list_entry_gives_the_single_calls_bits() {
    let coefficients = |k: f32| ss_coefficients::<f32> {
        normal_stiffness: k,
        restitution: 0.9,
        tangential_stiffness: 0.3 * k,
        dashpot_ratio: 0.5,
        friction: 0.4,
        ..Default::default()
    };
    let config = ss_table_config::<f32> {
        model: SS_MODEL_AA,
        materials: 2,
        ..Default::default()
    };
    let position: [f32; 9] = [0.0, 0.0, 0.0, 1.9e-3, 0.1e-3, 0.0, 3.8e-3, 0.0, 0.05e-3];
    let velocity: [f32; 9] = [0.1, 0.0, 0.02, -0.1, 0.05, 0.0, 0.0, -0.03, 0.01];
    let spin: [f32; 9] = [0.0, 5.0, 0.0, 1.0, 0.0, -3.0, 0.0, 0.0, 2.0];
    let (radius, mass, types) = ([1.0e-3_f32; 3], [1.0e-5_f32; 3], [0, 1, 0]);
    let neighbours: [Vec<i32>; 3] = [vec![1], vec![2], vec![]];
    let first: Vec<*const i32> = neighbours.iter().map(|v| v.as_ptr()).collect();
    let mut values: Vec<Vec<f32>> = vec![vec![1e-6, -2e-6, 0.0], vec![0.0, 3e-6, 1e-6], vec![]];
    let mut touch: Vec<Vec<i32>> = vec![vec![0], vec![0], vec![]];
    let first_value: Vec<*mut f32> = values.iter_mut().map(|v| v.as_mut_ptr()).collect();
    let first_touch: Vec<*mut i32> = touch.iter_mut().map(|v| v.as_mut_ptr()).collect();
    let (mut force, mut torque) = ([0.0_f32; 9], [0.0_f32; 9]);
    let mut table = null_mut();
    let atoms = ss_atoms::<f32> {
        count: 3,
        owned: 3,
        position: position.as_ptr(),
        velocity: velocity.as_ptr(),
        angular_velocity: spin.as_ptr(),
        radius: radius.as_ptr(),
        mass: mass.as_ptr(),
        types: types.as_ptr(),
        first_type: 0,
    };
    let list = ss_neighbours {
        count: 3,
        atoms: [0, 1, 2].as_ptr(),
        neighbour_counts: [1, 1, 0].as_ptr(),
        first_neighbour: first.as_ptr(),
        index_mask: -1,
    };
    let history = ss_history::<f32> {
        values: 3,
        first_value: first_value.as_ptr(),
        first_touch: first_touch.as_ptr(),
    };
    let loads = ss_loads::<f32> {
        force: force.as_mut_ptr(),
        torque: torque.as_mut_ptr(),
        newton: 1,
        pair_force: null_mut(),
    };
    let mut report = ss_list_report::default();
    // SAFETY: valid pointers throughout, as long as they say.
    unsafe {
        assert_eq!(ss_table_new_f32(&config, &mut table), SS_OK);
        assert_eq!(
            ss_table_set_f32(table, 0, 0, &coefficients(1.0e3), null_mut()),
            SS_OK
        );
        assert_eq!(
            ss_table_set_f32(table, 1, 1, &coefficients(4.0e3), null_mut()),
            SS_OK
        );
        assert_eq!(
            ss_table_prepare_f32(table, 1.0e-6, [1.0e-5_f32; 2].as_ptr(), null_mut()),
            SS_OK
        );
        let code = ss_table_evaluate_f32(table, &atoms, &list, &history, &loads, 1, &mut report);
        assert_eq!(code, SS_OK);
        ss_table_free_f32(table);
    }
    assert_eq!(report.contacts, 2);
    // The reference: each pair's law from the mixed coefficients (sqrt(1e3 * 4e3) = 2e3).
    let sphere = |k: usize| ss_sphere::<f32> {
        position: ss_vec3 {
            x: position[3 * k],
            y: position[3 * k + 1],
            z: position[3 * k + 2],
        },
        velocity: ss_vec3 {
            x: velocity[3 * k],
            y: velocity[3 * k + 1],
            z: velocity[3 * k + 2],
        },
        angular_velocity: ss_vec3 {
            x: spin[3 * k],
            y: spin[3 * k + 1],
            z: spin[3 * k + 2],
        },
        radius: radius[k],
        mass: mass[k],
    };
    let (mut expected_force, mut expected_torque) = ([0.0_f32; 9], [0.0_f32; 9]);
    let starts = [[1e-6_f32, -2e-6, 0.0], [0.0, 3e-6, 1e-6]];
    for (pair, [i, j]) in [[0usize, 1usize], [1, 2]].into_iter().enumerate() {
        let mixed = (1.0e3_f32 * 4.0e3).sqrt();
        let params = ss_params::<f32> {
            model: SS_MODEL_AA,
            normal_stiffness: mixed,
            restitution: 0.9,
            tangential_stiffness: ((0.3 * 1.0e3_f32) * (0.3 * 4.0e3_f32)).sqrt(),
            dashpot_ratio: 0.5,
            friction: 0.4,
            time_step: 1.0e-6,
            smallest_effective_mass: 5.0e-6,
            ..Default::default()
        };
        let mut state = ss_state::<f32>::default();
        let s = starts[pair];
        state.displacement = ss_vec3 {
            x: s[0],
            y: s[1],
            z: s[2],
        };
        let mut out = ss_forces::default();
        let mut law = null_mut();
        // SAFETY: valid pointers.
        unsafe {
            assert_eq!(ss_law_new_f32(&params, &mut law), SS_OK);
            assert_eq!(
                ss_sphere_sphere_f32(law, &sphere(i), &sphere(j), &mut state, &mut out),
                SS_OK
            );
            ss_law_free_f32(law);
        }
        assert_eq!(out.touching, 1);
        let stored = &values[i];
        assert_eq!(
            stored.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            [
                state.displacement.x,
                state.displacement.y,
                state.displacement.z
            ]
            .map(f32::to_bits)
        );
        let f = [out.force_on_j.x, out.force_on_j.y, out.force_on_j.z];
        let (ti, tj) = (out.torque_on_i, out.torque_on_j);
        for (c, (a, b)) in [(ti.x, tj.x), (ti.y, tj.y), (ti.z, tj.z)]
            .into_iter()
            .enumerate()
        {
            expected_force[3 * i + c] -= f[c];
            expected_force[3 * j + c] += f[c];
            expected_torque[3 * i + c] += a;
            expected_torque[3 * j + c] += b;
        }
    }
    assert_eq!(force.map(f32::to_bits), expected_force.map(f32::to_bits));
    assert_eq!(torque.map(f32::to_bits), expected_torque.map(f32::to_bits));
    assert_eq!(touch, vec![vec![1], vec![1], vec![]]);
}

/// The elastic-plastic rolling resistance through the list entry: each contact the bits of the
/// kernel's own law with the rolling slot (`ContactLaw::with_rolling`), its coefficients mixed
/// by their geometric means, the rolling spring kept after the tangential numbers.
/// The kernel's own one-contact calls on `host`, pair by pair in list order, for `steps` steps,
/// each pair's forces summed into the host's arrays as LAMMPS would: the reference a list entry
/// is held to bit for bit. `contact(i, j, p, q, stored)` evaluates spheres `i` and `j` of
/// coefficients `p` and `q` (the rough pair's for materials 0 and 2) on their stored values.
fn kernel_steps(
    host: &mut Host,
    steps: usize,
    mut contact: impl FnMut(
        &soft_sphere::prelude::Sphere<f64>,
        &soft_sphere::prelude::Sphere<f64>,
        &ss_coefficients<f64>,
        &ss_coefficients<f64>,
        &mut [f64],
    ) -> Option<soft_sphere::prelude::ContactForces<f64>>,
) {
    use soft_sphere::prelude::{Sphere, Vec3};
    let vector = |a: &[f64], k: usize| Vec3::new(a[3 * k], a[3 * k + 1], a[3 * k + 2]);
    let (n, values) = (host.radius.len(), host.values);
    for _ in 0..steps {
        let (mut force, mut torque) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        for &i in &host.list.clone() {
            let i = i as usize;
            for (jj, &j) in host.neighbours[i].clone().iter().enumerate() {
                let j = j as usize;
                let (a, b) = (host.types[i] as usize - 1, host.types[j] as usize - 1);
                let (p, q) = if (a, b) == (0, 2) || (a, b) == (2, 0) {
                    (rough(), rough())
                } else {
                    (material(a), material(b))
                };
                let sphere = |k: usize| Sphere {
                    position: vector(&host.position, k),
                    velocity: vector(&host.velocity, k),
                    angular_velocity: vector(&host.spin, k),
                    radius: host.radius[k],
                    mass: host.mass[k],
                };
                let (si, sj) = (sphere(i), sphere(j));
                let stored = &mut host.history[i][values * jj..values * (jj + 1)];
                if let Some(c) = contact(&si, &sj, &p, &q, stored) {
                    force[i] -= c.force_on_j();
                    force[j] += c.force_on_j();
                    torque[i] += c.torque_on_i;
                    torque[j] += c.torque_on_j;
                }
            }
        }
        for k in 0..n {
            for (c, (f, t)) in [
                (force[k].x, torque[k].x),
                (force[k].y, torque[k].y),
                (force[k].z, torque[k].z),
            ]
            .into_iter()
            .enumerate()
            {
                host.force[3 * k + c] += f;
                host.torque[3 * k + c] += t;
            }
        }
    }
}

#[test]
fn rolling_resistance_gives_the_kernel_laws_bits() {
    use soft_sphere::prelude::{
        ContactLaw, ElasticPlasticRolling, Interaction, LinearSpringDashpot, ModelAA,
        RollingSpring, SpringDisplacement, TangentialParameters, Vec3,
    };
    let inertia = 1.0e-12;
    let config = ss_table_config {
        model: SS_MODEL_AA,
        rolling: SS_ROLLING_EPSD,
        smallest_inertia: inertia,
        materials: 3,
        ..Default::default()
    };
    let table = table_of(&config);
    // SAFETY: from ss_table_new_f64.
    assert_eq!(unsafe { ss_table_state_values_f64(table) }, 6);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    let mut host = Host::new(31, 6);
    let mut expected = host.clone();
    for _ in 0..3 {
        assert_eq!(host.evaluate(table, 1, 1, |_, _, _| {}).0, SS_OK);
    }
    // The reference, pair by pair in list order, three steps.
    let mean = |x: f64, y: f64| if x == y { x } else { (x * y).sqrt() };
    let mut rolling_pairs = 0;
    kernel_steps(&mut expected, 3, |i, j, p, q, stored| {
        let law = ContactLaw::new(
            LinearSpringDashpot::new(
                mean(p.normal_stiffness, q.normal_stiffness),
                mean(p.restitution, q.restitution),
            )
            .unwrap(),
            ModelAA(
                TangentialParameters::new(
                    mean(p.tangential_stiffness, q.tangential_stiffness),
                    mean(p.dashpot_ratio, q.dashpot_ratio),
                    mean(p.friction, q.friction),
                )
                .unwrap(),
            ),
        )
        .with_rolling(
            ElasticPlasticRolling::new(
                mean(p.rolling_friction, q.rolling_friction),
                mean(p.rolling_stiffness, q.rolling_stiffness),
                mean(p.rolling_damping, q.rolling_damping),
                inertia,
            )
            .unwrap(),
        );
        let step = law.time_step(DT, 5.0e-6).unwrap();
        let mut state = RollingSpring {
            tangential: SpringDisplacement {
                displacement: Vec3::new(stored[0], stored[1], stored[2]),
            },
            torque: Vec3::new(stored[3], stored[4], stored[5]),
        };
        let outcome = law.sphere_sphere(i, j, &mut state, step).unwrap();
        let d = state.tangential.displacement;
        let t = state.torque;
        stored.copy_from_slice(&[d.x, d.y, d.z, t.x, t.y, t.z]);
        match outcome {
            Interaction::Touching(c) => {
                rolling_pairs += usize::from(t != Vec3::ZERO);
                Some(c)
            }
            Interaction::Apart => None,
        }
    });
    assert!(
        rolling_pairs > 40,
        "rolling springs must be at work: {rolling_pairs}"
    );
    assert_eq!(bits(&host.force), bits(&expected.force));
    assert_eq!(bits(&host.torque), bits(&expected.torque));
    for (a, b) in host.history.iter().zip(&expected.history) {
        assert_eq!(bits(a), bits(b));
    }
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// The frictionless families read no tangential coefficient: whatever stands there (a negative
/// stiffness, a friction that is not a number) is ignored, not refused.
#[test]
fn frictionless_tables_ignore_the_tangential_coefficients() {
    for model in [SS_MODEL_FRICTIONLESS, SS_MODEL_HERTZ_FRICTIONLESS] {
        let config = ss_table_config {
            model,
            materials: 1,
            largest_impact_speed: SPEED,
            largest_effective_radius: RADIUS,
            ..Default::default()
        };
        let ignored = ss_coefficients {
            tangential_stiffness: -1.0,
            dashpot_ratio: f64::NAN,
            friction: f64::NAN,
            ..material(0)
        };
        let mut table = null_mut();
        // SAFETY: valid pointers throughout.
        unsafe {
            assert_eq!(ss_table_new_f64(&config, &mut table), SS_OK);
            assert_eq!(
                ss_table_set_f64(table, 0, 0, &ignored, null_mut()),
                SS_OK,
                "{model}"
            );
            ss_table_free_f64(table);
        }
    }
}

/// The walls entry: the selected owned atoms against a floor and a moving ceiling, each contact
/// the bits of `ss_sphere_wall_f64` with the law of the atom's material and the walls', each
/// atom's forces summed wall by wall; the atoms not selected, and the ghosts, untouched.
#[test]
fn walls_give_the_single_wall_calls_bits() {
    let planes = [
        floor(),
        ss_wall {
            point: ss_vec3 {
                x: 0.0,
                y: 0.0,
                z: 4.7e-3,
            },
            direction: ss_vec3 {
                x: 0.0,
                y: 0.0,
                z: -2.0,
            },
            velocity: ss_vec3 {
                x: 0.05,
                y: 0.0,
                z: 0.0,
            },
            ..ss_wall::default()
        },
    ];
    // The floor and a turning drum about the columns that the corner columns touch.
    let drum = ss_wall {
        point: ss_vec3 {
            x: 2.85e-3,
            y: 2.85e-3,
            z: 0.0,
        },
        direction: ss_vec3 {
            x: 0.0,
            y: 0.0,
            z: 1.0,
        },
        velocity: ss_vec3::default(),
        radius: 4.95e-3,
        spin: -40.0,
    };
    let turning = [planes[0], drum];
    for walls in [planes, turning] {
        for model in [SS_MODEL_AA, SS_MODEL_HERTZ_AA_LUDING, SS_MODEL_STATELESS] {
            let table = table(model);
            assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
            let values = values_of(model);
            let (stride, wall_stride) = (16, 7);
            let mut host = Host::new(41 + model as u64, 1);
            let n = host.radius.len();
            let mut random = Xorshift::new(5);
            let mut states: Vec<f64> = (0..n * stride)
                .map(|_| 1e-7 * (random.unit() - 0.5))
                .collect();
            let selected: Vec<i32> = (0..n)
                .map(|k| if k % 3 == 0 { 0b100 } else { 0b010 })
                .collect();
            let mut expected = host.clone();
            let mut expected_states = states.clone();
            let mut report = ss_list_report::default();
            let atoms = host.atoms();
            let ss_walls_of = |states: &mut Vec<f64>| ss_walls {
                count: 2,
                walls: walls.as_ptr(),
                material: 0,
                states: states.as_mut_ptr(),
                stride,
                wall_stride,
                selected: selected.as_ptr(),
                bit: 0b010,
            };
            let loads = ss_loads {
                force: host.force.as_mut_ptr(),
                torque: host.torque.as_mut_ptr(),
                newton: 0,
                pair_force: null_mut(),
            };
            // SAFETY: valid pointers throughout, as long as they say.
            let code = unsafe {
                ss_table_evaluate_walls_f64(
                    table,
                    &atoms,
                    &ss_walls_of(&mut states),
                    &loads,
                    1,
                    &mut report,
                )
            };
            assert_eq!(code, SS_OK, "model {model}");
            let (mut touching, mut on_each) = (0, [0; 2]);
            for k in (0..expected.owned).filter(|k| selected[*k] & 0b010 != 0) {
                let params = reference_params(model, expected.types[k] as usize - 1, 0);
                let mut law = null_mut();
                // SAFETY: valid pointers.
                assert_eq!(unsafe { ss_law_new_f64(&params, &mut law) }, SS_OK);
                let (mut force, mut torque) = ([0.0; 3], [0.0; 3]);
                for (w, wall) in walls.iter().enumerate() {
                    let at = k * stride + w * wall_stride;
                    let stored = &mut expected_states[at..at + values];
                    let mut state = state_of(stored);
                    let mut out = ss_forces::default();
                    // SAFETY: valid pointers.
                    let code = unsafe {
                        ss_sphere_wall_f64(law, &expected.sphere(k), wall, &mut state, &mut out)
                    };
                    assert_eq!(code, SS_OK);
                    store(&state, stored);
                    touching += out.touching as usize;
                    on_each[w] += out.touching as usize;
                    if out.touching == 1 {
                        let (f, t) = (out.force_on_j, out.torque_on_j);
                        for (c, (fc, tc)) in
                            [(f.x, t.x), (f.y, t.y), (f.z, t.z)].into_iter().enumerate()
                        {
                            force[c] += fc;
                            torque[c] += tc;
                        }
                    }
                }
                // SAFETY: from ss_law_new_f64.
                unsafe { ss_law_free_f64(law) };
                for c in 0..3 {
                    expected.force[3 * k + c] += force[c];
                    expected.torque[3 * k + c] += torque[c];
                }
            }
            assert!(
                on_each.iter().all(|&n| n > 2),
                "model {model}: each wall must touch: {on_each:?}"
            );
            assert_eq!(report.contacts, touching);
            assert_eq!(bits(&host.force), bits(&expected.force), "model {model}");
            assert_eq!(bits(&host.torque), bits(&expected.torque), "model {model}");
            assert_eq!(bits(&states), bits(&expected_states), "model {model}");
            // A wall whose normal is zero: refused, nothing written.
            let before = (host.force.clone(), states.clone());
            let bad = [ss_wall::default()];
            let bad_walls = ss_walls {
                walls: bad.as_ptr(),
                count: 1,
                ..ss_walls_of(&mut states)
            };
            // SAFETY: as above.
            let code = unsafe {
                ss_table_evaluate_walls_f64(table, &atoms, &bad_walls, &loads, 1, &mut report)
            };
            assert_eq!(code, SS_ERR_BAD_WALL);
            assert_eq!((host.force.clone(), states.clone()), before);
            // A NaN already in an owned atom's force: refused, naming the atom, nothing written.
            // SAFETY: atom 2's force, inside the array.
            unsafe { *loads.force.add(3 * 2 + 1) = f64::NAN };
            let before = (bits(&host.force), bits(&states));
            // SAFETY: as above.
            let code = unsafe {
                ss_table_evaluate_walls_f64(
                    table,
                    &atoms,
                    &ss_walls_of(&mut states),
                    &loads,
                    1,
                    &mut report,
                )
            };
            assert_eq!((code, report.atoms), (SS_ERR_NON_FINITE_INPUT, [2, -1]));
            assert_eq!((bits(&host.force), bits(&states)), before);
            // SAFETY: from ss_table_new_f64.
            unsafe { ss_table_free_f64(table) };
        }
    }
}

/// Every family but the frictionless ones takes the rolling resistance, whose spring adds three
/// numbers to what the family keeps per contact.
#[test]
fn rolling_comes_with_every_family_that_has_friction() {
    for (model, kept) in [
        (SS_MODEL_STATELESS, Some(3)),
        (SS_MODEL_AA, Some(6)),
        (SS_MODEL_AA_LUDING, Some(6)),
        (SS_MODEL_FRICTIONLESS, None),
        (SS_MODEL_HERTZ_STATELESS, Some(3)),
        (SS_MODEL_HERTZ_AA, Some(7)),
        (SS_MODEL_HERTZ_AA_LUDING, Some(7)),
        (SS_MODEL_HERTZ_FRICTIONLESS, None),
        (SS_MODEL_HERTZ_MICROSLIP, Some(4 * SS_MICROSLIP_SPRINGS + 7)),
    ] {
        let config = ss_table_config {
            model,
            rolling: SS_ROLLING_EPSD,
            smallest_inertia: 1.0e-12,
            materials: 1,
            largest_impact_speed: SPEED,
            largest_effective_radius: RADIUS,
        };
        let mut table = null_mut();
        // SAFETY: valid pointers throughout.
        unsafe {
            let code = ss_table_new_f64(&config, &mut table);
            match kept {
                Some(values) => {
                    assert_eq!(code, SS_OK, "model {model}");
                    assert_eq!(ss_table_state_values_f64(table), values, "model {model}");
                    assert_eq!(
                        ss_table_set_f64(table, 0, 0, &material(1), null_mut()),
                        SS_OK
                    );
                    ss_table_free_f64(table);
                }
                None => assert_eq!(code, SS_ERR_UNKNOWN_MODEL, "model {model}"),
            }
        }
    }
}

/// Micro-slip through the list entry: every contact gives the bits of the kernel's own
/// `MicroSlip` law with the pair's mixed coefficients, its breakpoints kept flat in the history
/// (the normal, the contact radius, the positions, then the displacements).
#[test]
fn micro_slip_gives_the_kernel_laws_bits() {
    use soft_sphere::prelude::{
        ContactLaw, Hertz, HertzImpact, Interaction, Material, MicroSlip, MicroSlipSprings,
        MindlinParameters, Vec3,
    };
    let config = ss_table_config {
        model: SS_MODEL_HERTZ_MICROSLIP,
        materials: 3,
        largest_impact_speed: SPEED,
        largest_effective_radius: RADIUS,
        ..Default::default()
    };
    const S: usize = SS_MICROSLIP_SPRINGS;
    let values = 4 * S + 4;
    let table = table_of(&config);
    // SAFETY: from ss_table_new_f64.
    assert_eq!(unsafe { ss_table_state_values_f64(table) }, values);
    assert_eq!(prepare(table, [1e-5; 3]).0, SS_OK);
    let mut host = Host::new(37, values);
    let mut expected = host.clone();
    for _ in 0..3 {
        assert_eq!(host.evaluate(table, 1, 1, |_, _, _| {}).0, SS_OK);
    }
    let mut sheared = 0;
    kernel_steps(&mut expected, 3, |i, j, p, q, stored| {
        let params = reference_params(SS_MODEL_HERTZ_AA, 0, 0);
        let mix = |x: f64, y: f64| if x == y { x } else { (x * y).sqrt() };
        let elastic =
            |c: &ss_coefficients<f64>| Material::new(c.youngs_modulus, c.poisson_ratio).unwrap();
        let (e_star, g_star) = (
            elastic(p).effective_modulus(&elastic(q)),
            elastic(p).effective_shear_modulus(&elastic(q)),
        );
        let impact = HertzImpact {
            speed: SPEED,
            effective_radius: RADIUS,
        };
        let hertz = Hertz::new(e_star, mix(p.restitution, q.restitution), impact).unwrap();
        let mindlin = MindlinParameters::new(
            g_star,
            mix(p.dashpot_ratio, q.dashpot_ratio),
            mix(p.friction, q.friction),
        )
        .unwrap();
        let law = ContactLaw::new(hertz, MicroSlip::<f64, SS_MICROSLIP_SPRINGS>::new(mindlin));
        let step = law
            .time_step(params.time_step, params.smallest_effective_mass)
            .unwrap();
        let vector = |k: usize| Vec3::new(stored[k], stored[k + 1], stored[k + 2]);
        let mut state = MicroSlipSprings {
            normal: vector(0),
            contact_radius: stored[3],
            positions: std::array::from_fn(|k| stored[4 + k]),
            displacements: std::array::from_fn(|k| vector(4 + S + 3 * k)),
        };
        let outcome = law.sphere_sphere(i, j, &mut state, step).unwrap();
        let n = state.normal;
        stored[..4].copy_from_slice(&[n.x, n.y, n.z, state.contact_radius]);
        stored[4..4 + S].copy_from_slice(&state.positions);
        for (k, u) in state.displacements.iter().enumerate() {
            stored[4 + S + 3 * k..7 + S + 3 * k].copy_from_slice(&[u.x, u.y, u.z]);
        }
        match outcome {
            Interaction::Touching(c) => {
                sheared += usize::from(c.tangential_force != Vec3::ZERO);
                Some(c)
            }
            Interaction::Apart => None,
        }
    });
    assert!(sheared > 40, "the springs must be at work: {sheared}");
    assert_eq!(bits(&host.force), bits(&expected.force));
    assert_eq!(bits(&host.torque), bits(&expected.torque));
    for (a, b) in host.history.iter().zip(&expected.history) {
        assert_eq!(bits(a), bits(b));
    }
    // SAFETY: from ss_table_new_f64.
    unsafe { ss_table_free_f64(table) };
}

/// `ss_check_neighbours` over `host`'s list.
fn check_neighbours(host: &mut Host) -> (i32, ss_list_report) {
    let views = host.views();
    let list = ss_neighbours {
        count: host.list.len(),
        atoms: host.list.as_ptr(),
        neighbour_counts: host.counts.as_ptr(),
        first_neighbour: views.first_neighbour.as_ptr(),
        index_mask: 0x1FFF_FFFF,
    };
    let mut report = ss_list_report::default();
    // SAFETY: the host's arrays, as long as they say.
    let code = unsafe { ss_check_neighbours(host.radius.len(), &list, &mut report) };
    (code, report)
}

#[test]
fn a_list_naming_a_pair_twice_is_refused_when_it_is_built() {
    let mut host = Host::new(9, 4);
    assert_eq!(check_neighbours(&mut host).0, SS_OK);
    // Atom 7's page names its first neighbour twice.
    let mut twice = Host::new(9, 4);
    let j = twice.neighbours[7][0];
    twice.neighbours[7].push(j);
    twice.counts[7] += 1;
    let (code, report) = check_neighbours(&mut twice);
    assert_eq!(
        (code, report.atoms),
        (SS_ERR_REPEATED_PAIR, [7, i64::from(j)])
    );
    // Atom 3 names j, and j's page names 3 (j owned, so its page is in the list).
    let mut both = Host::new(9, 4);
    let j = *both.neighbours[3].iter().find(|&&j| j < 45).unwrap();
    both.neighbours[j as usize].push(3);
    both.counts[j as usize] += 1;
    let (code, report) = check_neighbours(&mut both);
    assert_eq!(code, SS_ERR_REPEATED_PAIR);
    let mut named = report.atoms;
    named.sort();
    assert_eq!(named, [3, i64::from(j)]);
    // A neighbour past the atoms, and a missing list.
    let mut past = Host::new(9, 4);
    past.neighbours[5][0] = 60;
    let (code, report) = check_neighbours(&mut past);
    assert_eq!((code, report.atoms), (SS_ERR_INDEX, [5, 60]));
    // SAFETY: a null list is refused before anything is read.
    let code = unsafe { ss_check_neighbours(60, null(), null_mut()) };
    assert_eq!(code, SS_ERR_NULL);
    // SAFETY: the texts are static C strings.
    let text = unsafe { std::ffi::CStr::from_ptr(ss_contact_error_text(SS_ERR_REPEATED_PAIR)) };
    assert!(text.to_str().unwrap().contains("twice"));
}
