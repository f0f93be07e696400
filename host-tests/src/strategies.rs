//! Bounded physical input strategies for the property tests, as
//! free functions, and the property-test configuration.
//!
//! Cases are generated in `f64` and converted to the precision under test, so that f32 and f64
//! see the same physical situations.

use std::f64::consts::PI;

use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence};
use soft_sphere::{Float, Sphere, Vec3, Wall};

use crate::triple::{add_scaled, dot, to_vec3};

/// Cases per property: `PROPTEST_CASES` when set (the slow configuration raises it), else 64.
/// Failures are kept beside the test file (`tests/<name>.proptest-regressions`, committed) and
/// replayed first on every run.
pub fn config() -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(64);
    Config {
        cases,
        // f32 cases whose steps the precision cannot resolve are rejected (see the properties).
        max_global_rejects: 4 * cases,
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..Config::default()
    }
}

/// A value drawn log-uniformly from `[low, high]`.
pub fn log_uniform(low: f64, high: f64) -> impl Strategy<Value = f64> {
    (low.ln()..=high.ln()).prop_map(f64::exp)
}

/// A unit vector, uniform on the sphere.
pub fn unit_vector() -> impl Strategy<Value = [f64; 3]> {
    (-1.0f64..=1.0, 0.0..2.0 * PI).prop_map(|(z, phi)| {
        let s = (1.0 - z * z).sqrt();
        [s * phi.cos(), s * phi.sin(), z]
    })
}

/// The material and law parameters of one collision.
#[derive(Clone, Copy, Debug)]
pub struct Material {
    /// Normal restitution, in `[0, 1]`.
    pub restitution: f64,
    /// Coulomb friction, in `[0, 2]`.
    pub friction: f64,
    /// `k_t / k_n`, in `[0.1, 2]` (2/7 to 1 is the physical range; the stress tests go from 0.01
    /// to 10).
    pub stiffness_ratio: f64,
    /// `eta_t / eta_n`, in `[0, 1]`.
    pub dashpot_ratio: f64,
    /// Peak overlap of a head-on impact at the approach speed as a fraction of the smaller radius,
    /// in `[1e-3, 0.05]`: sets `k_n`, so that every case is a soft-sphere contact of sensible depth.
    pub overlap_fraction: f64,
}

/// Any material: `e` in `[0, 1]` (both ends included often), `mu` in `[0, 2]`.
pub fn material() -> impl Strategy<Value = Material> {
    (
        prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64],
        prop_oneof![Just(0.0), 0.0..=2.0f64],
        log_uniform(0.1, 2.0),
        0.0..=1.0f64,
        log_uniform(1e-3, 0.05),
    )
        .prop_map(
            |(restitution, friction, stiffness_ratio, dashpot_ratio, overlap_fraction)| Material {
                restitution,
                friction,
                stiffness_ratio,
                dashpot_ratio,
                overlap_fraction,
            },
        )
}

/// One sphere's size, density and motion, before placement.
#[derive(Clone, Copy, Debug)]
pub struct Body {
    /// Radius (m), 1e-4 to 1e-1.
    pub radius: f64,
    /// Density (kg/m3), 500 to 8000.
    pub density: f64,
    /// Velocity (m/s), each component within +-2.
    pub velocity: [f64; 3],
    /// Angular velocity times radius (m/s), each component within +-2.
    pub spin_speed: [f64; 3],
}

fn component() -> impl Strategy<Value = f64> {
    -2.0..=2.0f64
}

fn triple() -> impl Strategy<Value = [f64; 3]> {
    [component(), component(), component()]
}

