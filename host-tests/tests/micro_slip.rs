//! The micro-slip law against Cattaneo & Mindlin's and Mindlin & Deresiewicz's closed forms
//! under a constant normal load, their convergence in the number of springs, what it does past
//! its declared contact radius, and that no loading cycle creates energy.

use host_tests::analytic::{
    cattaneo_mindlin, cycle_dissipation, full_slip_displacement, mindlin_deresiewicz_unloading,
};
use soft_sphere::tangential::TangentialInput;
use soft_sphere::{
    Libm, MicroSlip, MicroSlipSprings, MindlinParameters, NormalOscillator, Parameter,
    ParameterError, TangentialModel, Vec3,
};

/// Steel on a rigid plane: `E*`, `G*` (Pa), `R` (m), `mu`.
const MODULUS: f64 = 2.286e11;
const SHEAR: f64 = 4.706e10;
const RADIUS: f64 = 0.01;
const FRICTION: f64 = 0.3;

/// A micro-slip bed driven by hand: a held overlap and a prescribed tangential displacement.
struct Bed<const N: usize> {
    law: MicroSlip<f64, N>,
    state: MicroSlipSprings<f64, N>,
    overlap: f64,
    /// Tangential displacement so far (m).
    displacement: f64,
    /// Work done on the contact by whoever moved it, at each step's end force (J): an upper
    /// bound on what a spring can have taken.
    work: f64,
    /// The same by the trapezoidal rule, second order in the step (J).
    trapezoid: f64,
    /// The last force along x and y (N).
    last: (f64, f64),
    /// Whether the last step slid.
    sliding: bool,
}

impl<const N: usize> Bed<N> {
    /// A bed spanning `span` times the contact radius at `overlap`.
    fn new(overlap: f64, span: f64, dashpot: f64) -> Self {
        let p = MindlinParameters::new(SHEAR, dashpot, FRICTION).unwrap();
        let law = MicroSlip::new(p, span * (RADIUS * overlap).sqrt()).unwrap();
        Self {
            law,
            state: MicroSlipSprings::default(),
            overlap,
            displacement: 0.0,
            work: 0.0,
            trapezoid: 0.0,
            last: (0.0, 0.0),
            sliding: false,
        }
    }

    fn radius(&self) -> f64 {
        (RADIUS * self.overlap).sqrt()
    }

    /// Hertz's elastic load at the held overlap.
    fn load(&self) -> f64 {
        4.0 / 3.0 * MODULUS * self.radius() * self.overlap
    }

    /// What the law sees at the held overlap with normal `normal`, moved by `slip` in one step.
    fn input(&self, normal: Vec3<f64>, slip: Vec3<f64>) -> TangentialInput<f64> {
        TangentialInput {
            normal,
            slip_velocity: slip,
            normal_force: self.load(),
            overlap: self.overlap,
            approach_rate: 0.0,
            oscillator: NormalOscillator::default(),
            contact_radius: self.radius(),
            time_step: 1.0,
        }
    }

    /// The force on j after the contact turns to `normal` without slipping.
    fn turned_to(&self, normal: Vec3<f64>) -> Vec3<f64> {
        let input = self.input(normal, Vec3::ZERO);
        self.law.force::<Libm>(&self.state, &input).force
    }

    /// Moves the contact by `step` along x (and `across` along y): the tangential force on j
    /// along x, over `mu P`.
    fn push(&mut self, step: f64, across: f64) -> f64 {
        let input = self.input(Vec3::new(0.0, 0.0, 1.0), Vec3::new(step, across, 0.0));
        let out = self.law.force::<Libm>(&self.state, &input);
        self.state = out.state;
        self.displacement += step;
        // The driver holds j against the contact's force: its work is -F . du.
        self.work -= out.force.x * step + out.force.y * across;
        self.trapezoid -=
            0.5 * ((out.force.x + self.last.0) * step + (out.force.y + self.last.1) * across);
        self.last = (out.force.x, out.force.y);
        self.sliding = out.sliding;
        let limit = FRICTION * self.load();
        assert!(out.force.norm_squared().sqrt() <= limit * (1.0 + 1e-12));
        -out.force.x / limit
    }

    fn full_slip(&self) -> f64 {
        full_slip_displacement(FRICTION, self.load(), SHEAR, self.radius())
    }
}

/// Steps per full-slip displacement in the driven paths.
const STEPS: usize = 4000;

