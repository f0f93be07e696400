//! Many pairs per call over a host's arrays (structure of arrays): the arrays, their
//! reading and writing, and the pairs through the kernel one at a time.

use crate::real::Real;
use crate::registry::AnyBound;
use soft_sphere::prelude::{
    BoundLaw, CheckedSphere, ContactError, Float, Interaction, Law, Sphere, Vec3,
};

use crate::*;

/// Spheres as arrays, one pointer per field (structure of arrays): sphere `k` is element `k` of
/// every array. Every pointer must be valid for the call's `count` elements.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_sphere_arrays<F> {
    /// Centre x (m).
    pub position_x: *const F,
    /// Centre y (m).
    pub position_y: *const F,
    /// Centre z (m).
    pub position_z: *const F,
    /// Velocity x (m/s).
    pub velocity_x: *const F,
    /// Velocity y (m/s).
    pub velocity_y: *const F,
    /// Velocity z (m/s).
    pub velocity_z: *const F,
    /// Angular velocity x (rad/s).
    pub angular_velocity_x: *const F,
    /// Angular velocity y (rad/s).
    pub angular_velocity_y: *const F,
    /// Angular velocity z (rad/s).
    pub angular_velocity_z: *const F,
    /// Radius (m).
    pub radius: *const F,
    /// Mass (kg).
    pub mass: *const F,
}

/// Per-contact states as arrays: element `k` holds what `ss_state_*` holds for pair `k`. A law
/// reads only its own arrays (`SS_MODEL_AA*`: the displacement; `SS_MODEL_HERTZ_AA*`: the spring
/// force and the contact radius); the others, and all of them for the stateless and frictionless
/// laws, may be null.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_state_arrays<F> {
    /// Displacement x.
    pub displacement_x: *mut F,
    /// Displacement y.
    pub displacement_y: *mut F,
    /// Displacement z.
    pub displacement_z: *mut F,
    /// Spring force x.
    pub spring_force_x: *mut F,
    /// Spring force y.
    pub spring_force_y: *mut F,
    /// Spring force z.
    pub spring_force_z: *mut F,
    /// Contact radius.
    pub contact_radius: *mut F,
}

/// What a batch call writes, as arrays: element `k` of each holds what `ss_forces_*` holds for
/// pair `k`, and `status[k]` that pair's code (`SS_OK` or the error the single call gives).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ss_forces_arrays<F> {
    /// Each pair's code: `SS_OK`, or the error code of `ss_bound_sphere_sphere_*` for it.
    pub status: *mut i32,
    /// 1 when touching, 0 when apart.
    pub touching: *mut i32,
    /// 1 when the contact slid.
    pub sliding: *mut i32,
    /// Overlap (m).
    pub overlap: *mut F,
    /// Normal force (N).
    pub normal_force: *mut F,
    /// Force on j, x (N).
    pub force_on_j_x: *mut F,
    /// Force on j, y (N).
    pub force_on_j_y: *mut F,
    /// Force on j, z (N).
    pub force_on_j_z: *mut F,
    /// Torque on i, x (N m).
    pub torque_on_i_x: *mut F,
    /// Torque on i, y (N m).
    pub torque_on_i_y: *mut F,
    /// Torque on i, z (N m).
    pub torque_on_i_z: *mut F,
    /// Torque on j, x (N m).
    pub torque_on_j_x: *mut F,
    /// Torque on j, y (N m).
    pub torque_on_j_y: *mut F,
    /// Torque on j, z (N m).
    pub torque_on_j_z: *mut F,
}

/// `count` elements at `pointer`, or `None` for null.
///
/// # Safety
/// A non-null pointer must be valid for `count` reads.
pub(crate) unsafe fn read<'a, F>(pointer: *const F, count: usize) -> Option<&'a [F]> {
    // SAFETY: null is checked; the caller promises validity otherwise.
    (!pointer.is_null()).then(|| unsafe { core::slice::from_raw_parts(pointer, count) })
}

/// `count` elements at `pointer` to write, or `None` for null.
///
/// # Safety
/// A non-null pointer must be valid for `count` writes and overlap nothing else of the call.
pub(crate) unsafe fn write<'a, F>(pointer: *mut F, count: usize) -> Option<&'a mut [F]> {
    // SAFETY: null is checked; the caller promises validity otherwise.
    (!pointer.is_null()).then(|| unsafe { core::slice::from_raw_parts_mut(pointer, count) })
}

