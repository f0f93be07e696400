//! The law handles: a shared, read-only `ss_law_*` (a validated law and its checked step) and a
//! per-thread `ss_bound_law_*` made from it, with the single-contact calls on each.

use crate::registry::{AnyBound, AnyLaw, Family, family};
use crate::state::*;
use crate::*;
use soft_sphere::motion::advance_solid_sphere;
use soft_sphere::prelude::{
    CheckedSphere, ContactError, ContactLaw, Frictionless, Hertz, HertzImpact, Interaction,
    LinearSpringDashpot, Material, Sphere, TimeStep, Vec3, Wall,
};

/// A validated contact law and its checked time step (opaque to C).
#[derive(Debug)]
pub struct ss_law<F: Real> {
    pub(crate) law: AnyLaw<F>,
    pub(crate) time_step: TimeStep<F>,
}

pub(crate) fn build_law<F: Real>(p: &ss_params<F>) -> Result<ss_law<F>, i32> {
    checked_law(p).map_err(|(code, _)| code)
}

/// The law `*p` describes, or the error code and the `SS_PARAMETER_*` it is about.
pub(crate) fn checked_law<F: Real>(p: &ss_params<F>) -> Result<ss_law<F>, (i32, i32)> {
    let Some(law) = AnyLaw::new(p) else {
        return Err((SS_ERR_UNKNOWN_MODEL, SS_PARAMETER_MODEL));
    };
    let refused = |e| (parameter_code(e), rejected_parameter(e));
    let law = law.map_err(refused)?;
    let time_step = law.time_step(p).map_err(refused)?;
    Ok(ss_law { law, time_step })
}

/// The stability limit of the law `*params` describes, for its smallest effective mass: what a
/// host reports when `SS_ERR_UNSTABLE_TIME_STEP` refuses its step.
pub(crate) fn limit_of<F: Real>(p: &ss_params<F>) -> Result<F, i32> {
    let probe = ss_params {
        time_step: F::MIN_POSITIVE,
        ..*p
    };
    let law = build_law(&probe)?;
    let m = p.smallest_effective_mass;
    Ok(each_law!(law.law, AnyLaw, l => l.critical_time_step(m)))
}

/// # Safety
/// As the exported constructors.
pub(crate) unsafe fn law_new<F: Real>(
    params: *const ss_params<F>,
    out: *mut *mut ss_law<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(p), false) = (unsafe { params.as_ref() }, out.is_null()) else {
        return SS_ERR_NULL;
    };
    match build_law(p) {
        Ok(law) => {
            // SAFETY: out was checked non-null.
            unsafe { *out = Box::into_raw(Box::new(law)) };
            SS_OK
        }
        Err(code) => code,
    }
}

/// # Safety
/// As the exported destructors.
pub(crate) unsafe fn law_free<F: Real>(law: *mut ss_law<F>) {
    if !law.is_null() {
        // SAFETY: the handle came from Box::into_raw in law_new.
        drop(unsafe { Box::from_raw(law) });
    }
}

/// Evaluates `$call` on the law's state loaded from `*$state` (bound to `$s`); on success stores
/// the state back and writes `*$out`, on error leaves both as they were and gives the error's
/// code. A macro, not a function taking a closure: a closure is not inlined across codegen units,
/// and the call's result would then pass through memory.
macro_rules! evaluated {
    ($state:expr, $out:expr, $s:ident => $call:expr) => {{
        let mut $s = Stored::load($state);
        let result = $call;
        finish(result, &$s, $state, $out)
    }};
}

#[inline(always)]
pub(crate) fn finish<F: Real, S: Stored<F>>(
    result: Result<Interaction<F>, ContactError>,
    stored: &S,
    state: &mut ss_state<F>,
    out: &mut ss_forces<F>,
) -> i32 {
    match result {
        Ok(interaction) => {
            stored.store(state);
            *out = forces_of(interaction);
            SS_OK
        }
        Err(e) => contact_code(e),
    }
}

