//! The laws the C ABI offers, listed once in [`with_laws!`]: the handles' enums ([`AnyLaw`],
//! [`AnyBound`], the tables' [`PlainTable`] and [`RolledTable`]), every dispatch over them
//! (`each_law!`, `each_table_of!`), the constructors from `ss_params` and from a
//! table's configuration, each code's family and the names a host shows
//! (`ss_model_name`, `ss_model_of_name`, which the LAMMPS plugin reads) all follow from it.
//! So do the `SS_MODEL_*` codes (the header test writes them into the header from the list):
//! adding a law is one entry here. The list has two parts: the laws a handle (`ss_law_new_*`) and
//! a table both take, and those only a table takes (micro-slip, whose state does not fit
//! `ss_state`).

use soft_sphere::prelude::{
    BoundLaw, ContactLaw, Frictionless, Hertz, HertzImpact, HertzMixing, LinearMixing,
    LinearSpringDashpot, MindlinAA, MindlinAALuding, MindlinParameters, MindlinStateless, ModelAA,
    ModelAALuding, ParameterError, Stateless, TangentialParameters, TimeStep,
};

use crate::real::Real;
use crate::ss_params;
use crate::table::{MicroSlipMixing, Rolled, Tabled, elastic, elastic_frictionless, linear};
use crate::table::{linear_frictionless, rolled_elastic, rolled_linear};

/// Calls `$callback!` with every law of the kernel's list (`soft_sphere::for_each_law!`, whose
/// aliases name the variants; `host-tests/tests/law_list.rs` checks the two agree), in two
/// bracketed parts: the laws handles and tables both take, then those only tables take. One entry each: its code's documentation, then
/// `Variant = SS_MODEL_CODE = value, "name", family, TangentialSlot, tangential;` (a
/// tables-only law has no name, since no host offers it by name, and names its table's mixing
/// rule instead of its slot, since no handle holds its law). The family is `linear` (the linear
/// spring-dashpot, `TangentialParameters`) or `hertz` (Hertz, `MindlinParameters`), and
/// `tangential` makes the slot from the family's parameters (a tuple struct's name), is
/// `frictionless` (no tangential parameters are read) or `micro_slip` (Mindlin's parameters
/// spread over the table's declared contact radius). The header test reads these lines to
/// write the `SS_MODEL_*` constants into the C header.
macro_rules! with_laws {
    ($callback:ident ! $($d:tt)?) => {
        $callback! { $($d)?
            [
                /// The stateless (simplified) law: no tangential history is read or written.
                LinearStateless = SS_MODEL_STATELESS = 0, "stateless", linear, Stateless<F>, Stateless;
                /// Model AA: stored tangential spring limited to `mu |F_n| / k_t`.
                LinearAA = SS_MODEL_AA = 1, "aa", linear, ModelAA<F>, ModelAA;
                /// Model AA with Luding's reset: after sliding, spring plus dashpot equal the sliding force.
                LinearAALuding = SS_MODEL_AA_LUDING = 2, "aa/luding", linear, ModelAALuding<F>, ModelAALuding;
                /// No friction: normal force only (no tangential force, no torque, no state).
                LinearFrictionless = SS_MODEL_FRICTIONLESS = 3, "frictionless", linear, Frictionless, frictionless;
                /// Hertz, no friction.
                HertzFrictionless = SS_MODEL_HERTZ_FRICTIONLESS = 4, "hertz/frictionless", hertz, Frictionless, frictionless;
                /// Hertz with the stateless Mindlin law.
                HertzStateless = SS_MODEL_HERTZ_STATELESS = 5, "hertz/stateless", hertz, MindlinStateless<F>, MindlinStateless;
                /// Hertz with Mindlin's stored spring and Model AA's cap.
                HertzAA = SS_MODEL_HERTZ_AA = 6, "hertz/aa", hertz, MindlinAA<F>, MindlinAA;
                /// Hertz with Mindlin's stored spring and Luding's reset.
                HertzAALuding = SS_MODEL_HERTZ_AA_LUDING = 7, "hertz/aa/luding", hertz, MindlinAALuding<F>, MindlinAALuding;
            ]
            [
                /// Hertz with Mindlin & Deresiewicz's micro-slip, its profile in up to `SS_MICROSLIP_SPRINGS`
                /// breakpoints: material tables only (`ss_table_*`; its state, `4 SS_MICROSLIP_SPRINGS + 4`
                /// numbers per contact, does
                /// not fit `ss_state`, so `ss_law_new_*` answers `SS_ERR_UNKNOWN_MODEL`).
                HertzMicroSlip = SS_MODEL_HERTZ_MICROSLIP = 8, hertz, MicroSlipMixing<F>, micro_slip;
            ]
        }
    };
}

