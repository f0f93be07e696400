//! Hertz's elastic contact with the Tsuji et al. (1992) dashpot, its coefficient solved from the
//! restitution.

use super::{NormalContact, NormalModel, NormalOscillator, damped_critical_step};
use crate::value::backend::MathBackend;
use crate::value::error::{Parameter, ParameterError, non_negative, positive};
use crate::value::float::Float;

/// The impact a [`Hertz`] law is declared for: the fastest approach speed and the largest
/// effective radius its scene will see. A Hertz contact stiffens with its overlap, so its time
/// steps ([`NormalModel::critical_time_step`], [`NormalModel::contact_duration`]) are those of
/// this impact; a faster or larger one is stiffer than the step was checked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzImpact<F> {
    /// Largest normal approach speed (m/s).
    pub speed: F,
    /// Largest effective radius `R* = R_i R_j / (R_i + R_j)` (`R` against a wall) (m).
    pub effective_radius: F,
}

/// Hertz's normal force with the Tsuji et al. (1992) dashpot:
/// `F_n = (4/3) E* a delta - alpha sqrt(m* (4/3) E* a) v_n`, with `a = sqrt(R* delta)` the contact
/// radius, so the elastic part is `(4/3) E* sqrt(R*) delta^(3/2)` and the dashpot grows as
/// `delta^(1/4)`.
///
/// With this dashpot the rebound ratio of a free impact does not depend on the impact speed, the
/// masses or the moduli: it is a function of `alpha` alone. [`Hertz::new`] finds the `alpha`
/// that gives the requested `e` by integrating the dimensionless impact
/// `x'' = -x^(3/2) - alpha x^(1/4) x'` (RK4, 400 steps per unit, bisection in `f64`;
/// `docs/physics.md`, section 2.2). LAMMPS (`damping tsuji`) uses Tsuji's polynomial fit of
/// `alpha(e)` instead; the `validate` run measures its restitution error.
///
/// Like the linear dashpot this one pulls at the end of contact; the rebound ratio is `e` with
/// that pull. At `e = 0` the dashpot is the weakest that never lets the bodies part (the
/// overlap creeps back to zero), as critical damping is for the linear law.
///
/// ```
/// use soft_sphere::prelude::{Hertz, HertzImpact, Material};
/// let alumina = Material::new(380.0e9_f64, 0.23).unwrap();
/// let largest = HertzImpact { speed: 3.9, effective_radius: 2.5e-3 };
/// let law = Hertz::new(alumina.modulus_against_rigid(), 0.5, largest).unwrap();
/// assert!((law.damping_factor() - 0.4818).abs() < 1e-3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hertz<F> {
    effective_modulus: F,
    restitution: F,
    damping_factor: F,
    largest: HertzImpact<F>,
    // Dimensionless duration of the solved impact, in units of (m* v^2 / K)^(2/5) / v.
    duration_factor: F,
}

/// Steps per unit of dimensionless time in the restitution solve.
const STEPS_PER_UNIT: f64 = 400.0;
/// A dimensionless impact still touching after this long counts as never parting (the undamped
/// one lasts 3.218).
const LONGEST: f64 = 60.0;
/// Above this `alpha` no impact parts within [`LONGEST`].
const HIGHEST_DAMPING: f64 = 3.0;

/// The dimensionless impact `x'' = -x^(3/2) - alpha x^(1/4) x'`, `x(0) = 0`, `x'(0) = 1`: the
/// rebound speed and the duration, or `None` when the bodies have not parted after [`LONGEST`].
fn dimensionless_impact(alpha: f64) -> Option<(f64, f64)> {
    let h = 1.0 / STEPS_PER_UNIT;
    let acceleration = |x: f64, v: f64| {
        let x = x.max(0.0);
        let root = libm::sqrt(x);
        -x * root - alpha * libm::sqrt(root) * v
    };
    let (mut x, mut v, mut t) = (0.0_f64, 1.0_f64, 0.0_f64);
    while t < LONGEST {
        let (k1x, k1v) = (v, acceleration(x, v));
        let (k2x, k2v) = (
            v + 0.5 * h * k1v,
            acceleration(x + 0.5 * h * k1x, v + 0.5 * h * k1v),
        );
        let (k3x, k3v) = (
            v + 0.5 * h * k2v,
            acceleration(x + 0.5 * h * k2x, v + 0.5 * h * k2v),
        );
        let (k4x, k4v) = (v + h * k3v, acceleration(x + h * k3x, v + h * k3v));
        let next_x = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        let next_v = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if next_x <= 0.0 {
            // Interpolate the crossing within the step.
            let fraction = x / (x - next_x);
            return Some((-(v + fraction * (next_v - v)), t + fraction * h));
        }
        (x, v, t) = (next_x, next_v, t + h);
    }
    None
}

