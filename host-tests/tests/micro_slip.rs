//! The micro-slip law against Cattaneo & Mindlin's and Mindlin & Deresiewicz's closed forms
//! under a constant normal load at every contact size, Masing's memory of turning points, a
//! contact that grows and shrinks, and that no loading cycle creates energy.

use host_tests::analytic::{cattaneo_mindlin, cycle_dissipation, mindlin_deresiewicz_unloading};
use host_tests::random::Xorshift;
use host_tests::validation::micro_slip::ShearBed;
use soft_sphere::prelude::{
    Libm, MicroSlip, MicroSlipSprings, MindlinParameters, NormalOscillator, TangentialModel, Vec3,
};
use soft_sphere::slots::TangentialInput;

/// Steel on a rigid plane: `E*`, `G*` (Pa), `R` (m), `mu`.
const MODULUS: f64 = 2.286e11;
const SHEAR: f64 = 4.706e10;
const RADIUS: f64 = 0.01;
const FRICTION: f64 = 0.3;

/// A steel bed at `overlap`, tangential dashpot off.
fn steel<const N: usize>(overlap: f64) -> ShearBed<N> {
    let p = MindlinParameters::new(SHEAR, 0.0, FRICTION).unwrap();
    ShearBed::new(MODULUS, p, RADIUS, overlap)
}

/// Steps per full-slip displacement in the driven paths.
const STEPS: usize = 4000;

/// The largest distance from Cattaneo-Mindlin's first loading and from Mindlin-Deresiewicz's
/// unloading and reloading, over `mu P`, and the relative error of the energy one cycle to
/// `T* = amplitude mu P` dissipates, with `N` breakpoints at `overlap`.
fn errors<const N: usize>(overlap: f64, amplitude: f64) -> [f64; 3] {
    let mut bed = steel::<N>(overlap);
    let full = bed.full_slip();
    // Steps that land on the turning displacement, where Cattaneo-Mindlin's force is T*.
    let turning = bed.turning_displacement(amplitude);
    let du = bed.step_to(turning);
    let loading = bed.drive(turning, du, |x| cattaneo_mindlin(x, full));
    let (top, top_force) = (bed.displacement, cattaneo_mindlin(bed.displacement, full));
    // Unload to -delta*, reload to +delta*: the second half mirrors the first.
    let work_before = bed.trapezoid;
    let unloading = bed.drive(2.0 * turning, -du, |x| {
        mindlin_deresiewicz_unloading(x, top, top_force, full)
    });
    let reloading = bed.drive(2.0 * turning, du, |x| {
        -mindlin_deresiewicz_unloading(-x, top, top_force, full)
    });
    let dissipated = (bed.trapezoid - work_before) / (FRICTION * bed.load() * full);
    let exact = cycle_dissipation(top_force);
    [
        loading,
        unloading.max(reloading),
        (dissipated / exact - 1.0).abs(),
    ]
}

#[test]
fn cattaneo_mindlin_and_mindlin_deresiewicz_are_met_at_every_contact_size() {
    // Contact radii from 1 % to 100 % of the largest (overlaps 1e-4 to 1): the profile follows
    // the contact, so the accuracy is the same at each. The curves are exact at the steps; the
    // energy is the trapezoidal rule's over the steps (second order in the step).
    for overlap in [1e-9, 2.5e-8, 4e-7, 1e-5] {
        for amplitude in [0.05, 0.1, 0.3, 0.6, 0.9] {
            for (springs, e) in [
                (3, errors::<3>(overlap, amplitude)),
                (4, errors::<4>(overlap, amplitude)),
                (16, errors::<16>(overlap, amplitude)),
            ] {
                assert!(
                    e[0] < 1e-9 && e[1] < 1e-9 && e[2] < 1e-3,
                    "overlap {overlap}, tau {amplitude}, {springs} breakpoints: {e:?}"
                );
            }
        }
    }
}

