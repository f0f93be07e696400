//! [proptest](https://docs.rs/proptest) strategies for the kernel's inputs (feature
//! `proptest`): physical collisions, spheres, walls, every slot's parameters, and arbitrary bit
//! patterns, in `f32` and `f64`. The kernel's own property tests draw from these; an engine
//! author draws from them to fuzz a loop around the kernel, and asserts with
//! [`checks`](crate::checks).
//!
//! Physical cases are drawn in `f64` and rounded to the precision under test, so `f32` and `f64`
//! meet the same situations. Every range is stated where it is drawn.
//!
//! ```
//! use proptest::prelude::*;
//! use soft_sphere::strategies::collision;
//!
//! proptest!(|(c in collision())| {
//!     let (i, j) = c.pair::<f32>();
//!     prop_assert!(i.radius > 0.0 && j.radius > 0.0);
//! });
//! ```

use core::ops::RangeInclusive;

use proptest::prelude::*;

use crate::law::normal::{Hertz, HertzImpact, LinearSpringDashpot};
use crate::law::rolling::{ConstantRolling, ElasticPlasticRolling};
use crate::law::tangential::{MindlinParameters, TangentialParameters};
use crate::value::body::Sphere;
use crate::value::float::Float;
use crate::value::vector::Vec3;
use crate::value::wall::Wall;

/// A value drawn log-uniformly from `[low, high]` (both positive).
pub fn log_uniform(low: f64, high: f64) -> impl Strategy<Value = f64> + Clone {
    (libm::log(low)..=libm::log(high)).prop_map(libm::exp)
}

/// A unit vector, uniform on the sphere.
pub fn unit_vector() -> impl Strategy<Value = [f64; 3]> + Clone {
    (-1.0f64..=1.0, 0.0..2.0 * core::f64::consts::PI).prop_map(|(z, phi)| {
        let s = libm::sqrt(1.0 - z * z);
        [s * libm::cos(phi), s * libm::sin(phi), z]
    })
}

/// The coefficients of one collision's law, as ratios, so that one case suits every slot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coefficients {
    /// Normal restitution, in `[0, 1]`.
    pub restitution: f64,
    /// Coulomb friction, in `[0, 2]`.
    pub friction: f64,
    /// `k_t / k_n` (for Mindlin, `4 G* / E*`), in `[0.1, 2]` (2/7 to 1 is the physical range).
    pub stiffness_ratio: f64,
    /// `eta_t / eta_n`, in `[0, 1]`.
    pub dashpot_ratio: f64,
    /// Peak overlap of a head-on impact at the approach speed as a fraction of the smaller
    /// radius, in `[1e-3, 0.05]`: sets the normal stiffness, so that every case is a soft-sphere
    /// contact of sensible depth ([`Collision::normal_stiffness`]).
    pub overlap_fraction: f64,
}

/// Any coefficients in range: `e` of 0 and 1 and `mu` of 0 drawn often.
pub fn coefficients() -> impl Strategy<Value = Coefficients> + Clone {
    (
        prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64],
        prop_oneof![Just(0.0), 0.0..=2.0f64],
        log_uniform(0.1, 2.0),
        0.0..=1.0f64,
        log_uniform(1e-3, 0.05),
    )
        .prop_map(
            |(restitution, friction, stiffness_ratio, dashpot_ratio, overlap_fraction)| {
                Coefficients {
                    restitution,
                    friction,
                    stiffness_ratio,
                    dashpot_ratio,
                    overlap_fraction,
                }
            },
        )
}

/// One sphere's size, density and motion, before it is placed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Radius (m), 1e-4 to 1e-1, log-uniform.
    pub radius: f64,
    /// Density (kg/m3), 500 to 8000.
    pub density: f64,
    /// Velocity (m/s), each component within +-2.
    pub velocity: [f64; 3],
    /// Angular velocity times radius (m/s), each component within +-2.
    pub spin_speed: [f64; 3],
}

fn triple() -> impl Strategy<Value = [f64; 3]> + Clone {
    let component = -2.0..=2.0f64;
    [component.clone(), component.clone(), component]
}

/// A body of any size, density, velocity and spin in range.
pub fn body() -> impl Strategy<Value = Body> + Clone {
    (
        log_uniform(1e-4, 1e-1),
        500.0..=8000.0f64,
        triple(),
        triple(),
    )
        .prop_map(|(radius, density, velocity, spin_speed)| Body {
            radius,
            density,
            velocity,
            spin_speed,
        })
}