/// Each family's law and mixing rule for a tangential slot `T`, named by the family.
mod family {
    /// The linear spring-dashpot.
    pub(crate) mod linear {
        /// The law.
        pub(crate) type Law<F, T> =
            soft_sphere::prelude::LinearLaw<F, T, <F as crate::real::Real>::Backend>;
        /// The mixing rule.
        pub(crate) type Mixing<F, T> =
            soft_sphere::prelude::LinearMixing<F, T, <F as crate::real::Real>::Backend>;
    }
    /// Hertz.
    pub(crate) mod hertz {
        /// The law.
        pub(crate) type Law<F, T> =
            soft_sphere::prelude::HertzLaw<F, T, <F as crate::real::Real>::Backend>;
        /// The mixing rule.
        pub(crate) type Mixing<F, T> =
            soft_sphere::prelude::HertzMixing<F, T, <F as crate::real::Real>::Backend>;
    }
}

/// The law of a family and tangential constructor, from `ss_params`.
macro_rules! law_of {
    ($p:expr, linear, frictionless) => {
        linear_normal($p).map(|normal| ContactLaw::new(normal, Frictionless).with_backend())
    };
    ($p:expr, linear, $make:ident) => {
        linear_normal($p).and_then(|normal| {
            Ok(ContactLaw::new(normal, $make(linear_tangential($p)?)).with_backend())
        })
    };
    ($p:expr, hertz, frictionless) => {
        hertz_normal($p).map(|normal| ContactLaw::new(normal, Frictionless).with_backend())
    };
    ($p:expr, hertz, $make:ident) => {
        hertz_normal($p)
            .and_then(|normal| Ok(ContactLaw::new(normal, $make(mindlin($p)?)).with_backend()))
    };
}

/// The mixing rule of a family and tangential constructor.
macro_rules! mixing_of {
    ($impact:expr, hertz, micro_slip) => {
        MicroSlipMixing { largest: $impact }
    };
    ($impact:expr, linear, frictionless) => {
        LinearMixing::new(|_| Frictionless).with_backend()
    };
    ($impact:expr, linear, $make:ident) => {
        LinearMixing::new($make).with_backend()
    };
    ($impact:expr, hertz, frictionless) => {
        HertzMixing::new($impact, |_| Frictionless).with_backend()
    };
    ($impact:expr, hertz, $make:ident) => {
        HertzMixing::new($impact, $make).with_backend()
    };
}

/// How a table of a family reads a material's coefficients.
macro_rules! properties_of {
    (linear, frictionless) => {
        linear_frictionless
    };
    (linear, $make:ident) => {
        linear
    };
    (hertz, frictionless) => {
        elastic_frictionless
    };
    (hertz, $make:ident) => {
        elastic
    };
}

/// How a table of a family reads a material's coefficients with the rolling ones.
macro_rules! rolled_properties_of {
    (linear) => {
        rolled_linear
    };
    (hertz) => {
        rolled_elastic
    };
}