/// The spheres' arrays as slices, or `None` if one is null.
///
/// # Safety
/// As [`read`], for every field.
pub(crate) unsafe fn sphere_slices<'a, F>(
    s: &ss_sphere_arrays<F>,
    count: usize,
) -> Option<[&'a [F]; 11]> {
    let fields = [
        s.position_x,
        s.position_y,
        s.position_z,
        s.velocity_x,
        s.velocity_y,
        s.velocity_z,
        s.angular_velocity_x,
        s.angular_velocity_y,
        s.angular_velocity_z,
        s.radius,
        s.mass,
    ];
    let mut slices = [&[][..]; 11];
    for (slice, pointer) in slices.iter_mut().zip(fields) {
        // SAFETY: forwarded contract.
        *slice = unsafe { read(pointer, count) }?;
    }
    Some(slices)
}

/// The eleven field arrays of [`ss_sphere_arrays`], in its order.
pub(crate) type SphereSlices<'a, F> = [&'a [F]; 11];

/// Sphere `k` of the arrays.
#[inline(always)]
pub(crate) fn sphere_at<F: Float>(s: &[&[F]; 11], k: usize) -> Sphere<F> {
    Sphere {
        position: Vec3::new(s[0][k], s[1][k], s[2][k]),
        velocity: Vec3::new(s[3][k], s[4][k], s[5][k]),
        angular_velocity: Vec3::new(s[6][k], s[7][k], s[8][k]),
        radius: s[9][k],
        mass: s[10][k],
    }
}

/// A batch call's outputs, as slices.
pub(crate) struct Outputs<'a, F> {
    status: &'a mut [i32],
    flags: [&'a mut [i32]; 2],
    reals: [&'a mut [F]; 11],
}

impl<'a, F: Real> Outputs<'a, F> {
    /// The arrays of `*out`, or `None` if one is null.
    ///
    /// # Safety
    /// As [`write`], for every field.
    unsafe fn of(out: &ss_forces_arrays<F>, count: usize) -> Option<Self> {
        let reals = [
            out.overlap,
            out.normal_force,
            out.force_on_j_x,
            out.force_on_j_y,
            out.force_on_j_z,
            out.torque_on_i_x,
            out.torque_on_i_y,
            out.torque_on_i_z,
            out.torque_on_j_x,
            out.torque_on_j_y,
            out.torque_on_j_z,
        ];
        // SAFETY (all three): forwarded contract.
        let [Some(a), Some(b)] = [out.touching, out.sliding].map(|p| unsafe { write(p, count) })
        else {
            return None;
        };
        let reals = reals.map(|p| unsafe { write(p, count) });
        if reals.iter().any(Option::is_none) {
            return None;
        }
        Some(Self {
            status: unsafe { write(out.status, count) }?,
            flags: [a, b],
            reals: reals.map(Option::unwrap_or_default),
        })
    }

    /// Pair `k`'s result: its forces on success, only its code on error.
    #[inline(always)]
    fn set(&mut self, k: usize, result: Result<Interaction<F>, ContactError>) {
        match result {
            Ok(interaction) => {
                let f = forces_of(interaction);
                let vectors = [f.force_on_j, f.torque_on_i, f.torque_on_j].map(Vec3::from);
                self.write(
                    k,
                    [f.overlap, f.normal_force],
                    vectors,
                    [f.touching, f.sliding],
                );
            }
            Err(e) => self.status[k] = contact_code(e),
        }
    }

    /// A successful pair `k`: overlap and normal force, force on j and the two torques, and the
    /// touching and sliding flags, in the order of [`ss_forces_arrays`].
    #[inline(always)]
    fn write(&mut self, k: usize, scalars: [F; 2], vectors: [Vec3<F>; 3], flags: [i32; 2]) {
        let [overlap, normal_force] = scalars;
        let [f, a, b] = vectors;
        let values = [
            overlap,
            normal_force,
            f.x,
            f.y,
            f.z,
            a.x,
            a.y,
            a.z,
            b.x,
            b.y,
            b.z,
        ];
        for (array, value) in self.reals.iter_mut().zip(values) {
            array[k] = value;
        }
        self.flags[0][k] = flags[0];
        self.flags[1][k] = flags[1];
        self.status[k] = SS_OK;
    }
}

/// A batch call's states, as slices: the displacement's and the Mindlin spring's (`None` where
/// the caller gave null).
pub(crate) struct States<'a, F> {
    displacement: Option<[&'a mut [F]; 3]>,
    mindlin: Option<[&'a mut [F]; 4]>,
}

impl<F: Float> States<'_, F> {
    /// Whether the arrays a state of kind `arrays` lives in were given.
    fn has(&self, arrays: StateArrays) -> bool {
        match arrays {
            StateArrays::None => true,
            StateArrays::Displacement => self.displacement.is_some(),
            StateArrays::Mindlin => self.mindlin.is_some(),
        }
    }

    #[inline(always)]
    fn load<S: Stored<F>>(&self, k: usize) -> S {
        let mut state = ss_state::default();
        if let Some([x, y, z]) = &self.displacement {
            state.displacement = ss_vec3 {
                x: x[k],
                y: y[k],
                z: z[k],
            };
        }
        if let Some([x, y, z, a]) = &self.mindlin {
            state.spring_force = ss_vec3 {
                x: x[k],
                y: y[k],
                z: z[k],
            };
            state.contact_radius = a[k];
        }
        S::load(&state)
    }

    #[inline(always)]
    fn store<S: Stored<F>>(&mut self, k: usize, state: &S) {
        let mut out = ss_state::default();
        state.store(&mut out);
        match S::ARRAYS {
            StateArrays::None => {}
            StateArrays::Displacement => {
                if let Some([x, y, z]) = &mut self.displacement {
                    let d = out.displacement;
                    (x[k], y[k], z[k]) = (d.x, d.y, d.z);
                }
            }
            StateArrays::Mindlin => {
                if let Some([x, y, z, a]) = &mut self.mindlin {
                    let f = out.spring_force;
                    (x[k], y[k], z[k], a[k]) = (f.x, f.y, f.z, out.contact_radius);
                }
            }
        }
    }
}

/// The pairs one at a time through the bound law, each sphere checked, each pair's state and
/// result written back in order (a refused pair's state is left as it was).
#[inline(always)]
pub(crate) fn one_at_a_time<'a, L: Law>(
    bound: &mut BoundLaw<L>,
    (i, j): (&SphereSlices<'a, L::Float>, &SphereSlices<'a, L::Float>),
    states: &mut States<'a, L::Float>,
    out: &mut Outputs<'a, L::Float>,
) where
    L::Float: Real,
    L::State: Stored<L::Float>,
{
    for k in 0..out.status.len() {
        let mut state = states.load(k);
        let result = CheckedSphere::new(sphere_at(i, k)).and_then(|a| {
            let b = CheckedSphere::new(sphere_at(j, k))?;
            bound.sphere_sphere(&a, &b, &mut state)
        });
        if result.is_ok() {
            states.store(k, &state);
        }
        out.set(k, result);
    }
}

