//! What a host shows its users: the laws' names (from the registry), what each parameter code
//! names and what each error code means, as NUL-terminated static strings, so that no host
//! writes the lists again.

use core::ffi::{CStr, c_char};

use crate::registry::{NAMES, hertz_model};
use crate::table::{
    SS_ERR_INDEX, SS_ERR_LENGTH, SS_ERR_MATERIAL, SS_ERR_NOT_PREPARED, SS_ERR_REPEATED_PAIR,
};
use crate::*;

/// The library's version, `"MAJOR.MINOR.PATCH"` (NUL-terminated, static): the crate's version,
/// which the header's `SS_VERSION_*` macros also hold, so that a host can check at run time
/// that the library it loaded is the one its header describes (`docs/c-abi.md`, "Versions").
#[unsafe(no_mangle)]
pub extern "C" fn ss_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// How many laws the C ABI names (`ss_model_code` counts them; the material tables also take
/// `SS_MODEL_HERTZ_MICROSLIP`, which has no name).
#[unsafe(no_mangle)]
pub extern "C" fn ss_model_count() -> usize {
    NAMES.len()
}

/// The `SS_MODEL_*` code of the `index`-th named law (from 0), or -1 past the last.
#[unsafe(no_mangle)]
pub extern "C" fn ss_model_code(index: usize) -> i32 {
    NAMES.get(index).map_or(-1, |&(code, _)| code)
}

/// The name of law `model` as an input script writes it (`"aa"`, `"hertz/aa/luding"`, ...), or
/// null for a code with no name.
#[unsafe(no_mangle)]
pub extern "C" fn ss_model_name(model: i32) -> *const c_char {
    NAMES
        .iter()
        .find(|&&(code, _)| code == model)
        .map_or(core::ptr::null(), |&(_, name)| name.as_ptr().cast())
}

/// Writes the `SS_MODEL_*` code of the law named `name` (NUL-terminated) to `*model`. Returns
/// `SS_OK`, `SS_ERR_NULL`, or `SS_ERR_UNKNOWN_MODEL` (then `*model` is unchanged).
///
/// # Safety
/// Non-null pointers must be valid; `name` must be NUL-terminated.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ss_model_of_name(name: *const c_char, model: *mut i32) -> i32 {
    if name.is_null() || model.is_null() {
        return SS_ERR_NULL;
    }
    // SAFETY: non-null, and the caller promises a NUL-terminated string.
    let name = unsafe { CStr::from_ptr(name) }.to_bytes();
    match NAMES
        .iter()
        .find(|(_, n)| &n.as_bytes()[..n.len() - 1] == name)
    {
        Some(&(code, _)) => {
            // SAFETY: checked non-null.
            unsafe { *model = code };
            SS_OK
        }
        None => SS_ERR_UNKNOWN_MODEL,
    }
}

/// 1 when law `model` is of Hertz's family (its parameters are `E`, `nu` and a declared
/// impact; `SS_MODEL_HERTZ_MICROSLIP` included), 0 otherwise.
#[unsafe(no_mangle)]
pub extern "C" fn ss_model_is_hertz(model: i32) -> i32 {
    i32::from(hertz_model(model))
}

/// A static C string (the text ends in its NUL).
fn text(s: &'static [u8]) -> *const c_char {
    debug_assert_eq!(s.last(), Some(&0));
    s.as_ptr().cast()
}

