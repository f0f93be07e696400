//! The simplified ("stateless") law (`docs/physics.md`, section 3.1): Model AA's slider with the
//! tangential displacement estimated from the contact's elapsed time instead of stored.

use super::{Slide, TangentialInput, TangentialModel, TangentialOutput, TangentialParameters};
use crate::law::normal::{NormalContact, NormalOscillator};
use crate::value::backend::MathBackend;
use crate::value::float::Float;

/// The stateless law: `xi = v_t t_e`, then Model AA's limit and sliding rule. Stores nothing.
///
/// The elapsed time comes from the linear normal oscillator, whose overlap is
/// `delta = (v0 / wd) exp(-beta t) sin(wd t)` in a binary impact, so that
/// `t_e = atan2(wd delta, delta' + beta delta) / wd`, in `[0, pi / max(wd, beta)]`. At critical
/// damping (`wd = 0`) the limit `delta / (delta' + beta delta)` is used, with the same bound
/// `pi / beta`, so that the estimate is continuous as `e -> 0`.
///
/// It reproduces rigid-body theory (tangential restitution 5/7 below the gross-sliding threshold,
/// the closed form above it, rolling at 5/7 of the initial speed on a plate) near `e = 1`. With
/// more normal damping its gross-sliding branch departs from the closed form, because the Coulomb
/// limit includes the normal dashpot (see [`TangentialParameters`]): 6.7 % more friction impulse
/// than rigid-body theory at `e = 0.5`. Like every stateless
/// law it has no static friction at zero slip: it cannot hold a sphere at rest on a slope, and it
/// cannot show the elastic recoil of a stored spring. For persistent contacts (not binary impacts)
/// `t_e` is only a bounded estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stateless<F>(pub TangentialParameters<F>);

/// Estimated time since first touch of a binary impact, from the overlap and its rate.
#[inline(always)]
pub(crate) fn elapsed_contact_time<F: Float, M: MathBackend<F>>(
    overlap: F,
    approach_rate: F,
    oscillator: &NormalOscillator<F>,
) -> F {
    let (wd, beta) = (oscillator.damped_frequency, oscillator.decay_rate);
    let cosine_part = approach_rate + beta * overlap;
    if wd > F::ZERO {
        // Clamp guards approximate atan2 backends that stray outside [0, pi].
        let phase = M::atan2(wd * overlap, cosine_part)
            .max_of(F::ZERO)
            .min_of(F::PI);
        // Capped at pi / beta as well, so that the estimate is continuous as wd -> 0 (e -> 0):
        // without it, a rounding-sized wd would give pi / wd late in a contact. The cap only acts
        // when wd < beta, that is e < exp(-pi) = 0.043.
        (phase / wd).min_of(F::PI / beta)
    } else {
        let bound = F::PI / beta;
        if cosine_part > F::ZERO {
            (overlap / cosine_part).min_of(bound)
        } else {
            bound
        }
    }
}

/// Stability bound of a stateless law of stiffness `k_t` and dashpot `eta_t` on `mass`: while
/// sticking it is a dashpot of strength `k_t t_e + eta_t`, largest at `t_e = pi / max(wd, beta)`
/// (the cap of [`elapsed_contact_time`]), and an explicit update of a dashpot is stable below
/// `2 m_t / strength`.
pub(crate) fn stateless_critical_step<F: Float>(
    stiffness: F,
    dashpot: F,
    oscillator: &NormalOscillator<F>,
    mass: F,
) -> F {
    let longest = F::PI / oscillator.damped_frequency.max_of(oscillator.decay_rate);
    F::TWO * mass / (stiffness * longest + dashpot)
}

impl<F: Float> TangentialModel<F> for Stateless<F> {
    type State = ();

    #[inline(always)]
    fn force<M: MathBackend<F>>(
        &self,
        _: &(),
        contact: &TangentialInput<F>,
    ) -> TangentialOutput<F, ()> {
        let elapsed = elapsed_contact_time::<F, M>(
            contact.overlap,
            contact.approach_rate,
            &contact.oscillator,
        );
        let displacement = contact.slip_velocity * elapsed;
        let (force, sliding) = self.0.slide::<M>(displacement, contact, Slide::AlongTrial);
        TangentialOutput {
            force,
            state: (),
            sliding,
        }
    }

    /// While sticking the law is a dashpot of strength `k_t t_e + eta_t`, with `t_e` at most
    /// `pi / wd`: the explicit update of the slip stays stable below `2 m_t / (k_t pi / wd + eta_t)`.
    fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        let oscillator = &design.oscillator;
        stateless_critical_step(
            self.0.stiffness(),
            self.0.dashpot(oscillator),
            oscillator,
            tangential_mass,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::elapsed_contact_time;
    use crate::law::normal::{LinearSpringDashpot, NormalModel};
    use crate::value::backend::Libm;
    use core::f64::consts::PI;

    #[test]
    fn the_elapsed_time_is_read_off_the_normal_oscillator_exactly() {
        // Along the closed-form binary impact delta = (v0 / wd) exp(-beta t) sin(wd t) (and
        // v0 t exp(-beta t) at critical damping) the estimate is the time since first touch.
        let (mass, v0) = (1.0e-5, 0.7);
        for e in [0.0, 0.3, 0.7, 0.98] {
            let law = LinearSpringDashpot::new(1.0e4, e).unwrap();
            let o = NormalModel::<f64>::oscillator::<Libm>(&law, mass);
            let (wd, beta) = (o.damped_frequency, o.decay_rate);
            // Up to the documented bound pi / max(wd, beta).
            let t_c = PI / wd.max(beta);
            for k in 1..20 {
                let t = t_c * f64::from(k) / 20.0;
                let decay = libm::exp(-beta * t);
                let (overlap, rate) = if wd > 0.0 {
                    let (s, c) = (libm::sin(wd * t), libm::cos(wd * t));
                    (v0 / wd * decay * s, v0 * decay * (c - beta / wd * s))
                } else {
                    (v0 * t * decay, v0 * decay * (1.0 - beta * t))
                };
                let estimate = elapsed_contact_time::<f64, Libm>(overlap, rate, &o);
                assert!(
                    libm::fabs(estimate / t - 1.0) < 1e-9,
                    "e = {e}, t = {t:e}: {estimate:e}"
                );
            }
        }
    }

    #[test]
    fn the_elapsed_time_is_continuous_as_the_damped_frequency_vanishes() {
        // Found by the f32-against-f64 property at e = 0: a rounding-sized wd used to give
        // pi / wd late in a contact instead of the wd = 0 branch's pi / beta.
        let law = LinearSpringDashpot::new(1000.0f64, 0.0).unwrap();
        let exact = NormalModel::<f64>::oscillator::<Libm>(&law, 1e-3);
        assert_eq!(exact.damped_frequency, 0.0);
        let mut nearly = exact;
        nearly.damped_frequency = 1e-9 * exact.natural_frequency;
        for (overlap, rate) in [(1e-4, 0.5), (1e-4, -0.01), (1e-4, -0.5), (1e-6, -1.0)] {
            let a = elapsed_contact_time::<f64, Libm>(overlap, rate, &exact);
            let b = elapsed_contact_time::<f64, Libm>(overlap, rate, &nearly);
            assert!(
                libm::fabs(a - b) <= 1e-6 * a,
                "{overlap} {rate}: {a} vs {b}"
            );
        }
    }
}