/// The arrays the bound law's per-contact state lives in.
pub(crate) fn state_arrays<L: Law>(_: &BoundLaw<L>) -> StateArrays
where
    L::State: Stored<L::Float>,
{
    <L::State as Stored<L::Float>>::ARRAYS
}

/// # Safety
/// As the exported batch calls.
pub(crate) unsafe fn bound_pairs<F: Real>(
    bound: *mut ss_bound_law<F>,
    count: usize,
    i: *const ss_sphere_arrays<F>,
    j: *const ss_sphere_arrays<F>,
    states: *const ss_state_arrays<F>,
    out: *const ss_forces_arrays<F>,
) -> i32 {
    // SAFETY: null is checked; the caller promises validity otherwise.
    let (Some(bound), Some(i), Some(j), Some(states), Some(out)) = (unsafe {
        (
            bound.as_mut(),
            i.as_ref(),
            j.as_ref(),
            states.as_ref(),
            out.as_ref(),
        )
    }) else {
        return SS_ERR_NULL;
    };
    // SAFETY (all below): the caller promises each array valid for `count` elements and the
    // written ones disjoint from each other and from the inputs.
    let (Some(i), Some(j), Some(mut out)) = (unsafe {
        (
            sphere_slices(i, count),
            sphere_slices(j, count),
            Outputs::of(out, count),
        )
    }) else {
        return SS_ERR_NULL;
    };
    let displacement = [
        states.displacement_x,
        states.displacement_y,
        states.displacement_z,
    ]
    .map(|p| unsafe { write(p, count) });
    let mindlin = [
        states.spring_force_x,
        states.spring_force_y,
        states.spring_force_z,
        states.contact_radius,
    ]
    .map(|p| unsafe { write(p, count) });
    let mut states = States {
        displacement: match displacement {
            [Some(x), Some(y), Some(z)] => Some([x, y, z]),
            _ => None,
        },
        mindlin: match mindlin {
            [Some(x), Some(y), Some(z), Some(a)] => Some([x, y, z, a]),
            _ => None,
        },
    };
    // A law that keeps a per-contact state needs its arrays.
    let needed = each_law!(&bound.bound, AnyBound, b => state_arrays(b));
    if !states.has(needed) {
        return SS_ERR_NULL;
    }
    each_law!(&mut bound.bound, AnyBound, b => one_at_a_time(b, (&i, &j), &mut states, &mut out));
    SS_OK
}
