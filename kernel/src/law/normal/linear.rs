//! The linear laws: a spring, with or without a dashpot.

use super::{NormalContact, NormalModel, NormalOscillator, damped_critical_step};
use crate::value::backend::MathBackend;
use crate::value::error::{Parameter, ParameterError, positive};
use crate::value::float::Float;

/// Linear spring and dashpot: `F_n = k_n delta - eta_n v_n`, with `eta_n` from a coefficient of
/// restitution so that a free binary impact rebounds with exactly `e` times its approach speed.
///
/// `eta_n = 2 zeta sqrt(m* k_n)`, `zeta = |ln e| / sqrt(pi^2 + ln^2 e)` (`zeta = 1` at `e = 0`).
/// Near the end of contact the dashpot pulls (the force turns attractive). By default that pull is
/// kept, which makes the rebound ratio exactly `e`; [`LinearSpringDashpot::with_attraction_clamped`]
/// clips the force at zero instead (LIGGGHTS' `limitForce`), which raises the effective restitution
/// (0.5 becomes 0.5503, 0.9 becomes 0.9020; Schwager & Poeschel 2007).
/// [`LinearSpringDashpot::clamped_with_rebound`] builds a clamped law that rebounds at a given
/// ratio.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearSpringDashpot<F> {
    stiffness: F,
    restitution: F,
    damping_ratio: F,
    // sqrt(1 - zeta^2) = pi / sqrt(pi^2 + ln^2 e), kept so wd = w0 * this needs no second sqrt.
    damped_frequency_ratio: F,
    clamp_attraction: bool,
}

impl<F: Float> LinearSpringDashpot<F> {
    /// A spring of stiffness `k_n` (N/m) with damping from restitution `e` in `[0, 1]`.
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] or [`ParameterError::NotPositive`] for the stiffness;
    /// [`ParameterError::NonFinite`] for a NaN or infinite `e`;
    /// [`ParameterError::RestitutionOutOfRange`] for `e` outside `[0, 1]`.
    pub fn new(stiffness: F, restitution: F) -> Result<Self, ParameterError> {
        let stiffness = positive(stiffness, Parameter::NormalStiffness)?;
        if !restitution.is_finite() {
            return Err(ParameterError::NonFinite(Parameter::Restitution));
        }
        if !(restitution >= F::ZERO && restitution <= F::ONE) {
            return Err(ParameterError::RestitutionOutOfRange);
        }
        let (damping_ratio, damped_frequency_ratio) = if restitution == F::ZERO {
            (F::ONE, F::ZERO)
        } else {
            let log_e = F::DefaultBackend::ln(restitution);
            let root = F::DefaultBackend::sqrt(F::PI * F::PI + log_e * log_e);
            (log_e.abs() / root, F::PI / root)
        };
        Ok(Self {
            stiffness,
            restitution,
            damping_ratio,
            damped_frequency_ratio,
            clamp_attraction: false,
        })
    }

    /// A spring of stiffness `k_n` whose force is clipped at zero (never attractive), damped so
    /// that a free binary impact rebounds with exactly `rebound` times its approach speed.
    ///
    /// The clipped contact ends when `k_n delta + eta_n delta' = 0`, and the rebound ratio is then
    /// `exp(-2 (zeta / s) atan(s / zeta))` with `s = sqrt(1 - zeta^2)` (Schwager & Poeschel 2007;
    /// `docs/physics.md`, section 2). This solves it for `zeta` (bisection in `f64`, 64 halvings).
    /// It falls from 1 at `zeta = 0` to `exp(-2)` = 0.1353 at critical damping, so lower rebound
    /// ratios cannot be had from a clipped linear dashpot. [`LinearSpringDashpot::restitution`]
    /// then returns `rebound`.
    ///
    /// ```
    /// use soft_sphere::prelude::LinearSpringDashpot;
    /// let law = LinearSpringDashpot::clamped_with_rebound(1000.0_f64, 0.5).unwrap();
    /// assert!(law.clamps_attraction());
    /// // The unclipped law with the same dashpot has a lower restitution.
    /// let same_dashpot = LinearSpringDashpot::new(1000.0, 0.4363).unwrap();
    /// assert!((law.damping_ratio() - same_dashpot.damping_ratio()).abs() < 1e-4);
    /// ```
    ///
    /// # Errors
    /// As [`LinearSpringDashpot::new`], and [`ParameterError::ReboundUnreachable`] for a rebound
    /// ratio below `exp(-2)`.
    pub fn clamped_with_rebound(stiffness: F, rebound: F) -> Result<Self, ParameterError> {
        let law = Self::new(stiffness, rebound)?;
        let target = -libm::log(rebound.to_f64());
        if target > 2.0 {
            return Err(ParameterError::ReboundUnreachable {
                rebound: rebound.to_f64(),
                lowest: libm::exp(-2.0),
            });
        }
        // -ln(rebound) rises monotonically with zeta, from 0 to 2.
        let log_rebound = |zeta: f64| {
            if zeta >= 1.0 {
                return 2.0;
            }
            let s = libm::sqrt(1.0 - zeta * zeta);
            2.0 * zeta / s * libm::atan2(s, zeta)
        };
        let (mut low, mut high) = (0.0_f64, 1.0_f64);
        for _ in 0..64 {
            let middle = 0.5 * (low + high);
            if log_rebound(middle) < target {
                low = middle;
            } else {
                high = middle;
            }
        }
        let zeta = 0.5 * (low + high);
        Ok(Self {
            damping_ratio: F::from_f64(zeta),
            damped_frequency_ratio: F::from_f64(libm::sqrt(1.0 - zeta * zeta)),
            clamp_attraction: true,
            ..law
        })
    }

    /// The same law with the normal force clipped at zero (never attractive).
    pub fn with_attraction_clamped(mut self) -> Self {
        self.clamp_attraction = true;
        self
    }

    /// Normal stiffness `k_n` (N/m).
    pub fn stiffness(&self) -> F {
        self.stiffness
    }

    /// The coefficient of restitution the damping was derived from.
    pub fn restitution(&self) -> F {
        self.restitution
    }

    /// Damping ratio `zeta` (0 undamped, 1 critical).
    pub fn damping_ratio(&self) -> F {
        self.damping_ratio
    }

    /// Whether attractive normal forces are clipped to zero.
    pub fn clamps_attraction(&self) -> bool {
        self.clamp_attraction
    }
}