/// The `alpha` whose impact rebounds at `restitution`, and that impact's dimensionless duration
/// (infinite at `e = 0`).
fn solve_damping(restitution: f64) -> (f64, f64) {
    if restitution >= 1.0 {
        let (_, duration) = dimensionless_impact(0.0).unwrap_or((1.0, f64::INFINITY));
        return (0.0, duration);
    }
    // The rebound falls monotonically with alpha, to zero where the bodies stop parting.
    let (mut low, mut high) = (0.0_f64, HIGHEST_DAMPING);
    for _ in 0..48 {
        let middle = 0.5 * (low + high);
        match dimensionless_impact(middle) {
            Some((rebound, _)) if rebound > restitution => low = middle,
            _ => high = middle,
        }
    }
    let alpha = if restitution > 0.0 {
        0.5 * (low + high)
    } else {
        high
    };
    let duration = dimensionless_impact(alpha).map_or(f64::INFINITY, |(_, t)| t);
    (alpha, duration)
}

impl<F: Float> Hertz<F> {
    /// A Hertz contact of effective modulus `E*` (Pa; [`Material`](crate::Material) computes it)
    /// rebounding at restitution `e` in `[0, 1]`, declared for impacts up to `largest`.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] / [`ParameterError::NotPositive`] for `E*`, the speed or
    /// the radius; [`ParameterError::NonFinite`] or [`ParameterError::RestitutionOutOfRange`]
    /// for `e`.
    pub fn new(
        effective_modulus: F,
        restitution: F,
        largest: HertzImpact<F>,
    ) -> Result<Self, ParameterError> {
        let effective_modulus = positive(effective_modulus, Parameter::Modulus)?;
        if !restitution.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Restitution));
        }
        if !(restitution >= F::ZERO && restitution <= F::ONE) {
            return Err(ParameterError::RestitutionOutOfRange);
        }
        let largest = HertzImpact {
            speed: positive(largest.speed, Parameter::Speed)?,
            effective_radius: positive(largest.effective_radius, Parameter::Radius)?,
        };
        let (alpha, duration) = solve_damping(restitution.to_f64());
        Ok(Self {
            effective_modulus,
            restitution,
            damping_factor: F::from_f64(alpha),
            largest,
            duration_factor: F::from_f64(duration),
        })
    }

    /// A Hertz contact whose dashpot factor `alpha` is given instead of solved for: for
    /// reproducing another code's damping (LAMMPS' `damping tsuji` takes `alpha` from Tsuji's
    /// polynomial in `e`). [`Hertz::restitution`] is then the rebound ratio this `alpha` gives.
    ///
    /// # Errors
    /// As [`Hertz::new`]; [`ParameterError::NonFinite`] / [`ParameterError::Negative`] for
    /// `alpha` ([`Parameter::DampingFactor`]).
    pub fn with_damping_factor(
        effective_modulus: F,
        damping_factor: F,
        largest: HertzImpact<F>,
    ) -> Result<Self, ParameterError> {
        let alpha = non_negative(damping_factor, Parameter::DampingFactor)?;
        let law = Self::new(effective_modulus, F::ONE, largest)?;
        let (rebound, duration) =
            dimensionless_impact(alpha.to_f64()).unwrap_or((0.0, f64::INFINITY));
        Ok(Self {
            restitution: F::from_f64(rebound),
            damping_factor: alpha,
            duration_factor: F::from_f64(duration),
            ..law
        })
    }

    /// Effective modulus `E*` (Pa).
    pub fn effective_modulus(&self) -> F {
        self.effective_modulus
    }

    /// The coefficient of restitution the dashpot was solved for.
    pub fn restitution(&self) -> F {
        self.restitution
    }

    /// The dashpot's `alpha`: `eta_n = alpha sqrt(m* (4/3) E* a)`.
    pub fn damping_factor(&self) -> F {
        self.damping_factor
    }

    /// The impact the time steps are for.
    pub fn largest_impact(&self) -> HertzImpact<F> {
        self.largest
    }

    /// The largest contact radius the declared impact reaches for effective mass `m*` (m):
    /// `sqrt(R* delta_max)` at the declared `R*` and the undamped impact's peak overlap
    /// `delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5)`.
    pub fn largest_contact_radius(&self, effective_mass: F) -> F {
        let overlap = self.largest_overlap(effective_mass);
        F::from_f64(libm::sqrt(self.largest.effective_radius.to_f64() * overlap))
    }

    /// `(4/3) E*`: the secant stiffness `F / delta` per metre of contact radius.
    fn stiffness_per_radius(&self) -> F {
        F::from_f64(4.0 / 3.0) * self.effective_modulus
    }

    /// Peak overlap of the undamped declared impact for this effective mass:
    /// `(15 m* v^2 / (16 E* sqrt(R*)))^(2/5)`, which bounds the damped one.
    fn largest_overlap(&self, effective_mass: F) -> f64 {
        let (speed, radius) = (
            self.largest.speed.to_f64(),
            self.largest.effective_radius.to_f64(),
        );
        let energy_ratio = 15.0 * effective_mass.to_f64() * speed * speed
            / (16.0 * self.effective_modulus.to_f64() * libm::sqrt(radius));
        libm::pow(energy_ratio, 0.4)
    }
}