#[test]
fn masing_remembers_each_turning_point_until_a_larger_loop_wipes_it_out() {
    // Load to 0.8 mu P, unload to 0.2 mu P, reload: the inner loop closes at the turning point
    // (T* again), and loading on follows the first loading curve, as if the inner loop had not
    // been (Masing's memory rule); then unloading from 0.95 mu P follows Mindlin-Deresiewicz's
    // branch from there.
    let mut bed = steel::<4>(1e-5);
    let full = bed.full_slip();
    let at = |tau: f64| full * (1.0 - (1.0 - tau).powf(2.0 / 3.0));
    let du = full / STEPS as f64;
    let first = bed.drive(at(0.8), du, |x| cattaneo_mindlin(x, full));
    let (top, top_force) = (bed.displacement, cattaneo_mindlin(bed.displacement, full));
    // Down to 0.2 mu P on Mindlin-Deresiewicz's branch: 2 T((d* - d) / 2) = 0.6 mu P.
    let back = 2.0 * at(0.3);
    let steps = (back / du).round();
    let down = bed.drive(steps * du, -du, |x| {
        mindlin_deresiewicz_unloading(x, top, top_force, full)
    });
    let (low, low_force) = (bed.displacement, bed.push(0.0, 0.0));
    let up = bed.drive(steps * du, du, |x| {
        // Reloading from the inner turning point: Masing's doubled curve from there.
        low_force + 2.0 * cattaneo_mindlin((x - low) / 2.0, full)
    });
    let closed = (bed.push(0.0, 0.0) - top_force).abs();
    let on = bed.drive(at(0.95) - at(0.8), du, |x| cattaneo_mindlin(x, full));
    let (top, top_force) = (bed.displacement, cattaneo_mindlin(bed.displacement, full));
    let unload = bed.drive(at(0.5), -du, |x| {
        mindlin_deresiewicz_unloading(x, top, top_force, full)
    });
    for (what, e) in [
        ("first loading", first),
        ("inner unloading", down),
        ("inner reloading", up),
        ("the loop closes", closed),
        ("loading on", on),
        ("outer unloading", unload),
    ] {
        assert!(e < 1e-9, "{what}: {e}");
    }
}

#[test]
fn the_stuck_contact_has_mindlins_stiffness_and_slides_at_coulombs_limit() {
    for overlap in [1e-9, 1e-5] {
        let mut bed = steel::<8>(overlap);
        let du = 1e-3 * bed.full_slip();
        let t = bed.push(du, 0.0) * FRICTION * bed.load();
        // The rim slips at once (its pressure is zero): Mindlin's stiffness to within the
        // first loading's curvature, du / (4 delta_s).
        let mindlin = 8.0 * SHEAR * bed.contact_radius() * du;
        assert!(
            (t / mindlin - 1.0).abs() < 3e-4,
            "overlap {overlap}: {t} vs {mindlin}"
        );
        assert!(!bed.sliding, "overlap {overlap}");
        // What it holds is Mindlin's spring's energy, k_t u^2 / 2, to the same order.
        let held = bed.law.stored_energy(&bed.state);
        let spring = 0.5 * 8.0 * SHEAR * bed.contact_radius() * du * du;
        assert!(
            (held / spring - 1.0).abs() < 1e-3,
            "overlap {overlap}: {held} vs {spring}"
        );
        for _ in 0..990 {
            bed.push(du, 0.0);
        }
        assert!(!bed.sliding, "overlap {overlap}");
        // Past the full-slip displacement the contact slides at mu P exactly.
        for _ in 0..20 {
            bed.push(du, 0.0);
        }
        let t = bed.push(du, 0.0);
        assert!((t - 1.0).abs() < 1e-12, "overlap {overlap}: {t}");
        assert!(bed.sliding, "overlap {overlap}");
    }
}