/// What an `SS_PARAMETER_*` code names, for a law of `model` (the modulus is Young's `E` for
/// Hertz's family), as a user reads it: `"k_n (normal stiffness)"`, ...
#[unsafe(no_mangle)]
pub extern "C" fn ss_parameter_name(parameter: i32, model: i32) -> *const c_char {
    text(match parameter {
        SS_PARAMETER_NORMAL_STIFFNESS => b"k_n (normal stiffness)\0",
        SS_PARAMETER_RESTITUTION => b"e (restitution)\0",
        SS_PARAMETER_TANGENTIAL_STIFFNESS => b"k_t (tangential stiffness)\0",
        SS_PARAMETER_DASHPOT_RATIO => b"eta_ratio (tangential over normal dashpot)\0",
        SS_PARAMETER_FRICTION => b"mu (friction)\0",
        SS_PARAMETER_TIME_STEP => b"the time step\0",
        SS_PARAMETER_MASS => b"the smallest mass\0",
        SS_PARAMETER_MODULUS if ss_model_is_hertz(model) == 1 => b"E (Young's modulus)\0",
        SS_PARAMETER_MODULUS => b"the modulus\0",
        SS_PARAMETER_POISSON_RATIO => b"nu (Poisson's ratio)\0",
        SS_PARAMETER_SPEED => b"the declared impact speed\0",
        SS_PARAMETER_RADIUS => b"the largest radius\0",
        SS_PARAMETER_ROLLING_FRICTION => b"mu_r (rolling friction)\0",
        SS_PARAMETER_ROLLING_STIFFNESS => b"k_r (rolling stiffness)\0",
        SS_PARAMETER_ROLLING_DAMPING => b"eta_r (rolling dashpot)\0",
        SS_PARAMETER_WALL => b"the wall\0",
        SS_PARAMETER_DAMPING_FACTOR => b"alpha (Hertz damping factor)\0",
        SS_PARAMETER_INERTIA => b"the smallest moment of inertia\0",
        SS_PARAMETER_MODEL => b"the law\0",
        _ => b"a parameter\0",
    })
}

/// What an error code says of the parameter it is about, to follow its name: `"must be
/// positive"`, ...
#[unsafe(no_mangle)]
pub extern "C" fn ss_parameter_error_text(code: i32) -> *const c_char {
    text(match code {
        SS_ERR_NON_FINITE_PARAMETER => b"is not finite\0",
        SS_ERR_NOT_POSITIVE => b"must be positive\0",
        SS_ERR_NEGATIVE => b"must not be negative\0",
        SS_ERR_RESTITUTION => b"must lie in [0, 1]\0",
        SS_ERR_POISSON_RATIO => b"must lie in (-1, 0.5]\0",
        SS_ERR_UNSTABLE_TIME_STEP => b"is at or past the stability limit\0",
        SS_ERR_INACCURATE_TIME_STEP => b"is at or past the accuracy limit\0",
        SS_ERR_UNKNOWN_MODEL => b"is not one the kernel knows\0",
        _ => b"is invalid\0",
    })
}

/// What a contact or list error code means, as a sentence.
#[unsafe(no_mangle)]
pub extern "C" fn ss_contact_error_text(code: i32) -> *const c_char {
    text(match code {
        SS_ERR_NON_FINITE_INPUT => b"a position, velocity, radius, mass, or force or torque to add to, is not finite\0",
        SS_ERR_NON_POSITIVE_RADIUS => b"a radius is not positive\0",
        SS_ERR_NON_POSITIVE_MASS => b"a mass is not positive\0",
        SS_ERR_COINCIDENT_CENTRES => {
            b"the two centres coincide, or a sphere wider than a cylinder wall is on its axis\0"
        }
        SS_ERR_NON_FINITE_RESULT => b"the contact force overflowed\0",
        SS_ERR_HISTORY_FULL => b"a new contact found its history store full\0",
        SS_ERR_PAST_STABLE_STEP => {
            b"the contact is stiffer than the time step was checked for (past its accuracy or stability limit: shorten the time step, or for a Hertz law declare a faster impact)\0"
        }
        SS_ERR_LENGTH => b"a neighbour count or the history size is wrong\0",
        SS_ERR_INDEX => b"a neighbour index is past the spheres\0",
        SS_ERR_REPEATED_PAIR => b"the neighbour list names a pair twice\0",
        SS_ERR_MATERIAL => b"a material id is past the table's materials\0",
        SS_ERR_NULL => b"an array is missing\0",
        SS_ERR_NOT_PREPARED => b"the table was not prepared for a time step\0",
        SS_ERR_BAD_WALL => b"a wall's point or normal is not valid\0",
        _ => b"the contact was rejected\0",
    })
}