#[inline(always)]
pub(crate) fn forces_of<F: Real>(interaction: Interaction<F>) -> ss_forces<F> {
    match interaction {
        Interaction::Apart => ss_forces {
            touching: 0,
            sliding: 0,
            overlap: F::ZERO,
            normal_force: F::ZERO,
            force_on_j: Vec3::ZERO.into(),
            torque_on_i: Vec3::ZERO.into(),
            torque_on_j: Vec3::ZERO.into(),
        },
        Interaction::Touching(c) => ss_forces {
            touching: 1,
            sliding: i32::from(c.sliding),
            overlap: c.overlap,
            normal_force: c.normal_force,
            force_on_j: c.force_on_j().into(),
            torque_on_i: c.torque_on_i.into(),
            torque_on_j: c.torque_on_j.into(),
        },
    }
}

/// The kernel treats the sphere as body i against a wall: the C ABI reports its force as the one
/// on j, so that `force_on_j` and `torque_on_j` are always what the sphere receives.
#[inline(always)]
pub(crate) fn sphere_as_j<F: Real>(interaction: Interaction<F>) -> Interaction<F> {
    match interaction {
        Interaction::Touching(mut c) => {
            c.normal = -c.normal;
            c.tangential_force = -c.tangential_force;
            core::mem::swap(&mut c.torque_on_i, &mut c.torque_on_j);
            Interaction::Touching(c)
        }
        apart => apart,
    }
}

/// The kernel's wall for `*wall`, checked: a plane for a zero radius (of either sign), a
/// cylinder for a positive one; any other radius is refused.
#[inline(always)]
pub(crate) fn wall_of<F: Real>(wall: &ss_wall<F>) -> Result<Wall<F>, i32> {
    let (point, direction) = (wall.point.into(), wall.direction.into());
    if wall.radius == F::ZERO {
        Wall::new(point, direction)
    } else {
        Wall::cylinder(point, direction, wall.radius)
    }
    .and_then(|w| w.with_velocity(wall.velocity.into()))
    .and_then(|w| w.with_spin(wall.spin))
    .map_err(|_| SS_ERR_BAD_WALL)
}