#[test]
fn new_contact_area_is_laid_down_free_and_leaving_area_takes_its_shear() {
    // Shear a small contact, then grow it: the force is unchanged (the new rim is unstressed),
    // though the stuck stiffness grew with the radius.
    let mut bed = steel::<16>(1e-5);
    let du = 0.2 * bed.full_slip() / 100.0;
    for _ in 0..100 {
        bed.push(du, 0.0);
    }
    let small = bed.push(0.0, 0.0) * FRICTION * bed.load();
    bed.overlap *= 2.0;
    let grown = bed.push(0.0, 0.0) * FRICTION * bed.load();
    assert!((grown / small - 1.0).abs() < 1e-12, "{small} then {grown}");
    // Then sheared on, the new area takes its first shear free of any earlier one: the
    // increment is the stuck stiffness at the new radius.
    let before = grown;
    let after = bed.push(1e-6 * du, 0.0) * FRICTION * bed.load();
    let stiffness = 8.0 * SHEAR * bed.contact_radius();
    assert!(
        ((after - before) / (1e-6 * du * stiffness) - 1.0).abs() < 1e-3,
        "{before} then {after}"
    );
    // Shrinking back to below the first contact radius, the shear falls at least with the
    // radius (the leaving annulus carried its part).
    let before = after;
    bed.overlap /= 4.0;
    let shrunk = bed.push(0.0, 0.0) * FRICTION * bed.load();
    assert!(
        shrunk <= before * 0.5_f64.sqrt() * (1.0 + 1e-12),
        "{before} then {shrunk}"
    );
}

/// Circles, reversals and a breathing normal load on a bed of `N` breakpoints: what the springs
/// hold never exceeds the work put in, and a cycle back to the start has taken work.
fn no_energy_created<const N: usize>() {
    let mut bed = steel::<N>(1e-5);
    let full = bed.full_slip();
    let base = bed.overlap;
    let mut held = 0.0;
    for k in 0..20_000 {
        let angle = k as f64 * 0.01;
        bed.overlap = base * (1.0 + 0.5 * (0.0037 * k as f64).sin());
        let swing = 0.01 * full * (1.0 + (0.0011 * k as f64).sin());
        let (dx, dy) = (-angle.sin() * swing, angle.cos() * swing);
        bed.push(dx, dy);
        held = bed.law.stored_energy(&bed.state);
        assert!(
            held <= bed.work * (1.0 + 1e-9) + 1e-30,
            "{N} breakpoints, step {k}: holds {held}, took {}",
            bed.work
        );
    }
    assert!(bed.work > held, "{} {held}", bed.work);
}

/// A contact pressed deeper at every step while the push along x slows (a spinning sphere
/// meeting a wall head-on: the tangential force brakes the spin as the contact grows). Each
/// step lays down new area, so the profile gains a breakpoint at the old rim and, full, drops
/// one; the profile is convex in `1 - t^2` there, under every chord, so the line a drop leaves
/// lies above the springs it replaces. What the springs hold never exceeds the work put in.
fn growing_and_braked<const N: usize>() {
    let mut bed = steel::<N>(1e-7);
    let full = bed.full_slip();
    let steps = 50;
    for k in 0..steps {
        bed.overlap *= 1.15;
        let slowing = 1.0 - k as f64 / steps as f64;
        bed.push(0.05 * full * slowing * slowing, 0.0);
        let held = bed.law.stored_energy(&bed.state);
        assert!(
            held <= bed.work * (1.0 + 1e-9),
            "{N} breakpoints, step {k}: holds {held}, took {}",
            bed.work
        );
    }
}

#[test]
fn dropping_a_breakpoint_creates_no_energy() {
    growing_and_braked::<3>();
    growing_and_braked::<4>();
    growing_and_braked::<8>();
}

#[test]
fn no_loading_cycle_creates_energy() {
    no_energy_created::<3>();
    no_energy_created::<4>();
    no_energy_created::<16>();
}

