//! Closed-form results the kernel is checked against. Plain `f64` with `std` math, written from
//! the formulas in docs/physics.md and the cited papers, never calling the kernel.

use std::f64::consts::PI;

/// The linear spring-dashpot's free oscillator for stiffness `k`, restitution `e`, mass `m`:
/// `(w0, beta, wd)`.
pub fn oscillator(stiffness: f64, restitution: f64, mass: f64) -> (f64, f64, f64) {
    let w0 = (stiffness / mass).sqrt();
    let zeta = if restitution == 0.0 {
        1.0
    } else {
        let l = restitution.ln();
        -l / (PI * PI + l * l).sqrt()
    };
    let beta = zeta * w0;
    let wd = (w0 * w0 - beta * beta).max(0.0).sqrt();
    (w0, beta, wd)
}

/// Free contact duration `t_c = pi / wd`.
pub fn contact_duration(stiffness: f64, restitution: f64, mass: f64) -> f64 {
    let (_, _, wd) = oscillator(stiffness, restitution, mass);
    PI / wd
}

/// Maximum overlap of a free impact at speed `v0`: `(v0 / w0) exp(-(beta / wd) atan(wd / beta))`
/// (`v0 / w0` without damping).
pub fn max_overlap(stiffness: f64, restitution: f64, mass: f64, speed: f64) -> f64 {
    let (w0, beta, wd) = oscillator(stiffness, restitution, mass);
    if beta == 0.0 {
        return speed / w0;
    }
    speed / w0 * (-(beta / wd) * (wd / beta).atan()).exp()
}

/// Rebound ratio of an impact whose normal force is clipped at zero (never attractive):
/// the force vanishes at `wd t = 2 atan(wd / beta)`, and the speed then is
/// `v0 exp(-(2 beta / wd) atan(wd / beta))` (Schwager & Poeschel 2007).
pub fn clamped_restitution(restitution: f64) -> f64 {
    if restitution == 1.0 {
        return 1.0;
    }
    if restitution == 0.0 {
        // Critical damping: the force vanishes at t = 2 / beta, with speed v0 e^-2.
        return (-2.0f64).exp();
    }
    // Only the ratio beta / wd = |ln e| / pi matters.
    let ratio = -restitution.ln() / PI;
    (-2.0 * ratio * (1.0 / ratio).atan()).exp()
}

/// Rigid-body outcome of a homogeneous solid sphere hitting a wall at `angle_deg` from the wall
/// normal with restitution `e` and friction `mu`, no initial spin: `(e_t, w R / V)`.
/// Gross sliding when `tan(theta) >= 3.5 mu (1 + e)`; rolling at separation otherwise.
pub fn rigid_body_oblique(angle_deg: f64, restitution: f64, friction: f64) -> (f64, f64) {
    let theta = angle_deg.to_radians();
    let impulse = friction * (1.0 + restitution);
    if theta.tan() >= 3.5 * impulse {
        (1.0 - impulse / theta.tan(), 2.5 * impulse * theta.cos())
    } else {
        (5.0 / 7.0, 5.0 / 7.0 * theta.sin())
    }
}

/// Rolling-onset time of a sphere launched sliding at `u0` without spin on a plate:
/// `2 u0 / (7 mu g)`.
pub fn rolling_onset(initial_speed: f64, friction: f64, gravity: f64) -> f64 {
    2.0 * initial_speed / (7.0 * friction * gravity)
}