impl<F: Float> NormalModel<F> for Hertz<F> {
    const CONTACT_RADIUS: bool = true;

    /// `2 E* a`: the force `(4/3) E* a delta` with `a = sqrt(R* delta)`, differentiated.
    #[inline(always)]
    fn tangent_stiffness(&self, contact: &NormalContact<F>) -> F {
        F::TWO * self.effective_modulus * contact.contact_radius
    }

    /// `(8/15) E* a delta^2` with `a = sqrt(R* delta)`.
    fn elastic_energy(&self, overlap: F, effective_radius: F) -> F {
        let radius = F::DefaultBackend::sqrt(effective_radius * overlap);
        F::from_f64(8.0 / 15.0) * self.effective_modulus * radius * overlap * overlap
    }

    /// The oscillator linearised at a contact radius of 1 m: tangent stiffness `dF/d delta =
    /// 2 E* a`, dashpot `alpha sqrt(m* (4/3) E*)`.
    #[inline(always)]
    fn oscillator<M: MathBackend<F>>(&self, effective_mass: F) -> NormalOscillator<F> {
        let natural_frequency = M::sqrt(F::TWO * self.effective_modulus / effective_mass);
        let damping_coefficient =
            self.damping_factor * M::sqrt(effective_mass * self.stiffness_per_radius());
        let decay_rate = damping_coefficient / (F::TWO * effective_mass);
        let damped_squared = natural_frequency * natural_frequency - decay_rate * decay_rate;
        NormalOscillator {
            natural_frequency,
            damping_coefficient,
            decay_rate,
            damped_frequency: M::sqrt(damped_squared.max_of(F::ZERO)),
        }
    }

    #[inline(always)]
    fn contact<M: MathBackend<F>>(
        &self,
        overlap: F,
        normal_velocity: F,
        effective_radius: F,
        oscillator: &NormalOscillator<F>,
    ) -> NormalContact<F> {
        let contact_radius = M::sqrt(effective_radius * overlap);
        let oscillator = oscillator.scaled(M::sqrt(contact_radius));
        let elastic = self.stiffness_per_radius() * contact_radius * overlap;
        NormalContact {
            force: elastic - oscillator.damping_coefficient * normal_velocity,
            oscillator,
            contact_radius,
        }
    }

    fn design_contact(&self, effective_mass: F) -> NormalContact<F> {
        let overlap = F::from_f64(self.largest_overlap(effective_mass));
        let unit = self.oscillator::<F::DefaultBackend>(effective_mass);
        // The peak of an impact: the overlap is at rest.
        self.contact::<F::DefaultBackend>(overlap, F::ZERO, self.largest.effective_radius, &unit)
    }

    fn design_impact(&self) -> (F, F) {
        (self.largest.speed, self.largest.effective_radius)
    }

    /// `duration_factor (m* v^2 / K)^(2/5) / v` with `K = (4/3) E* sqrt(R*)`: for `e = 1`,
    /// `2.868 (m*^2 / (R* E*^2 v))^(1/5)`.
    fn contact_duration(&self, effective_mass: F) -> F {
        let (speed, radius) = (
            self.largest.speed.to_f64(),
            self.largest.effective_radius.to_f64(),
        );
        let stiffness = 4.0 / 3.0 * self.effective_modulus.to_f64() * libm::sqrt(radius);
        let length = libm::pow(effective_mass.to_f64() * speed * speed / stiffness, 0.4);
        F::from_f64(self.duration_factor.to_f64() * length / speed)
    }

    fn critical_time_step(&self, effective_mass: F) -> F {
        let peak = self.design_contact(effective_mass).oscillator;
        damped_critical_step(peak.natural_frequency, peak.damping_ratio())
    }
}