#[test]
fn a_rotating_contact_turns_its_springs() {
    // A stuck sheared contact whose normal turns: the force turns with it, keeping its length.
    let mut bed = steel::<8>(1e-5);
    bed.push(0.1 * bed.full_slip(), 0.0);
    let t = bed.push(0.0, 0.0) * FRICTION * bed.load();
    let (s, c) = 0.3_f64.sin_cos();
    let force = bed.turned_to(Vec3::new(s, 0.0, c));
    let expected = Vec3::new(-t * c, 0.0, t * s);
    let d = force - expected;
    assert!(
        d.norm_squared().sqrt() < 1e-12 * t,
        "{force:?} vs {expected:?}"
    );
    assert_eq!(
        *bed.law.parameters(),
        MindlinParameters::new(SHEAR, 0.0, FRICTION).unwrap()
    );
}

#[test]
fn a_contact_turning_about_its_shear_keeps_it() {
    // The normal turns about the displacement's own direction: the smallest rotation leaves the
    // displacement, and the force, as they were.
    let mut bed = steel::<8>(1e-5);
    bed.push(0.1 * bed.full_slip(), 0.0);
    let t = bed.push(0.0, 0.0) * FRICTION * bed.load();
    let (s, c) = 0.4_f64.sin_cos();
    let force = bed.turned_to(Vec3::new(0.0, -s, c));
    let d = force - Vec3::new(-t, 0.0, 0.0);
    assert!(d.norm_squared().sqrt() < 1e-12 * t, "{force:?} vs {t}");
}

#[test]
fn the_dashpot_adds_to_the_springs_and_no_friction_means_no_force() {
    // One step from first touch, stuck: -k_t v dt - r eta_n v (to within the rim's slip,
    // du / (4 delta_s) = 2e-7 here).
    let p = MindlinParameters::new(SHEAR, 0.5, 10.0).unwrap();
    let radius = (RADIUS * 1e-5).sqrt();
    let law = MicroSlip::<f64, 8>::new(p);
    let oscillator = NormalOscillator {
        damping_coefficient: 3.0,
        ..Default::default()
    };
    let (v, dt) = (1e-3, 1e-7);
    let input = TangentialInput {
        normal: Vec3::new(0.0, 0.0, 1.0),
        slip_velocity: Vec3::new(v, 0.0, 0.0),
        normal_force: 4.0 / 3.0 * MODULUS * radius * 1e-5,
        overlap: 1e-5,
        approach_rate: 0.0,
        oscillator,
        contact_radius: radius,
        time_step: dt,
    };
    let out = law.force::<Libm>(&MicroSlipSprings::default(), &input);
    let expected = -(8.0 * SHEAR * radius * v * dt) - 0.5 * 3.0 * v;
    assert!(
        (out.force.x / expected - 1.0).abs() < 1e-6,
        "{} vs {expected}",
        out.force.x
    );
    assert!(!out.sliding);
    // Without friction and without slip: no force, no slide, nothing non-finite.
    let frictionless = MicroSlip::<f64, 8>::new(MindlinParameters::new(SHEAR, 0.0, 0.0).unwrap());
    let still = TangentialInput {
        slip_velocity: Vec3::ZERO,
        ..input
    };
    let out = frictionless.force::<Libm>(&MicroSlipSprings::default(), &still);
    assert_eq!(out.force, Vec3::ZERO);
    assert!(soft_sphere::prelude::ContactState::is_finite(&out.state));
}

#[test]
fn a_state_is_finite_only_when_every_number_is() {
    use soft_sphere::prelude::ContactState;
    let good = MicroSlipSprings::<f64, 2> {
        normal: Vec3::new(0.0, 0.0, 1.0),
        contact_radius: 1e-4,
        positions: [0.0, 0.5],
        displacements: [Vec3::new(1e-6, 0.0, 0.0); 2],
    };
    assert!(good.is_finite());
    let mut bad = good;
    bad.normal.x = f64::NAN;
    assert!(!bad.is_finite());
    let mut bad = good;
    bad.contact_radius = f64::INFINITY;
    assert!(!bad.is_finite());
    let mut bad = good;
    bad.positions[1] = f64::NAN;
    assert!(!bad.is_finite());
    let mut bad = good;
    bad.displacements[1].z = f64::NAN;
    assert!(!bad.is_finite());
}

