//! The common laws by name: each alias fixes the normal and tangential slots and leaves the
//! precision `F` open, with the default backend, rotation and no rolling resistance (change
//! those with the law's `with_*` builders). `ContactLaw<f64, LinearSpringDashpot<f64>,
//! ModelAA<f64>>` is `LinearAA<f64>`.

use crate::law::ContactLaw;
use crate::normal::{Hertz, LinearSpringDashpot};
use crate::tangential::{
    Frictionless, MicroSlip, MindlinAA, MindlinAALuding, MindlinStateless, ModelAA, ModelAALuding,
    Stateless,
};

/// The linear spring-dashpot with Model AA's limited tangential spring.
pub type LinearAA<F> = ContactLaw<F, LinearSpringDashpot<F>, ModelAA<F>>;
/// The linear spring-dashpot with Model AA and Luding's reset of the spring on sliding.
pub type LinearAALuding<F> = ContactLaw<F, LinearSpringDashpot<F>, ModelAALuding<F>>;
/// The linear spring-dashpot with the simplified law that stores no tangential history.
pub type LinearStateless<F> = ContactLaw<F, LinearSpringDashpot<F>, Stateless<F>>;
/// The linear spring-dashpot without friction.
pub type LinearFrictionless<F> = ContactLaw<F, LinearSpringDashpot<F>, Frictionless>;
/// Hertz with Mindlin's tangential spring, limited as Model AA.
pub type HertzAA<F> = ContactLaw<F, Hertz<F>, MindlinAA<F>>;
/// Hertz with Mindlin's tangential spring, limited as Model AA with Luding's reset.
pub type HertzAALuding<F> = ContactLaw<F, Hertz<F>, MindlinAALuding<F>>;
/// Hertz with the simplified tangential law at Mindlin's stiffness.
pub type HertzStateless<F> = ContactLaw<F, Hertz<F>, MindlinStateless<F>>;
/// Hertz without friction.
pub type HertzFrictionless<F> = ContactLaw<F, Hertz<F>, Frictionless>;
/// Hertz with Mindlin and Deresiewicz's micro-slip over `SPRINGS` cells.
pub type HertzMicroSlip<F, const SPRINGS: usize> = ContactLaw<F, Hertz<F>, MicroSlip<F, SPRINGS>>;