impl<F: Float> NormalModel<F> for LinearSpringDashpot<F> {
    #[inline(always)]
    fn tangent_stiffness(&self, _: &NormalContact<F>) -> F {
        self.stiffness
    }

    fn elastic_energy(&self, overlap: F, _: F) -> F {
        F::HALF * self.stiffness * overlap * overlap
    }

    #[inline(always)]
    fn oscillator<M: MathBackend<F>>(&self, effective_mass: F) -> NormalOscillator<F> {
        let natural_frequency = M::sqrt(self.stiffness / effective_mass);
        let decay_rate = self.damping_ratio * natural_frequency;
        NormalOscillator {
            natural_frequency,
            damping_coefficient: F::TWO * effective_mass * decay_rate,
            decay_rate,
            damped_frequency: self.damped_frequency_ratio * natural_frequency,
        }
    }

    #[inline(always)]
    fn contact<M: MathBackend<F>>(
        &self,
        overlap: F,
        normal_velocity: F,
        _: F,
        oscillator: &NormalOscillator<F>,
    ) -> NormalContact<F> {
        let force = self.stiffness * overlap - oscillator.damping_coefficient * normal_velocity;
        let force = if self.clamp_attraction {
            force.max_of(F::ZERO)
        } else {
            force
        };
        NormalContact {
            force,
            oscillator: *oscillator,
            contact_radius: F::ZERO,
        }
    }

    fn design_contact(&self, effective_mass: F) -> NormalContact<F> {
        linear_design(self.oscillator::<F::DefaultBackend>(effective_mass))
    }

    fn contact_duration(&self, effective_mass: F) -> F {
        let o = self.oscillator::<F::DefaultBackend>(effective_mass);
        let (wd, beta) = (o.damped_frequency, o.decay_rate);
        if !self.clamp_attraction {
            // Free contact ends when the overlap returns to zero: half a damped period (never,
            // pi / 0 = infinity, at critical damping).
            return F::PI / wd;
        }
        // Clamped contact ends when k delta + eta delta' = 0, at wd t = 2 atan(wd / beta).
        if wd > F::ZERO {
            F::TWO * F::DefaultBackend::atan2(wd, beta) / wd
        } else {
            F::TWO / beta
        }
    }

    fn critical_time_step(&self, effective_mass: F) -> F {
        let o = self.oscillator::<F::DefaultBackend>(effective_mass);
        damped_critical_step(o.natural_frequency, self.damping_ratio)
    }
}

/// Linear spring without a dashpot, `F_n = k_n delta`: restitution 1, for scenes that need no
/// normal damping (the dashpot's velocity term is not computed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearSpring<F> {
    stiffness: F,
}

impl<F: Float> LinearSpring<F> {
    /// A spring of stiffness `k_n` (N/m).
    ///
    /// # Errors
    /// [`ParameterError::NonFinite`] or [`ParameterError::NotPositive`] for the stiffness.
    pub fn new(stiffness: F) -> Result<Self, ParameterError> {
        Ok(Self {
            stiffness: positive(stiffness, Parameter::NormalStiffness)?,
        })
    }
}

impl<F: Float> NormalModel<F> for LinearSpring<F> {
    #[inline(always)]
    fn tangent_stiffness(&self, _: &NormalContact<F>) -> F {
        self.stiffness
    }

    fn elastic_energy(&self, overlap: F, _: F) -> F {
        F::HALF * self.stiffness * overlap * overlap
    }

    #[inline(always)]
    fn oscillator<M: MathBackend<F>>(&self, effective_mass: F) -> NormalOscillator<F> {
        let natural_frequency = M::sqrt(self.stiffness / effective_mass);
        NormalOscillator {
            natural_frequency,
            damping_coefficient: F::ZERO,
            decay_rate: F::ZERO,
            damped_frequency: natural_frequency,
        }
    }

    #[inline(always)]
    fn contact<M: MathBackend<F>>(
        &self,
        overlap: F,
        _: F,
        _: F,
        oscillator: &NormalOscillator<F>,
    ) -> NormalContact<F> {
        NormalContact {
            force: self.stiffness * overlap,
            oscillator: *oscillator,
            contact_radius: F::ZERO,
        }
    }

    fn design_contact(&self, effective_mass: F) -> NormalContact<F> {
        linear_design(self.oscillator::<F::DefaultBackend>(effective_mass))
    }

    fn contact_duration(&self, effective_mass: F) -> F {
        F::PI
            / self
                .oscillator::<F::DefaultBackend>(effective_mass)
                .natural_frequency
    }

    fn critical_time_step(&self, effective_mass: F) -> F {
        F::TWO
            / self
                .oscillator::<F::DefaultBackend>(effective_mass)
                .natural_frequency
    }
}

/// A linear law's stiffest contact is its only one: the oscillator, with no contact radius.
fn linear_design<F: Float>(oscillator: NormalOscillator<F>) -> NormalContact<F> {
    NormalContact {
        oscillator,
        ..NormalContact::default()
    }
}