#[test]
fn a_position_not_above_the_last_or_at_the_rim_ends_the_profile() {
    // A caller's state whose positions stop rising, or reach the rim, is read up to there: the
    // same force as the state with the rest cleared to the rim's (1, 0).
    let bed = steel::<4>(1e-5);
    let u = 0.05 * bed.full_slip();
    let x = |s: f64| Vec3::new(s * u, 0.0, 0.0);
    let state = |positions: [f64; 4], tail: Vec3<f64>| MicroSlipSprings {
        normal: Vec3::new(0.0, 0.0, 1.0),
        contact_radius: bed.contact_radius(),
        positions,
        displacements: [x(1.0), x(0.8), tail, tail],
    };
    let force = |bed: &ShearBed<4>, s: MicroSlipSprings<f64, 4>| {
        let input = bed.input(Vec3::new(0.0, 0.0, 1.0), Vec3::ZERO);
        bed.law.force::<Libm>(&s, &input).force
    };
    let cleared = force(&bed, state([0.0, 0.5, 1.0, 1.0], Vec3::ZERO));
    for positions in [
        [0.0, 0.5, 0.5, 0.7],
        [0.0, 0.5, 1.0, 1.0],
        [0.0, 0.5, 0.4, 0.9],
    ] {
        let read = force(&bed, state(positions, x(0.6)));
        assert_eq!(read, cleared, "{positions:?}");
    }
    // And a tail that does rise is read: it changes the force.
    let rising = force(&bed, state([0.0, 0.5, 0.6, 0.7], x(0.6)));
    assert!(rising.x < cleared.x, "{rising:?} vs {cleared:?}");
}

/// The bed the law stands for, spring by spring: `COUNT` springs at the midpoints of equal cells
/// along the contact radius, each moved by the step and held to its own limit
/// `delta_s (1 - t^2)` along its own direction. Its mean displacement (m).
struct SpringBySpring {
    springs: Vec<(f64, f64)>,
}

impl SpringBySpring {
    const COUNT: usize = 20_000;

    fn new() -> Self {
        Self {
            springs: vec![(0.0, 0.0); Self::COUNT],
        }
    }

    fn push(&mut self, (dx, dy): (f64, f64), full_slip: f64) -> (f64, f64) {
        let n = Self::COUNT as f64;
        let (mut sx, mut sy) = (0.0, 0.0);
        for (i, u) in self.springs.iter_mut().enumerate() {
            let t = (i as f64 + 0.5) / n;
            let limit = full_slip * (1.0 - t * t);
            let (x, y) = (u.0 + dx, u.1 + dy);
            let length = (x * x + y * y).sqrt();
            *u = if length > limit {
                (x * limit / length, y * limit / length)
            } else {
                (x, y)
            };
            sx += u.0;
            sy += u.1;
        }
        (sx / n, sy / n)
    }
}

/// The largest distance, over `mu P`, between the law's force and the spring-by-spring bed's
/// along a path that turns: along x, across along y, back along -x, round a circle.
fn distance_from_the_springs<const N: usize>() -> f64 {
    let mut bed = steel::<N>(1e-5);
    let mut springs = SpringBySpring::new();
    let full = bed.full_slip();
    let stiffness = 8.0 * SHEAR * bed.contact_radius();
    let mut path = Vec::new();
    path.extend(std::iter::repeat_n((0.003 * full, 0.0), 200));
    path.extend(std::iter::repeat_n((0.0, 0.0015 * full), 200));
    path.extend(std::iter::repeat_n((-0.004 * full, 0.0), 250));
    path.extend((0..600).map(|k| {
        let angle = k as f64 * std::f64::consts::TAU / 600.0;
        let step = 0.2 * full * std::f64::consts::TAU / 600.0;
        (-angle.sin() * step, angle.cos() * step)
    }));
    let mut worst = 0.0_f64;
    for (dx, dy) in path {
        bed.push(dx, dy);
        let (mx, my) = springs.push((dx, dy), full);
        let (fx, fy) = (-stiffness * mx, -stiffness * my);
        let d = ((bed.last.0 - fx).powi(2) + (bed.last.1 - fy).powi(2)).sqrt();
        worst = worst.max(d / bed.limit());
    }
    worst
}