/// A sphere of any size, density, velocity and spin in range.
pub fn body() -> impl Strategy<Value = Body> {
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
#[derive(Clone, Copy, Debug)]
pub struct Collision {
    /// The first sphere (the one at the origin).
    pub first: Body,
    /// The second sphere (or the sphere, against a wall).
    pub second: Body,
    /// Unit normal from the first centre to the second (the wall's normal).
    pub normal: [f64; 3],
    /// Approach speed (m/s), 0.05 to 5.
    pub speed: f64,
    /// Angle of the approach from the normal (deg), 0 to 89.
    pub angle_deg: f64,
    /// Direction of the tangential part (any vector; its normal part is removed).
    pub tangent_hint: [f64; 3],
    /// Material and law.
    pub material: Material,
}

/// Any collision in range; the second radius is within a factor 10 of the first.
pub fn collision() -> impl Strategy<Value = Collision> {
    (
        body(),
        (body(), log_uniform(0.1, 10.0)).prop_map(|(mut b, ratio)| {
            b.radius = 0.0;
            (b, ratio)
        }),
        unit_vector(),
        log_uniform(0.05, 5.0),
        prop_oneof![Just(0.0), 0.0..=89.0f64, 85.0..=89.0f64],
        unit_vector(),
        material(),
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

impl Collision {
    /// Unit tangent of the approach, normal to `normal`.
    fn tangent(&self) -> [f64; 3] {
        let t = add_scaled(
            self.tangent_hint,
            self.normal,
            -dot(self.tangent_hint, self.normal),
        );
        let length = dot(t, t).sqrt();
        if length < 1e-6 {
            // Hint parallel to the normal: any perpendicular will do.
            let other = if self.normal[0].abs() < 0.9 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            let t = add_scaled(other, self.normal, -dot(other, self.normal));
            let length = dot(t, t).sqrt();
            return [t[0] / length, t[1] / length, t[2] / length];
        }
        [t[0] / length, t[1] / length, t[2] / length]
    }

    /// Relative velocity of the second sphere against the first: approaching along `-normal`.
    fn approach(&self) -> [f64; 3] {
        let theta = self.angle_deg.to_radians();
        let along = add_scaled([0.0; 3], self.normal, -self.speed * theta.cos());
        add_scaled(along, self.tangent(), self.speed * theta.sin())
    }

    /// The two spheres, just touching, the second approaching the first.
    pub fn pair<F: Float>(&self) -> (Sphere<F>, Sphere<F>) {
        let (a, b) = (self.first, self.second);
        let mut i = Sphere::solid(Vec3::ZERO, F::from_f64(a.radius), F::from_f64(a.density));
        i.velocity = to_vec3(a.velocity);
        i.angular_velocity = to_vec3(a.spin_speed.map(|s| s / a.radius));
        let centre = self.normal.map(|n| n * (a.radius + b.radius));
        let mut j = Sphere::solid(
            to_vec3(centre),
            F::from_f64(b.radius),
            F::from_f64(b.density),
        );
        j.velocity = to_vec3(add_scaled(a.velocity, self.approach(), 1.0));
        j.angular_velocity = to_vec3(b.spin_speed.map(|s| s / b.radius));
        (i, j)
    }

    /// A wall through the origin with normal `normal`, and the second sphere just touching it,
    /// approaching.
    pub fn wall<F: Float>(&self) -> (Wall<F>, Sphere<F>) {
        let b = self.second;
        let wall = Wall::new(Vec3::ZERO, to_vec3(self.normal)).expect("a unit normal");
        let centre = self.normal.map(|n| n * b.radius);
        let mut sphere = Sphere::solid(
            to_vec3(centre),
            F::from_f64(b.radius),
            F::from_f64(b.density),
        );
        sphere.velocity = to_vec3(self.approach());
        sphere.angular_velocity = to_vec3(b.spin_speed.map(|s| s / b.radius));
        (wall, sphere)
    }

    /// `k_n` giving the head-on peak overlap `overlap_fraction` of the smaller radius for an
    /// undamped impact at `speed` with effective mass `m_star`: `k_n = m* (v / delta)^2`.
    pub fn normal_stiffness(&self, effective_mass: f64) -> f64 {
        let radius = self.first.radius.min(self.second.radius);
        let overlap = self.material.overlap_fraction * radius;
        effective_mass * (self.speed / overlap).powi(2)
    }
}