/// # Safety
/// As the exported sphere-sphere calls.
pub(crate) unsafe fn pair<F: Real>(
    law: *const ss_law<F>,
    i: *const ss_sphere<F>,
    j: *const ss_sphere<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), Some(i), Some(j), Some(state), Some(out)) = (unsafe {
        (
            law.as_ref(),
            i.as_ref(),
            j.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let (i, j): (Sphere<F>, Sphere<F>) = ((*i).into(), (*j).into());
    let dt = law.time_step;
    each_law!(&law.law, AnyLaw, l => evaluated!(state, out, s => l.sphere_sphere(&i, &j, &mut s, dt)))
}

/// # Safety
/// As the exported sphere-wall calls.
pub(crate) unsafe fn on_wall<F: Real>(
    law: *const ss_law<F>,
    sphere: *const ss_sphere<F>,
    wall: *const ss_wall<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), Some(sphere), Some(wall), Some(state), Some(out)) = (unsafe {
        (
            law.as_ref(),
            sphere.as_ref(),
            wall.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let checked = match wall_of(wall) {
        Ok(checked) => checked,
        Err(code) => return code,
    };
    let sphere: Sphere<F> = (*sphere).into();
    let dt = law.time_step;
    each_law!(&law.law, AnyLaw, l => evaluated!(state, out, s => {
        l.sphere_wall(&sphere, &checked, &mut s, dt).map(sphere_as_j)
    }))
}

/// A law bound to its time step, for one thread's run of calls (opaque to C). It remembers the
/// normal oscillator of the last pair of masses and the last wall it checked, so a host that
/// calls it over a neighbour list derives each once; the results are the same bits as the
/// `ss_law` entry points'.
#[derive(Debug)]
pub struct ss_bound_law<F: Real> {
    pub(crate) bound: AnyBound<F>,
    /// The last wall that passed its checks, as given and as checked.
    pub(crate) wall: Option<(ss_wall<F>, Wall<F>)>,
}

/// The same bits, so that a memo keyed on them gives what a fresh check would (-0.0 and 0.0
/// differ; a NaN never passes the check, so it is never a key).
pub(crate) fn same_wall<F: Real>(a: &ss_wall<F>, b: &ss_wall<F>) -> bool {
    let bits = |w: &ss_wall<F>| {
        let vectors = [w.point, w.direction, w.velocity].map(|v| [v.x, v.y, v.z]);
        let [p, d, v] = vectors.map(|v| v.map(|x| x.to_f64().to_bits()));
        (p, d, v, [w.radius, w.spin].map(|x| x.to_f64().to_bits()))
    };
    bits(a) == bits(b)
}

/// # Safety
/// As the exported bound-law constructors.
pub(crate) unsafe fn bound_new<F: Real>(
    law: *const ss_law<F>,
    out: *mut *mut ss_bound_law<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), false) = (unsafe { law.as_ref() }, out.is_null()) else {
        return SS_ERR_NULL;
    };
    let bound = law.law.at(law.time_step);
    let handle = ss_bound_law { bound, wall: None };
    // SAFETY: out was checked non-null.
    unsafe { *out = Box::into_raw(Box::new(handle)) };
    SS_OK
}

/// # Safety
/// As the exported bound-law destructors.
pub(crate) unsafe fn bound_free<F: Real>(bound: *mut ss_bound_law<F>) {
    if bound.is_null() {
        return;
    }
    // SAFETY: the handle came from Box::into_raw in bound_new.
    drop(unsafe { Box::from_raw(bound) });
}

/// # Safety
/// As the exported bound sphere-sphere calls.
pub(crate) unsafe fn bound_pair<F: Real>(
    bound: *mut ss_bound_law<F>,
    i: *const ss_sphere<F>,
    j: *const ss_sphere<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(bound), Some(i), Some(j), Some(state), Some(out)) = (unsafe {
        (
            bound.as_mut(),
            i.as_ref(),
            j.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    // One sphere at a time: a tuple of two results is copied through memory, a measurable cost
    // per call.
    let i = match CheckedSphere::new((*i).into()) {
        Ok(i) => i,
        Err(e) => return contact_code(e),
    };
    let j = match CheckedSphere::new((*j).into()) {
        Ok(j) => j,
        Err(e) => return contact_code(e),
    };
    each_law!(&mut bound.bound, AnyBound, b => evaluated!(state, out, s => b.sphere_sphere(&i, &j, &mut s)))
}

/// # Safety
/// As the exported bound sphere-wall calls.
pub(crate) unsafe fn bound_wall<F: Real>(
    bound: *mut ss_bound_law<F>,
    sphere: *const ss_sphere<F>,
    wall: *const ss_wall<F>,
    state: *mut ss_state<F>,
    out: *mut ss_forces<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(bound), Some(sphere), Some(wall), Some(state), Some(out)) = (unsafe {
        (
            bound.as_mut(),
            sphere.as_ref(),
            wall.as_ref(),
            state.as_mut(),
            out.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let checked = match bound.wall {
        Some((given, checked)) if same_wall(&given, wall) => checked,
        _ => match wall_of(wall) {
            Ok(checked) => {
                bound.wall = Some((*wall, checked));
                checked
            }
            Err(code) => return code,
        },
    };
    let sphere = match CheckedSphere::new((*sphere).into()) {
        Ok(sphere) => sphere,
        Err(e) => return contact_code(e),
    };
    each_law!(&mut bound.bound, AnyBound, b => evaluated!(state, out, s => {
        b.sphere_wall(&sphere, &checked, &mut s).map(sphere_as_j)
    }))
}

/// # Safety
/// As the exported advance calls.
pub(crate) unsafe fn advance<F: Real>(
    law: *const ss_law<F>,
    sphere: *mut ss_sphere<F>,
    force: ss_vec3<F>,
    torque: ss_vec3<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(law), Some(sphere)) = (unsafe { (law.as_ref(), sphere.as_mut()) }) else {
        return SS_ERR_NULL;
    };
    let mut s: Sphere<F> = (*sphere).into();
    advance_solid_sphere(&mut s, force.into(), torque.into(), law.time_step);
    sphere.position = s.position.into();
    sphere.velocity = s.velocity.into();
    sphere.angular_velocity = s.angular_velocity.into();
    SS_OK
}

/// # Safety
/// As the exported duration calls.
pub(crate) unsafe fn duration<F: Real>(params: *const ss_params<F>, m_star: F, out: *mut F) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(p), Some(out)) = (unsafe { (params.as_ref(), out.as_mut()) }) else {
        return SS_ERR_NULL;
    };
    if !(m_star > F::ZERO && m_star.is_finite()) {
        return SS_ERR_NOT_POSITIVE;
    }
    let duration = match family(p.model) {
        Some(Family::Hertz) => {
            let largest = HertzImpact {
                speed: p.largest_impact_speed,
                effective_radius: p.largest_effective_radius,
            };
            Hertz::new(p.effective_modulus, p.restitution, largest)
                .map(|normal| ContactLaw::new(normal, Frictionless).contact_duration(m_star))
        }
        Some(Family::Linear) => LinearSpringDashpot::new(p.normal_stiffness, p.restitution)
            .map(|normal| ContactLaw::new(normal, Frictionless).contact_duration(m_star)),
        None => return SS_ERR_UNKNOWN_MODEL,
    };
    match duration {
        Ok(duration) => {
            *out = duration;
            SS_OK
        }
        Err(e) => parameter_code(e),
    }
}

/// # Safety
/// As the exported stability-limit calls.
pub(crate) unsafe fn stability_limit<F: Real>(params: *const ss_params<F>, out: *mut F) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(p), Some(out)) = (unsafe { (params.as_ref(), out.as_mut()) }) else {
        return SS_ERR_NULL;
    };
    match limit_of(p) {
        Ok(limit) => {
            *out = limit;
            SS_OK
        }
        Err(code) => code,
    }
}