/// The family's [`Family`].
macro_rules! family_of {
    (linear) => {
        Family::Linear
    };
    (hertz) => {
        Family::Hertz
    };
}

/// Whether a law has friction (the rolling resistance needs it).
macro_rules! rolls {
    (frictionless) => {
        false
    };
    ($make:ident) => {
        true
    };
}

/// The codes, enums, constructors and names, from the list.
macro_rules! registry {
    ($d:tt [$(
        $(#[$doc:meta])*
        $variant:ident = $code:ident = $value:literal, $name:literal, $family:ident, $t:ty, $make:ident;
    )*] [$(
        $(#[$tdoc:meta])*
        $tvariant:ident = $tcode:ident = $tvalue:literal, $tfamily:ident, $tt:ty, $tmake:ident;
    )*]) => {
        $(
            $(#[$doc])*
            pub const $code: i32 = $value;
        )*
        $(
            $(#[$tdoc])*
            pub const $tcode: i32 = $tvalue;
        )*

        /// Which law a handle holds.
        #[derive(Clone, Copy, Debug)]
        pub(crate) enum AnyLaw<F: Real> {
            $(
                #[doc = $name]
                $variant(family::$family::Law<F, $t>),
            )*
        }

        /// Which law a bound handle holds: a copy of the law, bound to its time step.
        #[derive(Debug)]
        pub(crate) enum AnyBound<F: Real> {
            $(
                #[doc = $name]
                $variant(BoundLaw<family::$family::Law<F, $t>>),
            )*
        }

        /// A material table of each law.
        #[derive(Debug)]
        pub(crate) enum PlainTable<F: Real> {
            $(
                #[doc = $name]
                $variant(Box<Tabled<F, family::$family::Mixing<F, $t>>>),
            )*
            $(
                #[doc = stringify!($tvariant)]
                $tvariant(Box<Tabled<F, $tt>>),
            )*
        }

        /// A material table of each law with the elastic-plastic rolling resistance.
        #[derive(Debug)]
        pub(crate) enum RolledTable<F: Real> {
            $(
                #[doc = $name]
                $variant(Box<Tabled<F, Rolled<family::$family::Mixing<F, $t>, F>>>),
            )*
            $(
                #[doc = stringify!($tvariant)]
                $tvariant(Box<Tabled<F, Rolled<$tt, F>>>),
            )*
        }

        /// `$body` with `$law` bound to the law inside an [`AnyLaw`] or an [`AnyBound`],
        /// whichever it is (each arm is compiled for its own law type).
        macro_rules! each_law {
            ($d any:expr, $d kind:ident, $d law:pat => $d body:expr) => {
                match $d any {
                    $( $d kind::$variant($d law) => $d body, )*
                }
            };
        }

        /// `$body` with `$t` bound to the table inside a [`PlainTable`] or a [`RolledTable`].
        macro_rules! each_table_of {
            ($d any:expr, $d kind:ident, $d table:pat => $d body:expr) => {
                match $d any {
                    $( $d kind::$variant($d table) => $d body, )*
                    $( $d kind::$tvariant($d table) => $d body, )*
                }
            };
        }

        impl<F: Real> AnyLaw<F> {
            /// The law `p` describes, before its time step is checked; `None` for a code the
            /// list does not hold for handles.
            pub(crate) fn new(p: &ss_params<F>) -> Option<Result<Self, ParameterError>> {
                Some(match p.model {
                    $( $code => law_of!(p, $family, $make).map(Self::$variant), )*
                    _ => return None,
                })
            }

            /// The law checked at the time step `p` declares.
            pub(crate) fn time_step(&self, p: &ss_params<F>) -> Result<TimeStep<F>, ParameterError> {
                each_law!(self, AnyLaw, l => l.time_step(p.time_step, p.smallest_effective_mass))
            }

            /// The law bound to `time_step`.
            pub(crate) fn at(&self, time_step: TimeStep<F>) -> AnyBound<F> {
                match self {
                    $( Self::$variant(l) => AnyBound::$variant(l.at(time_step)), )*
                }
            }
        }

        impl<F: Real> PlainTable<F> {
            /// A table of `materials` materials of the law `model` names; `None` for a code the
            /// list does not hold.
            pub(crate) fn new(model: i32, impact: HertzImpact<F>, materials: usize) -> Option<Self> {
                Some(match model {
                    $( $code => Self::$variant(Tabled::new(
                        mixing_of!(impact, $family, $make),
                        properties_of!($family, $make),
                        materials,
                    )), )*
                    $( $tcode => Self::$tvariant(Tabled::new(
                        mixing_of!(impact, $tfamily, $tmake),
                        properties_of!($tfamily, $tmake),
                        materials,
                    )), )*
                    _ => return None,
                })
            }
        }

        impl<F: Real> RolledTable<F> {
            /// As [`PlainTable::new`], with the rolling resistance checked for
            /// `smallest_inertia`; `None` also for a frictionless law (nothing to roll
            /// against).
            pub(crate) fn new(
                model: i32,
                impact: HertzImpact<F>,
                materials: usize,
                smallest_inertia: F,
            ) -> Option<Self> {
                Some(match model {
                    $( $code if rolls!($make) => Self::$variant(Tabled::new(
                        Rolled { mixing: mixing_of!(impact, $family, $make), smallest_inertia },
                        rolled_properties_of!($family),
                        materials,
                    )), )*
                    $( $tcode if rolls!($tmake) => Self::$tvariant(Tabled::new(
                        Rolled { mixing: mixing_of!(impact, $tfamily, $tmake), smallest_inertia },
                        rolled_properties_of!($tfamily),
                        materials,
                    )), )*
                    _ => return None,
                })
            }
        }

        /// The family of the law `model` names; `None` for a code no law has.
        pub(crate) fn family(model: i32) -> Option<Family> {
            match model {
                $( $code => Some(family_of!($family)), )*
                $( $tcode => Some(family_of!($tfamily)), )*
                _ => None,
            }
        }

        /// Every named law's code and name, in the list's order.
        pub(crate) const NAMES: &[(i32, &str)] = &[ $( ($code, concat!($name, "\0")), )* ];
    };
}

with_laws!(registry!$);

/// Which normal law a model has, so which fields of `ss_params` describe it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Family {
    /// The linear spring-dashpot: `normal_stiffness`, `restitution`.
    Linear,
    /// Hertz: `effective_modulus`, `restitution` and the declared impact.
    Hertz,
}

/// Whether `model` is a law of Hertz's family, micro-slip included.
pub(crate) fn hertz_model(model: i32) -> bool {
    family(model) == Some(Family::Hertz)
}

/// The linear normal law of `p`.
fn linear_normal<F: Real>(p: &ss_params<F>) -> Result<LinearSpringDashpot<F>, ParameterError> {
    LinearSpringDashpot::new(p.normal_stiffness, p.restitution)
}

/// The linear tangential parameters of `p`.
fn linear_tangential<F: Real>(p: &ss_params<F>) -> Result<TangentialParameters<F>, ParameterError> {
    TangentialParameters::new(p.tangential_stiffness, p.dashpot_ratio, p.friction)
}

/// Hertz's normal law of `p`, checked for its declared impact.
fn hertz_normal<F: Real>(p: &ss_params<F>) -> Result<Hertz<F>, ParameterError> {
    let largest = HertzImpact {
        speed: p.largest_impact_speed,
        effective_radius: p.largest_effective_radius,
    };
    Hertz::new(p.effective_modulus, p.restitution, largest)
}

/// Mindlin's tangential parameters of `p`.
fn mindlin<F: Real>(p: &ss_params<F>) -> Result<MindlinParameters<F>, ParameterError> {
    MindlinParameters::new(p.effective_shear_modulus, p.dashpot_ratio, p.friction)
}
