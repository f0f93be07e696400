//! The accuracy limit of a normal law: the largest phase `w0 dt` a step may advance a contact's
//! normal oscillator by and still give the law's rebound, whatever the step's phase against the
//! first touch.
//!
//! A stable step can still create energy: a contact is first seen at an overlap the sphere
//! reached somewhere inside a step, and last seen somewhere inside another, so a contact resolved
//! in a few steps rebounds faster than the law's restitution (a linear law with `e = 0.7` at 0.9
//! of its stability limit rebounds at up to 1.9 times its impact speed). The limit follows from
//! the integrator's discrete map: a head-on impact is stepped exactly as the integrators of this
//! crate step it (symplectic Euler, and velocity Verlet, whose positions, forces and half-step
//! velocities are the same sequence; see [`crate::value::motion`]) at [`PHASES`] entry phases, with the
//! law's own force, for growing steps; the limit is the last step before any phase rebounds more
//! than [`SCAN_TOLERANCE`] away from the law's rebound at a vanishing step.
//!
//! Every rate of a linear law scales as `1 / sqrt(m*)` and Hertz's impact is self-similar (the
//! rebound at a given phase depends on `w_peak dt` only), so one scan at a unit effective mass,
//! at the law's declared impact ([`NormalModel::design_impact`]), gives the limit of every mass
//! and speed up to the declared one.

use super::{NormalModel, NormalOscillator};
use crate::value::backend::MathBackend;
use crate::value::float::Float;

/// How far from the law's rebound (absolute, in units of the impact speed) an accepted step may
/// rebound at any phase: the documented 0.02, less a margin for steps between the scanned ones.
pub(crate) const SCAN_TOLERANCE: f64 = 0.015;

/// Entry phases per scanned step: the overlap at first sight is `k / PHASES` of one step's
/// travel, `k = 1..=PHASES` (a phase of 0 is first seen a step later, at a whole step's travel).
pub(crate) const PHASES: u32 = 32;

/// The first phase `w0 dt` scanned (below every law's recommended step, `pi / 50` or less), and
/// the ratio between scanned phases.
const FIRST: f64 = 0.02;
const RATIO: f64 = 1.05;

/// The phase of the reference impact, whose rebound stands for the law's own.
const REFERENCE: f64 = 0.002;

/// An impact still touching after this many undamped half-periods counts as never parting
/// (critical damping without the attraction clamp creeps back forever).
const LONGEST: f64 = 64.0;

/// The accuracy limit of a normal law, as phases `w dt` (rad).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Accuracy<F> {
    /// The largest step, as the design contact's phase, at which every entry phase of a
    /// head-on impact at the declared speed rebounds at most [`SCAN_TOLERANCE`] above the law's
    /// rebound: what a time step is checked against.
    pub(crate) design: F,
    /// The largest phase `sqrt(k / m*) dt` of the contact's tangent stiffness `k` that those
    /// impacts reach: what every contact is checked against. The design phase for a linear law;
    /// a little more for [`Hertz`](super::Hertz), whose stepped impact overshoots the continuous
    /// peak overlap.
    pub(crate) contact: F,
}

/// The accuracy limit of `normal`, scanned up to its stability limit. [`FIRST`] when even that
/// step misses (no law of this crate does).
pub(crate) fn scan_accuracy<F: Float, N: NormalModel<F>>(normal: &N) -> Accuracy<F> {
    let impact = Impact::new(normal);
    let stable_phase = normal.critical_time_step(F::ONE) * impact.natural_frequency;
    let reference = impact.rebound(F::from_f64(REFERENCE), F::ONE).0;
    let tolerance = F::from_f64(SCAN_TOLERANCE);
    let first = F::from_f64(FIRST);
    let mut accurate = Accuracy {
        design: first,
        contact: first,
    };
    let mut phase = first;
    while phase < stable_phase {
        let mut reached = F::ZERO;
        let mut k = 1;
        while k <= PHASES {
            let entry = F::from_f64(f64::from(k) / f64::from(PHASES));
            let (rebound, peak) = impact.rebound(phase, entry);
            // A NaN rebound also ends the scan. Rebounding below the law's rebound dissipates
            // more than it should but creates no energy: it is not bounded.
            let within = rebound - reference <= tolerance;
            if !within {
                return accurate;
            }
            reached = reached.max_of(peak);
            k += 1;
        }
        accurate = Accuracy {
            design: phase,
            contact: reached.max_of(accurate.contact),
        };
        phase *= F::from_f64(RATIO);
    }
    accurate
}

/// A head-on impact at the law's declared speed and effective radius, unit effective mass.
struct Impact<'a, F, N> {
    normal: &'a N,
    oscillator: NormalOscillator<F>,
    speed: F,
    effective_radius: F,
    natural_frequency: F,
}

impl<'a, F: Float, N: NormalModel<F>> Impact<'a, F, N> {
    fn new(normal: &'a N) -> Self {
        let (speed, effective_radius) = normal.design_impact();
        Self {
            normal,
            oscillator: normal.oscillator::<F::DefaultBackend>(F::ONE),
            speed,
            effective_radius,
            natural_frequency: normal.design_contact(F::ONE).oscillator.natural_frequency,
        }
    }

    /// The rebound speed over the impact speed of an impact stepped at phase `w0 dt`, first seen
    /// at `entry` of one step's travel, and the largest phase `sqrt(k) dt` its tangent stiffness
    /// `k` reached: the overlap `x` and its rate `u` (the half-step velocity of velocity Verlet)
    /// advance as `u += -F(x, u) dt / m*`, then `x += u dt`, while `x > 0`.
    fn rebound(&self, phase: F, entry: F) -> (F, F) {
        let dt = phase / self.natural_frequency;
        let mut overlap = self.speed * dt * entry;
        let mut rate = self.speed;
        let steps = F::from_f64(LONGEST) * F::PI / phase;
        let mut step = F::ZERO;
        let mut stiffest = F::ZERO;
        while overlap > F::ZERO {
            if step > steps {
                // Never parts: it gives back nothing more.
                break;
            }
            let contact = self.normal.contact::<F::DefaultBackend>(
                overlap,
                -rate,
                self.effective_radius,
                &self.oscillator,
            );
            stiffest = stiffest.max_of(self.normal.tangent_stiffness(&contact));
            rate -= contact.force * dt;
            overlap += rate * dt;
            step += F::ONE;
        }
        let peak = F::DefaultBackend::sqrt(stiffest) * dt;
        if overlap > F::ZERO {
            return (F::ZERO, peak);
        }
        (-rate / self.speed, peak)
    }
}
