//! The common laws by name: each alias fixes the normal and tangential slots and leaves the
//! precision `F` open, with the default backend, rotation and no rolling resistance (change
//! those with the law's `with_*` builders). `ContactLaw<f64, LinearSpringDashpot<f64>,
//! ModelAA<f64>>` is `LinearAA<f64>`.

use crate::law::contact_law::ContactLaw;
use crate::law::normal::{Hertz, LinearSpringDashpot};
use crate::law::rolling::NoRolling;
use crate::law::rotation::Rotating;
use crate::law::tangential::{
    Frictionless, MicroSlip, MindlinAA, MindlinAALuding, MindlinStateless, ModelAA, ModelAALuding,
    Stateless,
};
use crate::value::float::Float;

/// The linear spring-dashpot with any tangential slot `T` (and the other slots as
/// [`ContactLaw`]'s): the family every linear law below belongs to.
pub type LinearLaw<F, T, M = <F as Float>::DefaultBackend, R = Rotating, Ro = NoRolling> =
    ContactLaw<F, LinearSpringDashpot<F>, T, M, R, Ro>;
/// Hertz with any tangential slot `T` (and the other slots as [`ContactLaw`]'s): the family
/// every Hertz law below belongs to.
pub type HertzLaw<F, T, M = <F as Float>::DefaultBackend, R = Rotating, Ro = NoRolling> =
    ContactLaw<F, Hertz<F>, T, M, R, Ro>;

/// The linear spring-dashpot with Model AA's limited tangential spring.
pub type LinearAA<F> = LinearLaw<F, ModelAA<F>>;
/// The linear spring-dashpot with Model AA and Luding's reset of the spring on sliding.
pub type LinearAALuding<F> = LinearLaw<F, ModelAALuding<F>>;
/// The linear spring-dashpot with the simplified law that stores no tangential history.
pub type LinearStateless<F> = LinearLaw<F, Stateless<F>>;
/// The linear spring-dashpot without friction.
pub type LinearFrictionless<F> = LinearLaw<F, Frictionless>;
/// Hertz with Mindlin's tangential spring, limited as Model AA.
pub type HertzAA<F> = HertzLaw<F, MindlinAA<F>>;
/// Hertz with Mindlin's tangential spring, limited as Model AA with Luding's reset.
pub type HertzAALuding<F> = HertzLaw<F, MindlinAALuding<F>>;
/// Hertz with the simplified tangential law at Mindlin's stiffness.
pub type HertzStateless<F> = HertzLaw<F, MindlinStateless<F>>;
/// Hertz without friction.
pub type HertzFrictionless<F> = HertzLaw<F, Frictionless>;
/// Hertz with Mindlin and Deresiewicz's micro-slip, its profile in up to `SPRINGS` breakpoints.
pub type HertzMicroSlip<F, const SPRINGS: usize> = HertzLaw<F, MicroSlip<F, SPRINGS>>;

/// Calls `$callback!` with every law named above, one entry each, in this form:
/// `Alias = "name", NormalSlot, TangentialSlot;`. This is the one list of the named laws: the
/// C ABI's codes, the validation cases, the property tests, the benchmarks and the docs' tables
/// are checked against it (`host-tests/tests/law_list.rs`), so adding a law is its slots, its
/// alias above and one entry here. The name is the one a host offers it by (`"hertz/aa"`); the
/// slots are the types' names, generic over `F` except `Frictionless` and `MicroSlip`'s count.
///
/// ```
/// macro_rules! names {
///     ($($alias:ident = $name:literal, $normal:ident, $tangential:ident;)*) => {
///         [$($name),*]
///     };
/// }
/// let names = soft_sphere::for_each_law!(names);
/// assert!(names.contains(&"hertz/aa"));
/// ```
#[macro_export]
macro_rules! for_each_law {
    ($callback:ident) => {
        $callback! {
            LinearStateless = "stateless", LinearSpringDashpot, Stateless;
            LinearAA = "aa", LinearSpringDashpot, ModelAA;
            LinearAALuding = "aa/luding", LinearSpringDashpot, ModelAALuding;
            LinearFrictionless = "frictionless", LinearSpringDashpot, Frictionless;
            HertzFrictionless = "hertz/frictionless", Hertz, Frictionless;
            HertzStateless = "hertz/stateless", Hertz, MindlinStateless;
            HertzAA = "hertz/aa", Hertz, MindlinAA;
            HertzAALuding = "hertz/aa/luding", Hertz, MindlinAALuding;
            HertzMicroSlip = "hertz/microslip", Hertz, MicroSlip;
        }
    };
}