/// Contact duration of an impact whose normal force is clipped at zero: the force vanishes at
/// `t_f` (`wd t_f = 2 atan(wd / beta)`), after which the sphere coasts out of the remaining overlap
/// at its speed then, `t_c = t_f + delta(t_f) / |delta'(t_f)|`.
pub fn clamped_contact_duration(stiffness: f64, restitution: f64, mass: f64) -> f64 {
    let (w0, beta, wd) = oscillator(stiffness, restitution, mass);
    if beta == 0.0 {
        return PI / w0;
    }
    if wd == 0.0 {
        // Critical damping: delta = v0 t e^(-beta t), the force vanishes at t = 2 / beta with
        // delta = 2 v0 e^-2 / beta and speed v0 e^-2.
        return 4.0 / beta;
    }
    let t_force_free = 2.0 * (wd / beta).atan() / wd;
    // delta and delta' share the factor (v0 / wd) exp(-beta t), which cancels.
    let phase = wd * t_force_free;
    let overlap = phase.sin();
    let rate = wd * phase.cos() - beta * phase.sin();
    t_force_free + overlap / -rate
}

/// `integral |F_n| dt / (m* v0)` over a free binary impact (the contact ending at `delta = 0`):
/// the normal impulse magnitude a Coulomb limit `mu |F_n|` acts with, dashpot pull included. The
/// signed integral is `1 + e`; the attractive end of the contact adds to the magnitude. Midpoint
/// quadrature of the closed-form force `m* (w0^2 delta + 2 beta delta')` over 200,000 steps.
pub fn normal_impulse_magnitude(restitution: f64) -> f64 {
    // Only the ratio beta / wd matters: take wd = 1.
    let ratio = -restitution.ln() / PI;
    let (beta, wd) = (ratio, 1.0);
    let w0_squared = wd * wd + beta * beta;
    let steps = 200_000;
    let dt = PI / wd / steps as f64;
    (0..steps)
        .map(|k| {
            let t = (k as f64 + 0.5) * dt;
            let decay = (-beta * t).exp();
            let overlap = decay * (wd * t).sin() / wd;
            let rate = decay * ((wd * t).cos() - beta / wd * (wd * t).sin());
            (w0_squared * overlap + 2.0 * beta * rate).abs() * dt
        })
        .sum()
}

/// Cattaneo & Mindlin's tangential contact under a constant normal load `P`, in the kernel's
/// `G*` (`k_t = 8 G* a` when stuck): the displacement at which the whole contact slides,
/// `delta_s = 3 mu P / (16 G* a)`.
pub fn full_slip_displacement(friction: f64, load: f64, shear_modulus: f64, radius: f64) -> f64 {
    3.0 * friction * load / (16.0 * shear_modulus * radius)
}

/// Cattaneo & Mindlin's first loading, `T / (mu P)` at tangential displacement `delta_t`:
/// the inverse of `delta_t = delta_s (1 - (1 - T / (mu P))^(2/3))`, 1 past `delta_s`.
pub fn cattaneo_mindlin(displacement: f64, full_slip: f64) -> f64 {
    let x = (displacement / full_slip).clamp(0.0, 1.0);
    1.0 - (1.0 - x).powf(1.5)
}

/// Mindlin & Deresiewicz's unloading from the turning point `(delta*, T*)` of a first loading,
/// `T / (mu P)` at `delta_t` (Masing's rule: the loading curve, doubled, from the turning point).
pub fn mindlin_deresiewicz_unloading(
    displacement: f64,
    turning_displacement: f64,
    turning_force: f64,
    full_slip: f64,
) -> f64 {
    turning_force - 2.0 * cattaneo_mindlin((turning_displacement - displacement) / 2.0, full_slip)
}

/// Energy dissipated per tangential cycle between `+-T*` under a constant normal load, over
/// `mu P delta_s`: with `tau = T* / (mu P)`,
/// `(24/5) (1 - (1 - tau)^(5/3)) - 4 tau (1 + (1 - tau)^(2/3))` (Mindlin & Deresiewicz 1953;
/// Johnson, Contact Mechanics, eq. 7.60, in the kernel's `G*`).
pub fn cycle_dissipation(amplitude: f64) -> f64 {
    let rest = 1.0 - amplitude;
    24.0 / 5.0 * (1.0 - rest.powf(5.0 / 3.0)) - 4.0 * amplitude * (1.0 + rest.powf(2.0 / 3.0))
}