/// The largest distance from Cattaneo-Mindlin's first loading, from Mindlin-Deresiewicz's
/// unloading and reloading, and the relative error of the energy one cycle dissipates, for a
/// cycle to `T* = 0.8 mu P` with `N` springs across `span` contact radii.
fn errors<const N: usize>(span: f64) -> [f64; 3] {
    let mut bed = Bed::<N>::new(1e-5, span, 0.0);
    let full = bed.full_slip();
    let du = full / STEPS as f64;
    // First loading to the displacement where Cattaneo-Mindlin's force is 0.8 mu P.
    let amplitude = 0.8_f64;
    let turning = full * (1.0 - (1.0 - amplitude).powf(2.0 / 3.0));
    let steps = (turning / du).round() as usize;
    let mut loading = 0.0_f64;
    for _ in 0..steps {
        let t = bed.push(du, 0.0);
        loading = loading.max((t - cattaneo_mindlin(bed.displacement, full)).abs());
    }
    let (top, top_force) = (bed.displacement, cattaneo_mindlin(bed.displacement, full));
    // Unload to -delta*, reload to +delta*: the second half mirrors the first.
    let mut cycle = 0.0_f64;
    let work_before = bed.trapezoid;
    for _ in 0..2 * steps {
        let t = bed.push(-du, 0.0);
        let expected = mindlin_deresiewicz_unloading(bed.displacement, top, top_force, full);
        cycle = cycle.max((t - expected).abs());
    }
    for _ in 0..2 * steps {
        let t = bed.push(du, 0.0);
        let expected = -mindlin_deresiewicz_unloading(-bed.displacement, top, top_force, full);
        cycle = cycle.max((t - expected).abs());
    }
    let dissipated = (bed.trapezoid - work_before) / (FRICTION * bed.load() * full);
    let exact = cycle_dissipation(top_force);
    [loading, cycle, (dissipated / exact - 1.0).abs()]
}

#[test]
fn cattaneo_mindlin_and_mindlin_deresiewicz_are_met_and_converge() {
    // The contact edge inside a cell (span 1.13 contact radii) and on a cell boundary (1.0).
    for span in [1.13, 1.0] {
        let e = [
            errors::<4>(span),
            errors::<8>(span),
            errors::<16>(span),
            errors::<32>(span),
            errors::<64>(span),
        ];
        for (k, row) in e.iter().enumerate() {
            println!("span {span} springs {}: {row:?}", 4 << k);
        }
        // 16 springs: within 2 % of mu P of every branch, 3 % of the dissipated energy.
        assert!(
            e[2][0] < 0.02 && e[2][1] < 0.02 && e[2][2] < 0.03,
            "{:?}",
            e[2]
        );
        // 64 springs: within 0.5 % and 1 %.
        assert!(
            e[4][0] < 5e-3 && e[4][1] < 5e-3 && e[4][2] < 1e-2,
            "{:?}",
            e[4]
        );
        // Second order in the spring width: N^2 times each error stays within 1.3 times its
        // value at 8 springs. (Not monotone: where the contact edge falls in its cell varies
        // with N.)
        for (k, row) in e.iter().enumerate().skip(2) {
            let springs = (4 << k) as f64;
            for q in 0..3 {
                assert!(
                    springs * springs * row[q] <= 1.3 * 64.0 * e[1][q],
                    "span {span}, quantity {q}, {springs} springs: {} against {} at 8",
                    row[q],
                    e[1][q]
                );
            }
        }
    }
}

#[test]
fn the_stuck_contact_has_mindlins_stiffness_and_slides_at_coulombs_limit_past_its_span() {
    // A contact 1.5 times wider than the springs span: the last cell takes the rim.
    for span in [1.0 / 1.5, 1.0, 2.0] {
        let mut bed = Bed::<8>::new(1e-5, span, 0.0);
        let du = 1e-3 * bed.full_slip();
        let t = bed.push(du, 0.0) * FRICTION * bed.load();
        let mindlin = 8.0 * SHEAR * bed.radius() * du;
        assert!(
            (t / mindlin - 1.0).abs() < 1e-12,
            "span {span}: {t} vs {mindlin}"
        );
        assert!(!bed.sliding, "span {span}");
        // What it holds is Mindlin's spring's energy, k_t u^2 / 2.
        let held = bed.law.stored_energy(&bed.state);
        let spring = 0.5 * 8.0 * SHEAR * bed.radius() * du * du;
        assert!(
            (held / spring - 1.0).abs() < 1e-12,
            "span {span}: {held} vs {spring}"
        );
        for _ in 0..3000 {
            bed.push(du, 0.0);
        }
        // Past the full-slip displacement the contact slides at mu P exactly.
        let t = bed.push(du, 0.0);
        assert!((t - 1.0).abs() < 1e-12, "span {span}: {t}");
        assert!(bed.sliding, "span {span}");
    }
}