/// A binary collision: two spheres (or a sphere and a wall) just touching along `normal`, the
/// second approaching the first at `speed` and `angle_deg` from the normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collision {
    /// The first sphere (the one at the origin).
    pub first: Body,
    /// The second sphere (or the sphere, against a wall); its radius is within a factor 10 of
    /// the first's.
    pub second: Body,
    /// Unit normal from the first centre to the second (the wall's normal).
    pub normal: [f64; 3],
    /// Approach speed (m/s), 0.05 to 5 ([`collision`]).
    pub speed: f64,
    /// Angle of the approach from the normal (deg), 0 to 89 ([`collision`]).
    pub angle_deg: f64,
    /// Direction of the tangential part (any vector; its normal part is removed).
    pub tangent_hint: [f64; 3],
    /// The law's coefficients.
    pub material: Coefficients,
}

/// Any collision in range: head-on (0 deg), oblique and grazing (85-89 deg) approaches drawn
/// often.
pub fn collision() -> impl Strategy<Value = Collision> + Clone {
    collision_with(
        prop_oneof![Just(0.0), 0.0..=89.0f64, 85.0..=89.0f64],
        log_uniform(0.05, 5.0),
    )
}

/// Collisions at angles (deg from the normal, within `[0, 90)`) and speeds (m/s, positive)
/// drawn uniformly from the given ranges.
pub fn impact(
    angles_deg: RangeInclusive<f64>,
    speeds: RangeInclusive<f64>,
) -> impl Strategy<Value = Collision> + Clone {
    collision_with(angles_deg, speeds)
}

fn collision_with(
    angle: impl Strategy<Value = f64> + Clone,
    speed: impl Strategy<Value = f64> + Clone,
) -> impl Strategy<Value = Collision> + Clone {
    (
        body(),
        (body(), log_uniform(0.1, 10.0)),
        unit_vector(),
        speed,
        angle,
        unit_vector(),
        coefficients(),
    )
        .prop_map(
            |(first, (mut second, ratio), normal, speed, angle_deg, tangent_hint, material)| {
                second.radius = first.radius * ratio;
                Collision {
                    first,
                    second,
                    normal,
                    speed,
                    angle_deg,
                    tangent_hint,
                    material,
                }
            },
        )
}