#[test]
fn a_turning_path_stays_near_the_bed_it_stands_for() {
    // Along x the profile is exact; across and round, the springs of a slipping annulus turn
    // each by its own angle and the breakpoints follow them as far as they are allowed:
    // within 0.3 % of mu P at 16 breakpoints, 0.04 % at 32 (measured 0.17 % and 0.032 %), and
    // a few percent when a handful must hold it all (measured 2.0 % at 4 and 8, 7.1 % at 3).
    let distances = [
        (3, distance_from_the_springs::<3>(), 0.1),
        (4, distance_from_the_springs::<4>(), 0.03),
        (8, distance_from_the_springs::<8>(), 0.03),
        (16, distance_from_the_springs::<16>(), 3e-3),
        (32, distance_from_the_springs::<32>(), 4e-4),
    ];
    for (n, d, bound) in distances {
        assert!(d < bound, "{n} breakpoints: {d:e} of mu P, bound {bound:e}");
    }
}

/// A random walk of the contact (steps of up to a tenth of the full-slip displacement, any
/// direction in the plane) under a load that breathes, on a bed of `N` breakpoints: the profile
/// stays well formed (positions rising from the centre, then the rim's), the springs never hold
/// more than the work put in.
fn random_walk<const N: usize>(seed: u64) {
    let mut bed = steel::<N>(1e-5);
    let full = bed.full_slip();
    let base = bed.overlap;
    let mut random = Xorshift::new(seed);
    let mut uniform = || random.unit();
    for k in 0..5_000 {
        bed.overlap = base * (1.0 + 0.3 * (0.01 * k as f64).sin());
        let (length, angle) = (0.1 * full * uniform(), std::f64::consts::TAU * uniform());
        bed.push(length * angle.cos(), length * angle.sin());
        let p = bed.state.positions;
        let used = 1 + p
            .windows(2)
            .take_while(|w| w[1] > w[0] && w[1] < 1.0)
            .count();
        assert_eq!(p[0], 0.0, "{N} breakpoints, step {k}: {p:?}");
        assert!(
            p[used..].iter().all(|&t| t == 1.0),
            "{N} breakpoints, step {k}: {p:?}"
        );
        let held = bed.law.stored_energy(&bed.state);
        assert!(held <= bed.work * (1.0 + 1e-9) + 1e-30, "{N}, step {k}");
    }
}

#[test]
fn a_random_walk_keeps_the_profile_well_formed() {
    for seed in 1..4 {
        random_walk::<3>(seed);
        random_walk::<4>(seed);
        random_walk::<8>(seed);
    }
}