#[test]
fn new_contact_area_is_laid_down_free_and_leaving_area_takes_its_shear() {
    // Shear a small contact, then grow it: the force is unchanged (the new rim is unstressed),
    // though the stuck stiffness grew with the radius.
    // The first contact's edge inside a cell (2.1 radii over 32 cells).
    let mut bed = Bed::<32>::new(1e-5, 2.1, 0.0);
    let du = 0.2 * bed.full_slip() / 100.0;
    for _ in 0..100 {
        bed.push(du, 0.0);
    }
    let small = bed.push(0.0, 0.0);
    let load = bed.load();
    bed.overlap *= 2.0;
    let grown = bed.push(0.0, 0.0) * FRICTION * bed.load() / (FRICTION * load);
    assert!((grown / small - 1.0).abs() < 1e-12, "{small} then {grown}");
    // Shrinking back to below the first contact radius, the shear falls at least with the
    // radius (the leaving annulus carried its part).
    let before = grown * FRICTION * load;
    bed.overlap /= 4.0;
    let shrunk = bed.push(0.0, 0.0) * FRICTION * bed.load();
    assert!(
        shrunk <= before * 0.5_f64.sqrt() * (1.0 + 1e-12),
        "{before} then {shrunk}"
    );
}

#[test]
fn no_loading_cycle_creates_energy() {
    // Circles, reversals and a breathing normal load: what the springs hold never exceeds the
    // work put in, and a cycle back to the start has taken work.
    let mut bed = Bed::<16>::new(1e-5, 1.3, 0.0);
    let full = bed.full_slip();
    let base = bed.overlap;
    let mut held = 0.0;
    for k in 0..20_000 {
        let angle = k as f64 * 0.01;
        bed.overlap = base * (1.0 + 0.5 * (0.0037 * k as f64).sin());
        let (dx, dy) = (-angle.sin() * 0.01 * full, angle.cos() * 0.01 * full);
        bed.push(dx, dy);
        held = bed.law.stored_energy(&bed.state);
        assert!(
            held <= bed.work * (1.0 + 1e-9) + 1e-30,
            "step {k}: holds {held}, took {}",
            bed.work
        );
    }
    assert!(bed.work > held, "{} {held}", bed.work);
}

#[test]
fn a_rotating_contact_turns_its_springs() {
    // A stuck sheared contact whose normal turns: the force turns with it, keeping its length.
    let mut bed = Bed::<8>::new(1e-5, 1.0, 0.0);
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
}

#[test]
fn bad_spans_are_refused_and_good_ones_given_back() {
    let p = MindlinParameters::new(SHEAR, 0.0, FRICTION).unwrap();
    let law = MicroSlip::<f64, 8>::new(p, 3.0e-4).unwrap();
    assert_eq!(law.largest_contact_radius(), 3.0e-4);
    assert_eq!(*law.parameters(), p);
    assert_eq!(
        MicroSlip::<f64, 8>::new(p, 0.0),
        Err(ParameterError::NotPositive(Parameter::Radius))
    );
    assert_eq!(
        MicroSlip::<f64, 8>::new(p, f64::NAN),
        Err(ParameterError::NonFinite(Parameter::Radius))
    );
}

#[test]
fn a_contact_turning_about_its_shear_keeps_it() {
    // The normal turns about the displacement's own direction: the smallest rotation leaves the
    // displacement, and the force, as they were.
    let mut bed = Bed::<8>::new(1e-5, 1.0, 0.0);
    bed.push(0.1 * bed.full_slip(), 0.0);
    let t = bed.push(0.0, 0.0) * FRICTION * bed.load();
    let (s, c) = 0.4_f64.sin_cos();
    let force = bed.turned_to(Vec3::new(0.0, -s, c));
    let d = force - Vec3::new(-t, 0.0, 0.0);
    assert!(d.norm_squared().sqrt() < 1e-12 * t, "{force:?} vs {t}");
}

#[test]
fn the_dashpot_adds_to_the_springs_and_no_friction_means_no_force() {
    // One step from first touch, stuck: -k_t v dt - r eta_n v.
    let p = MindlinParameters::new(SHEAR, 0.5, 10.0).unwrap();
    let radius = (RADIUS * 1e-5).sqrt();
    let law = MicroSlip::<f64, 8>::new(p, radius).unwrap();
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
        (out.force.x / expected - 1.0).abs() < 1e-12,
        "{} vs {expected}",
        out.force.x
    );
    assert!(!out.sliding);
    // Without friction and without slip: no force, no slide, nothing non-finite.
    let frictionless =
        MicroSlip::<f64, 8>::new(MindlinParameters::new(SHEAR, 0.0, 0.0).unwrap(), radius).unwrap();
    let still = TangentialInput {
        slip_velocity: Vec3::ZERO,
        ..input
    };
    let out = frictionless.force::<Libm>(&MicroSlipSprings::default(), &still);
    assert_eq!(out.force, Vec3::ZERO);
    assert!(soft_sphere::ContactState::is_finite(&out.state));
}

#[test]
fn a_state_is_finite_only_when_every_number_is() {
    use soft_sphere::ContactState;
    let good = MicroSlipSprings::<f64, 2> {
        normal: Vec3::new(0.0, 0.0, 1.0),
        contact_radius: 1e-4,
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
    bad.displacements[1].z = f64::NAN;
    assert!(!bad.is_finite());
}
