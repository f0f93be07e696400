//! docs/physics.md, section 5.7: the micro-slip law's tangential load cycles at a fixed overlap
//! against Mindlin & Deresiewicz's closed form, at every breakpoint count and contact size
//! (`microslip_loops.csv`).

use soft_sphere::prelude::{
    Libm, MicroSlip, MicroSlipSprings, MindlinParameters, NormalOscillator, TangentialModel, Vec3,
};
use soft_sphere::slots::TangentialInput;

use super::{CaseOutput, Table};
use crate::analytic::{cycle_dissipation, full_slip_displacement};
use crate::validation::chung_ooi::test5_pair;

/// Relative tolerance on a cycle's dissipated energy: the trapezoidal rule's error over the
/// cycle's steps (the law itself is exact there).
pub const LOOP_ENERGY_TOLERANCE: f64 = 1e-3;

/// Steps per full-slip displacement in a driven cycle.
pub const STEPS_PER_FULL_SLIP: f64 = 4000.0;

/// A micro-slip contact driven by hand: a held overlap of a sphere of radius `R*` on a half
/// space, and a prescribed tangential displacement, dashpots off.
#[derive(Debug)]
pub struct ShearBed<const N: usize> {
    /// The law.
    pub law: MicroSlip<f64, N>,
    /// Its state.
    pub state: MicroSlipSprings<f64, N>,
    /// `E*` (Pa).
    pub modulus: f64,
    /// `R*` (m).
    pub radius: f64,
    /// The held overlap (m).
    pub overlap: f64,
    /// Tangential displacement so far (m).
    pub displacement: f64,
    /// Work done on the contact by whoever moved it, at each step's end force (J): an upper
    /// bound on what a spring can have taken.
    pub work: f64,
    /// The same by the trapezoidal rule, second order in the step (J).
    pub trapezoid: f64,
    /// The last force along x and y (N).
    pub last: (f64, f64),
    /// Whether the last step slid.
    pub sliding: bool,
}

impl<const N: usize> ShearBed<N> {
    /// A bed of `E*` (Pa), Mindlin's `parameters` and `R*` (m) at `overlap` (m).
    pub fn new(
        modulus: f64,
        parameters: MindlinParameters<f64>,
        radius: f64,
        overlap: f64,
    ) -> Self {
        Self {
            law: MicroSlip::new(parameters),
            state: MicroSlipSprings::default(),
            modulus,
            radius,
            overlap,
            displacement: 0.0,
            work: 0.0,
            trapezoid: 0.0,
            last: (0.0, 0.0),
            sliding: false,
        }
    }

    /// Hertz's contact radius at the held overlap (m).
    pub fn contact_radius(&self) -> f64 {
        (self.radius * self.overlap).sqrt()
    }

    /// Hertz's elastic load at the held overlap (N).
    pub fn load(&self) -> f64 {
        4.0 / 3.0 * self.modulus * self.contact_radius() * self.overlap
    }

    /// `mu P` (N).
    pub fn limit(&self) -> f64 {
        self.law.parameters().friction() * self.load()
    }

    /// Mindlin's full-slip displacement at the held overlap (m).
    pub fn full_slip(&self) -> f64 {
        let p = self.law.parameters();
        full_slip_displacement(
            p.friction(),
            self.load(),
            p.shear_modulus(),
            self.contact_radius(),
        )
    }

    /// What the law sees at the held overlap with normal `normal`, moved by `slip` in one step.
    pub fn input(&self, normal: Vec3<f64>, slip: Vec3<f64>) -> TangentialInput<f64> {
        TangentialInput {
            normal,
            slip_velocity: slip,
            normal_force: self.load(),
            overlap: self.overlap,
            approach_rate: 0.0,
            oscillator: NormalOscillator::default(),
            contact_radius: self.contact_radius(),
            time_step: 1.0,
        }
    }

    /// The force on j after the contact turns to `normal` without slipping.
    pub fn turned_to(&self, normal: Vec3<f64>) -> Vec3<f64> {
        let input = self.input(normal, Vec3::ZERO);
        self.law.force::<Libm>(&self.state, &input).force
    }

    /// Moves the contact by `step` along x (and `across` along y): the tangential force on j
    /// against x, over `mu P`.
    ///
    /// # Panics
    /// When the force exceeds `mu P` (beyond rounding).
    pub fn push(&mut self, step: f64, across: f64) -> f64 {
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
        let limit = self.limit();
        assert!(out.force.norm_squared().sqrt() <= limit * (1.0 + 1e-12));
        -out.force.x / limit
    }