/// One step from 1,000 caller's profiles along x (2 to 6 breakpoints, each within or past its
/// limit, of either sign, on a contact 0.7 to 1.4 times as wide as now), against the springs it
/// stands for: each spring takes the profile's value where it was (linear in `1 - t^2` between
/// breakpoints, zero at and past the old rim), moves and is held to its limit. Along one
/// direction the law's step is theirs (with room for every crossing), to the springs' own
/// discretisation (1.4e-8 of mu P measured); and so is the energy they hold (1.4e-8 of
/// mu P delta_s).
#[test]
fn one_step_from_any_profile_along_x_is_the_springs_step() {
    let bed = steel::<32>(1e-5);
    let full = bed.full_slip();
    let stiffness = 8.0 * SHEAR * bed.contact_radius();
    let limit = |t: f64| full * (1.0 - t * t);
    let mut random = Xorshift::new(7);
    let mut uniform = || random.unit();
    let (mut worst, mut worst_energy) = (0.0_f64, 0.0_f64);
    for _ in 0..1000 {
        let used = 2 + (uniform() * 5.0) as usize;
        let mut positions = [1.0; 32];
        positions[0] = 0.0;
        // Rising, a breakpoint to each of `used - 1` equal bands (the springs below resolve
        // every segment).
        let bands = (used - 1) as f64;
        for (k, t) in positions[1..used].iter_mut().enumerate() {
            *t = 0.05 + 0.9 * (k as f64 + 0.1 + 0.8 * uniform()) / bands;
        }
        let mut values = [0.0; 32];
        for k in 0..used {
            values[k] = (2.0 * uniform() - 1.0) * 1.5 * limit(positions[k]);
        }
        let step = (2.0 * uniform() - 1.0) * 0.3 * full;
        // The contact was this much wider (a shrinking contact) or narrower (a growing one).
        let ratio = 0.7 + 0.7 * uniform();
        let state = MicroSlipSprings {
            normal: Vec3::new(0.0, 0.0, 1.0),
            contact_radius: bed.contact_radius() * ratio,
            positions,
            displacements: values.map(|x| Vec3::new(x, 0.0, 0.0)),
        };
        let input = bed.input(Vec3::new(0.0, 0.0, 1.0), Vec3::new(step, 0.0, 0.0));
        let out = bed.law.force::<Libm>(&state, &input);
        let law = out.force.x;
        // The springs, at the midpoints of 20,000 equal cells.
        let count = 20_000;
        let (mut sum, mut squares) = (0.0, 0.0);
        let mut k = 0;
        for i in 0..count {
            let t = (i as f64 + 0.5) / count as f64;
            // Where the spring was on the old contact: past its rim, new area free of shear.
            let was = t / ratio;
            while k + 1 < used && positions[k + 1] <= was {
                k += 1;
            }
            let (a, u) = (positions[k], values[k]);
            let (b, v) = if k + 1 < used {
                (positions[k + 1], values[k + 1])
            } else {
                (1.0, 0.0)
            };
            let w = (a * a - was * was) / (a * a - b * b);
            let old = if was < 1.0 { u + w * (v - u) } else { 0.0 };
            let moved = old + step;
            let held = moved.clamp(-limit(t), limit(t));
            sum += held;
            squares += held * held;
        }
        let springs = -stiffness * sum / count as f64;
        // What they hold, `8 G* a / 2` times the mean of `u^2`, against the law's account.
        let energy = 0.5 * stiffness * squares / count as f64;
        let held = bed.law.stored_energy(&out.state);
        worst_energy = worst_energy.max((held - energy).abs() / (bed.limit() * full));
        let d = (law - springs).abs() / bed.limit();
        worst = worst.max(d);
    }
    eprintln!(
        "one step from a profile: force {worst:e} of mu P, energy {worst_energy:e} of mu P delta_s"
    );
    assert!(worst < 1e-6, "{worst:e} of mu P");
    assert!(worst_energy < 1e-6, "{worst_energy:e} of mu P delta_s");
}

#[test]
fn the_stable_step_is_mindlins() {
    // The springs never exceed Mindlin's no-slip stiffness: the same tangential mode.
    let hertz = soft_sphere::prelude::Hertz::new(
        MODULUS,
        0.9,
        soft_sphere::prelude::HertzImpact {
            speed: 5.0,
            effective_radius: RADIUS,
        },
    )
    .unwrap();
    let p = MindlinParameters::new(SHEAR, 0.5, FRICTION).unwrap();
    let design = soft_sphere::prelude::NormalModel::design_contact(&hertz, 0.03);
    let micro = MicroSlip::<f64, 8>::new(p).critical_time_step(&design, 0.01);
    let mindlin = soft_sphere::prelude::MindlinAA(p).critical_time_step(&design, 0.01);
    assert!(micro > 0.0 && micro.is_finite());
    assert_eq!(micro, mindlin);
}