/// # Safety
/// As the exported moduli calls.
pub(crate) unsafe fn moduli<F: Real>(
    i: *const ss_material<F>,
    j: *const ss_material<F>,
    effective_modulus: *mut F,
    effective_shear_modulus: *mut F,
) -> i32 {
    // SAFETY: null is checked (j may be null: a rigid body); the caller promises validity.
    let (Some(i), j, Some(e), Some(g)) = (unsafe {
        (
            i.as_ref(),
            j.as_ref(),
            effective_modulus.as_mut(),
            effective_shear_modulus.as_mut(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let material = |m: &ss_material<F>| Material::new(m.youngs_modulus, m.poisson_ratio);
    let result = material(i).and_then(|a| match j {
        Some(j) => material(j).map(|b| (a.effective_modulus(&b), a.effective_shear_modulus(&b))),
        None => Ok((a.modulus_against_rigid(), a.shear_modulus_against_rigid())),
    });
    match result {
        Ok((modulus, shear)) => {
            (*e, *g) = (modulus, shear);
            SS_OK
        }
        Err(error) => parameter_code(error),
    }
}

/// Hertz's `E*` and Mindlin's `G*` of a contact between materials `*i` and `*j` (`j` null: a
/// rigid body, such as a wall), for `ss_params_f64`. Returns `SS_OK`, `SS_ERR_NULL`, or the
/// material's error (`SS_ERR_NOT_POSITIVE`, `SS_ERR_NON_FINITE_PARAMETER`,
/// `SS_ERR_POISSON_RATIO`); the outputs are written only on success.
///
/// # Safety
/// Non-null pointers must be valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ss_effective_moduli_f64(
    i: *const ss_material<f64>,
    j: *const ss_material<f64>,
    effective_modulus: *mut f64,
    effective_shear_modulus: *mut f64,
) -> i32 {
    // SAFETY: forwarded.
    unsafe { moduli(i, j, effective_modulus, effective_shear_modulus) }
}

/// As `ss_effective_moduli_f64`, in f32.
///
/// # Safety
/// Non-null pointers must be valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ss_effective_moduli_f32(
    i: *const ss_material<f32>,
    j: *const ss_material<f32>,
    effective_modulus: *mut f32,
    effective_shear_modulus: *mut f32,
) -> i32 {
    // SAFETY: forwarded.
    unsafe { moduli(i, j, effective_modulus, effective_shear_modulus) }
}

/// # Safety
/// As the exported rejected-parameter calls.
pub(crate) unsafe fn rejected<F: Real>(params: *const ss_params<F>) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let Some(p) = (unsafe { params.as_ref() }) else {
        return SS_PARAMETER_NONE;
    };
    match checked_law(p) {
        Ok(_) => SS_PARAMETER_NONE,
        Err((_, parameter)) => parameter,
    }
}