    /// Drives the bed by `distance` in steps of `du` (signed), each step's force against
    /// `expected(displacement)`: the largest distance, over `mu P`.
    pub fn drive(&mut self, distance: f64, du: f64, expected: impl Fn(f64) -> f64) -> f64 {
        let steps = (distance / du.abs()).round() as usize;
        let mut worst = 0.0_f64;
        for _ in 0..steps {
            let t = self.push(du, 0.0);
            worst = worst.max((t - expected(self.displacement)).abs());
        }
        worst
    }

    /// The displacement of Cattaneo & Mindlin's first loading to `T = amplitude mu P` (m).
    pub fn turning_displacement(&self, amplitude: f64) -> f64 {
        self.full_slip() * (1.0 - (1.0 - amplitude).powf(2.0 / 3.0))
    }

    /// A step near `1 / STEPS_PER_FULL_SLIP` of the full-slip displacement that lands on
    /// `distance` (m).
    pub fn step_to(&self, distance: f64) -> f64 {
        distance / (distance * STEPS_PER_FULL_SLIP / self.full_slip()).ceil()
    }
}

/// The energy one tangential cycle between `+-T*` dissipates, `T* = amplitude mu P`, after a
/// first loading to `T*` from rest (J): the trapezoidal rule's work over the closed loop.
pub fn loop_energy<const N: usize>(bed: &mut ShearBed<N>, amplitude: f64) -> f64 {
    let turning = bed.turning_displacement(amplitude);
    let du = bed.step_to(turning);
    bed.drive(turning, du, |_| 0.0);
    let before = bed.trapezoid;
    bed.drive(2.0 * turning, -du, |_| 0.0);
    bed.drive(2.0 * turning, du, |_| 0.0);
    bed.trapezoid - before
}

/// Mindlin & Deresiewicz's energy of that cycle (J).
pub fn closed_form_loop_energy<const N: usize>(bed: &ShearBed<N>, amplitude: f64) -> f64 {
    bed.limit() * bed.full_slip() * cycle_dissipation(amplitude)
}

/// The amplitudes `tau = T* / (mu P)` of the cycles.
pub const AMPLITUDES: [f64; 5] = [0.05, 0.1, 0.3, 0.6, 0.9];
/// The contact radii, as fractions of the largest that Test 5's declared impact reaches.
pub const RADIUS_RATIOS: [f64; 4] = [0.01, 0.05, 0.2, 1.0];

/// One breakpoint count's rows: every amplitude at every contact radius.
fn rows<const N: usize>(table: &mut Table, out: &mut CaseOutput) {
    let pair = test5_pair();
    let hertz = pair.hertz();
    let largest = hertz.largest_contact_radius(pair.effective_mass);
    let mindlin = MindlinParameters::new(pair.effective_shear_modulus, 0.0, pair.friction)
        .expect("valid Mindlin parameters");
    for ratio in RADIUS_RATIOS {
        let contact_radius = ratio * largest;
        let overlap = contact_radius * contact_radius / pair.effective_radius;
        for tau in AMPLITUDES {
            let mut bed = ShearBed::<N>::new(
                pair.effective_modulus,
                mindlin,
                pair.effective_radius,
                overlap,
            );
            let energy = loop_energy(&mut bed, tau);
            let exact = closed_form_loop_energy(&bed, tau);
            table.push(vec![
                (N as f64).into(),
                tau.into(),
                ratio.into(),
                pair.friction.into(),
                bed.load().into(),
                bed.contact_radius().into(),
                pair.effective_shear_modulus.into(),
                energy.into(),
            ]);
            out.relative(
                format!(
                    "micro_slip {N} breakpoints, tau {tau}, contact radius {ratio} of the largest: loop energy vs Mindlin-Deresiewicz"
                ),
                energy,
                exact,
                LOOP_ENERGY_TOLERANCE,
            );
        }
    }
}

/// The cycles at 4, 8, 16 and 32 breakpoints, each amplitude and contact radius.
pub fn case(progress: impl Fn(&str)) -> CaseOutput {
    progress("micro-slip load cycles");
    let mut out = CaseOutput::default();
    let mut table = Table::new(&[
        "springs",
        "tau",
        "radius_ratio",
        "mu",
        "normal_force",
        "contact_radius",
        "shear_modulus",
        "loop_energy",
    ])
    .with_comment(
        "micro-slip: energy (J) of one tangential cycle between +-tau mu P at a fixed overlap, dashpots off, after a first loading from rest; Test 5's steel sphere (R 10 mm) on a rigid plane, contact radii as fractions of the largest its declared 5 m/s impact reaches; springs: breakpoints of the profile; shear_modulus: the kernel's G*",
    );
    rows::<4>(&mut table, &mut out);
    rows::<8>(&mut table, &mut out);
    rows::<16>(&mut table, &mut out);
    rows::<32>(&mut table, &mut out);
    out.tables.push(("microslip_loops".into(), table));
    out
}
