//! The normal slot: how the overlap and approach rate become a normal force.
//!
//! | slot | elastic force | dashpot | restitution |
//! |---|---|---|---|
//! | [`LinearSpringDashpot`] | `k_n delta` | `eta_n`, constant | exactly `e` (or the clamped law's rebound) |
//! | [`LinearSpring`] | `k_n delta` | none | 1 |
//! | [`Hertz`] | `(4/3) E* sqrt(R*) delta^(3/2)` | `alpha sqrt(m* (4/3) E* a)`, grows as `delta^(1/4)` (Tsuji et al. 1992) | exactly `e` at any impact speed |

mod accuracy;
mod hertz;
mod linear;

pub(crate) use accuracy::{Accuracy, scan_accuracy};

pub use hertz::{Hertz, HertzImpact};
pub use linear::{LinearSpring, LinearSpringDashpot};

use crate::value::backend::MathBackend;
use crate::value::float::Float;

/// The linear normal oscillator of one contact (effective mass `m*`, stiffness `k_n`, dashpot
/// `eta_n`): what the tangential laws and the time steps derive from the normal law.
///
/// A linear law has one oscillator per pair of masses. A [`Hertz`] contact stiffens as it loads:
/// its oscillator is the one linearised at the current overlap, and every rate in it grows as
/// `sqrt(a)`, the square root of the contact radius.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormalOscillator<F> {
    /// Undamped angular frequency `w0 = sqrt(k_n / m*)` (rad/s).
    pub natural_frequency: F,
    /// Normal dashpot coefficient `eta_n` (N s/m).
    pub damping_coefficient: F,
    /// Decay rate `beta = eta_n / (2 m*)` (1/s).
    pub decay_rate: F,
    /// Damped angular frequency `wd = sqrt(w0^2 - beta^2)` (rad/s); zero at critical damping.
    pub damped_frequency: F,
}

impl<F: Float> NormalOscillator<F> {
    /// Damping ratio `beta / w0`.
    pub fn damping_ratio(&self) -> F {
        self.decay_rate / self.natural_frequency
    }

    /// Every rate times `factor`.
    #[inline(always)]
    pub(crate) fn scaled(&self, factor: F) -> Self {
        Self {
            natural_frequency: self.natural_frequency * factor,
            damping_coefficient: self.damping_coefficient * factor,
            decay_rate: self.decay_rate * factor,
            damped_frequency: self.damped_frequency * factor,
        }
    }
}

/// What the normal law says of one touching contact at one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormalContact<F> {
    /// Normal force on body `j` along the unit normal (N); positive pushes the bodies apart.
    pub force: F,
    /// The contact's oscillator at this overlap (gives the tangential dashpot and the stateless
    /// law's elapsed time).
    pub oscillator: NormalOscillator<F>,
    /// Radius `a = sqrt(R* delta)` of the contact area (m), from which Mindlin's tangential
    /// stiffness `8 G* a` follows. Zero for a linear law, which has no contact area.
    pub contact_radius: F,
}

/// A normal force law: the first slot of a [`ContactLaw`](crate::ContactLaw).
pub trait NormalModel<F: Float>: Copy + core::fmt::Debug + Send + Sync {
    /// Whether [`NormalModel::contact`] gives a contact radius (a tangential law whose stiffness
    /// grows with it, [`MindlinAA`](crate::MindlinAA) and its kin, needs one).
    const CONTACT_RADIUS: bool = false;

    /// What the law derives once per pair of masses, computed with backend `M`: a linear law's
    /// oscillator; for [`Hertz`], the oscillator at a contact radius of 1 m, which
    /// [`NormalModel::contact`] scales by `sqrt(a)`.
    fn oscillator<M: MathBackend<F>>(&self, effective_mass: F) -> NormalOscillator<F>;

    /// The contact at overlap `delta > 0` and normal relative velocity `v_n` (negative while
    /// approaching), for effective radius `R*` and the pair's `oscillator`.
    fn contact<M: MathBackend<F>>(
        &self,
        overlap: F,
        normal_velocity: F,
        effective_radius: F,
        oscillator: &NormalOscillator<F>,
    ) -> NormalContact<F>;

    /// The tangent stiffness `dF/d delta` of this contact (N/m): `k_n` for a linear law,
    /// `2 E* a` for [`Hertz`]. The contact's undamped frequency is `sqrt(this / m*)`, which its
    /// step's stability limit is checked against.
    fn tangent_stiffness(&self, contact: &NormalContact<F>) -> F;

    /// The elastic energy the spring holds at overlap `delta` (J): `k_n delta^2 / 2` for a
    /// linear law, `(8/15) E* sqrt(R*) delta^(5/2)` for [`Hertz`] (the work of its elastic
    /// force from first touch). The dashpot holds none.
    fn elastic_energy(&self, overlap: F, effective_radius: F) -> F;

    /// The stiffest contact the law expects for this effective mass, from which the time steps
    /// follow: a linear law's only oscillator; for [`Hertz`], the contact at the peak overlap of
    /// its declared largest impact.
    fn design_contact(&self, effective_mass: F) -> NormalContact<F>;

    /// The approach speed (m/s) and effective radius (m) of the impact the law is declared for:
    /// [`Hertz`]'s largest impact. A linear law is the same at every speed and size and keeps
    /// the default of ones. The accuracy limit ([`ContactLaw::accurate_phase`](crate::ContactLaw::accurate_phase))
    /// is scanned at this impact.
    fn design_impact(&self) -> (F, F) {
        (F::ONE, F::ONE)
    }

    /// How long a binary impact carries normal force (s): from first touch until the force ends.
    /// Infinite when it never ends (critical damping without the attraction clamp). For
    /// [`Hertz`], the declared largest impact's.
    fn contact_duration(&self, effective_mass: F) -> F;

    /// Largest time step for which explicit (symplectic Euler, leapfrog, velocity Verlet)
    /// integration of this law's oscillator is stable.
    fn critical_time_step(&self, effective_mass: F) -> F;
}

/// Stability bound of explicit integration for a damped linear oscillator of frequency `w` and
/// damping ratio `zeta`: `dt < (2 / w) (sqrt(1 + zeta^2) - zeta)` (symplectic Euler and central
/// differences share it; it reduces to `2 / w` without damping).
pub(crate) fn damped_critical_step<F: Float>(frequency: F, damping_ratio: F) -> F {
    let root = F::DefaultBackend::sqrt(F::ONE + damping_ratio * damping_ratio);
    F::TWO / frequency * (root - damping_ratio)
}