fn add_scaled(a: [f64; 3], b: [f64; 3], scale: f64) -> [f64; 3] {
    [
        a[0] + scale * b[0],
        a[1] + scale * b[1],
        a[2] + scale * b[2],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn rounded<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::new(F::from_f64(a[0]), F::from_f64(a[1]), F::from_f64(a[2]))
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let length = libm::sqrt(dot(a, a));
    a.map(|x| x / length)
}

impl Collision {
    /// Unit tangent of the approach, normal to `normal`.
    fn tangent(&self) -> [f64; 3] {
        let t = add_scaled(
            self.tangent_hint,
            self.normal,
            -dot(self.tangent_hint, self.normal),
        );
        if dot(t, t) < 1e-12 {
            // Hint parallel to the normal: any perpendicular will do.
            let other = if self.normal[0].abs() < 0.9 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            return unit(add_scaled(other, self.normal, -dot(other, self.normal)));
        }
        unit(t)
    }

    /// Relative velocity of the second sphere against the first: approaching along `-normal`.
    fn approach(&self) -> [f64; 3] {
        let theta = self.angle_deg.to_radians();
        let along = add_scaled([0.0; 3], self.normal, -self.speed * libm::cos(theta));
        add_scaled(along, self.tangent(), self.speed * libm::sin(theta))
    }

    /// The two solid spheres, just touching, the second approaching the first.
    pub fn pair<F: Float>(&self) -> (Sphere<F>, Sphere<F>) {
        let (a, b) = (self.first, self.second);
        let mut i = Sphere::solid(Vec3::ZERO, F::from_f64(a.radius), F::from_f64(a.density));
        i.velocity = rounded(a.velocity);
        i.angular_velocity = rounded(a.spin_speed.map(|s| s / a.radius));
        let centre = self.normal.map(|n| n * (a.radius + b.radius));
        let mut j = Sphere::solid(
            rounded(centre),
            F::from_f64(b.radius),
            F::from_f64(b.density),
        );
        j.velocity = rounded(add_scaled(a.velocity, self.approach(), 1.0));
        j.angular_velocity = rounded(b.spin_speed.map(|s| s / b.radius));
        (i, j)
    }

    /// A still wall through the origin with normal `normal`, and the second sphere just
    /// touching it, approaching.
    pub fn wall<F: Float>(&self) -> (Wall<F>, Sphere<F>) {
        let b = self.second;
        let wall = Wall::new(Vec3::ZERO, rounded(self.normal)).expect("a unit normal is valid");
        let centre = self.normal.map(|n| n * b.radius);
        let mut sphere = Sphere::solid(
            rounded(centre),
            F::from_f64(b.radius),
            F::from_f64(b.density),
        );
        sphere.velocity = rounded(self.approach());
        sphere.angular_velocity = rounded(b.spin_speed.map(|s| s / b.radius));
        (wall, sphere)
    }

    /// `k_n` giving the head-on peak overlap `overlap_fraction` of the smaller radius for an
    /// undamped impact at `speed` with effective mass `m*`: `k_n = m* (v / delta)^2`.
    pub fn normal_stiffness(&self, effective_mass: f64) -> f64 {
        let radius = self.first.radius.min(self.second.radius);
        let overlap = self.material.overlap_fraction * radius;
        let rate = self.speed / overlap;
        effective_mass * rate * rate
    }

    /// The pair moved together by `depth` of the smaller radius along the normal: a contact
    /// already under way.
    pub fn overlapping<F: Float>(&self, depth: f64) -> (Sphere<F>, Sphere<F>) {
        let (i, mut j) = self.pair::<F>();
        let shift = depth * self.first.radius.min(self.second.radius);
        j.position = rounded(add_scaled(
            self.normal
                .map(|n| n * (self.first.radius + self.second.radius)),
            self.normal,
            -shift,
        ));
        (i, j)
    }
}

/// Two spheres in contact, overlapping by 1e-4 to 0.05 of the smaller radius, moving as a
/// [`collision`]'s.
pub fn touching_pair<F: Float>() -> impl Strategy<Value = (Sphere<F>, Sphere<F>)> + Clone {
    (collision(), log_uniform(1e-4, 0.05)).prop_map(|(c, depth)| c.overlapping(depth))
}

/// Two spheres barely in contact, overlapping by 1e-9 to 1e-6 of the smaller radius: where the
/// overlap is a difference of nearly equal numbers, the hardest case for rounding (and in `f32`
/// often no overlap at all).
pub fn grazing_pair<F: Float>() -> impl Strategy<Value = (Sphere<F>, Sphere<F>)> + Clone {
    (collision(), log_uniform(1e-9, 1e-6)).prop_map(|(c, depth)| c.overlapping(depth))
}

/// A solid sphere: position within +-1 m, a [`body`]'s radius, density and motion.
pub fn sphere<F: Float>() -> impl Strategy<Value = Sphere<F>> + Clone {
    (body(), triple()).prop_map(|(b, at)| {
        let mut s = Sphere::solid(
            rounded(at.map(|x| x / 2.0)),
            F::from_f64(b.radius),
            F::from_f64(b.density),
        );
        s.velocity = rounded(b.velocity);
        s.angular_velocity = rounded(b.spin_speed.map(|w| w / b.radius));
        s
    })
}

/// A plane wall through a point within +-1 m with any unit normal, or a cylinder of radius 0.05
/// to 2 m about an axis through such a point; moving at up to 2 m/s per component, turning at up
/// to 20 rad/s about its axis.
pub fn wall<F: Float>() -> impl Strategy<Value = Wall<F>> + Clone {
    let shape = prop_oneof![Just(None), log_uniform(0.05, 2.0).prop_map(Some)];
    let motion = (triple(), prop_oneof![Just(0.0), -20.0..20.0]);
    (triple(), unit_vector(), shape, motion).prop_filter_map(
        "a valid wall",
        |(at, direction, shape, (velocity, spin))| {
            let at = rounded(at.map(|x| x / 2.0));
            let direction = rounded(direction);
            match shape {
                None => Wall::new(at, direction),
                Some(radius) => Wall::cylinder(at, direction, F::from_f64(radius)),
            }
            .and_then(|wall| wall.with_velocity(rounded(velocity)))
            .and_then(|wall| wall.with_spin(F::from_f64(spin)))
            .ok()
        },
    )
}

/// The linear normal slot: `k_n` 10 to 1e7 N/m (log-uniform), `e` in `[0, 1]`.
pub fn linear_spring_dashpot<F: Float>() -> impl Strategy<Value = LinearSpringDashpot<F>> + Clone {
    (log_uniform(10.0, 1e7), prop_oneof![Just(1.0), 0.0..=1.0f64])
        .prop_filter_map("a valid linear law", |(k, e)| {
            LinearSpringDashpot::new(F::from_f64(k), F::from_f64(e)).ok()
        })
}

/// The Hertz normal slot: `E*` 1e6 to 1e12 Pa, `e` in `[0, 1]`, declared for impacts up to
/// 0.05 to 5 m/s and `R*` 1e-4 to 0.1 m (all log-uniform but `e`).
pub fn hertz<F: Float>() -> impl Strategy<Value = Hertz<F>> + Clone {
    (
        log_uniform(1e6, 1e12),
        prop_oneof![Just(1.0), 0.0..=1.0f64],
        log_uniform(0.05, 5.0),
        log_uniform(1e-4, 0.1),
    )
        .prop_filter_map("a valid Hertz law", |(modulus, e, speed, radius)| {
            let largest = HertzImpact {
                speed: F::from_f64(speed),
                effective_radius: F::from_f64(radius),
            };
            Hertz::new(F::from_f64(modulus), F::from_f64(e), largest).ok()
        })
}

/// The linear tangential slots' parameters: `k_t` 10 to 1e7 N/m, dashpot ratio in `[0, 1]`,
/// `mu` in `[0, 2]` (0 drawn often).
pub fn tangential_parameters<F: Float>() -> impl Strategy<Value = TangentialParameters<F>> + Clone {
    (
        log_uniform(10.0, 1e7),
        0.0..=1.0f64,
        prop_oneof![Just(0.0), 0.0..=2.0f64],
    )
        .prop_filter_map("valid parameters", |(k, r, mu)| {
            TangentialParameters::new(F::from_f64(k), F::from_f64(r), F::from_f64(mu)).ok()
        })
}

/// The Mindlin slots' parameters: `G*` 1e5 to 1e11 Pa, dashpot ratio in `[0, 1]`, `mu` in
/// `[0, 2]` (0 drawn often).
pub fn mindlin_parameters<F: Float>() -> impl Strategy<Value = MindlinParameters<F>> + Clone {
    (
        log_uniform(1e5, 1e11),
        0.0..=1.0f64,
        prop_oneof![Just(0.0), 0.0..=2.0f64],
    )
        .prop_filter_map("valid parameters", |(g, r, mu)| {
            MindlinParameters::new(F::from_f64(g), F::from_f64(r), F::from_f64(mu)).ok()
        })
}

/// The constant rolling torque: `mu_r` in `[0, 0.5]`.
pub fn constant_rolling<F: Float>() -> impl Strategy<Value = ConstantRolling<F>> + Clone {
    (0.0..=0.5f64).prop_filter_map("a valid rolling friction", |mu| {
        ConstantRolling::new(F::from_f64(mu)).ok()
    })
}

/// The elastic-plastic rolling spring, checked for `smallest_inertia` (kg m^2): `mu_r` in
/// `[0, 0.5]`, `k_r` 1e-9 to 1 N m/rad, `eta_r` 0 or up to 1e-6 N m s/rad.
pub fn elastic_plastic_rolling<F: Float>(
    smallest_inertia: F,
) -> impl Strategy<Value = ElasticPlasticRolling<F>> + Clone {
    (
        0.0..=0.5f64,
        log_uniform(1e-9, 1.0),
        prop_oneof![Just(0.0), log_uniform(1e-12, 1e-6)],
    )
        .prop_filter_map("a valid rolling spring", move |(mu, k, eta)| {
            ElasticPlasticRolling::new(
                F::from_f64(mu),
                F::from_f64(k),
                F::from_f64(eta),
                smallest_inertia,
            )
            .ok()
        })
}

/// Any bit pattern of `F`, with NaN, the infinities, both zeros, the extremes, the smallest
/// normal and a subnormal drawn often (7 draws in 10), and ordinary magnitudes (within +-1e3,
/// and 1e-6 to 0.1) so that some cases touch: what an engine's corrupted memory could hand the
/// kernel.
pub fn any_bits<F: Float>() -> impl Strategy<Value = F> + Clone {
    let special = prop_oneof![
        Just(F::from_f64(f64::NAN)),
        Just(F::INFINITY),
        Just(F::from_f64(f64::NEG_INFINITY)),
        Just(F::ZERO),
        Just(F::from_f64(-0.0)),
        Just(F::MIN_POSITIVE),
        Just(F::MIN_POSITIVE * F::HALF),
        Just(F::MAX),
    ];
    prop_oneof![
        1 => any::<u64>().prop_map(F::from_bits_u64),
        7 => special,
        1 => (-1e3..1e3f64).prop_map(F::from_f64),
        1 => (1e-6..1e-1f64).prop_map(F::from_f64),
    ]
}

/// A vector of [`any_bits`].
pub fn any_vec3<F: Float>() -> impl Strategy<Value = Vec3<F>> + Clone {
    (any_bits::<F>(), any_bits::<F>(), any_bits::<F>()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// A sphere whose every field is [`any_bits`].
pub fn any_sphere<F: Float>() -> impl Strategy<Value = Sphere<F>> + Clone {
    (
        any_vec3::<F>(),
        any_vec3::<F>(),
        any_vec3::<F>(),
        any_bits::<F>(),
        any_bits::<F>(),
    )
        .prop_map(
            |(position, velocity, angular_velocity, radius, mass)| Sphere {
                position,
                velocity,
                angular_velocity,
                radius,
                mass,
            },
        )
}
