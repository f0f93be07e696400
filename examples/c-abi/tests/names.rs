//! The names a host shows: every law the documentation lists (`docs/lammps.md`: the plugin's
//! law names) is named, found by its name, of the family its parameters say, and built by the
//! constructor it names; every parameter and error code has its own text; bad names and null
//! pointers get their codes.

use std::ffi::{CStr, CString};
use std::ptr::{null, null_mut};

use soft_sphere_ffi::*;

/// The documented names and codes (the header's constants), written here, not read from the list.
const DOCUMENTED: [(&str, i32, bool); 8] = [
    ("stateless", SS_MODEL_STATELESS, false),
    ("aa", SS_MODEL_AA, false),
    ("aa/luding", SS_MODEL_AA_LUDING, false),
    ("frictionless", SS_MODEL_FRICTIONLESS, false),
    ("hertz/frictionless", SS_MODEL_HERTZ_FRICTIONLESS, true),
    ("hertz/stateless", SS_MODEL_HERTZ_STATELESS, true),
    ("hertz/aa", SS_MODEL_HERTZ_AA, true),
    ("hertz/aa/luding", SS_MODEL_HERTZ_AA_LUDING, true),
];

fn text(pointer: *const std::ffi::c_char) -> String {
    assert!(!pointer.is_null());
    // SAFETY: the C ABI returns static NUL-terminated strings.
    unsafe { CStr::from_ptr(pointer) }
        .to_str()
        .unwrap()
        .to_owned()
}

fn code_of(name: &str) -> Result<i32, i32> {
    let name = CString::new(name).unwrap();
    let mut model = -7;
    // SAFETY: valid pointers.
    match unsafe { ss_model_of_name(name.as_ptr(), &mut model) } {
        SS_OK => Ok(model),
        code => {
            assert_eq!(model, -7, "a refused name leaves the output alone");
            Err(code)
        }
    }
}

/// Parameters valid for either family: the linear stiffnesses and Hertz's moduli and impact.
fn params(model: i32) -> ss_params<f64> {
    ss_params {
        model,
        normal_stiffness: 1.0e4,
        restitution: 0.7,
        tangential_stiffness: 2.8e3,
        dashpot_ratio: 0.5,
        friction: 0.4,
        time_step: 1.0e-7,
        smallest_effective_mass: 1.0e-6,
        effective_modulus: 1.0e8,
        effective_shear_modulus: 4.0e7,
        largest_impact_speed: 1.0,
        largest_effective_radius: 1.0e-3,
    }
}

#[test]
fn every_documented_law_is_named_found_and_built() {
    assert_eq!(ss_model_count(), DOCUMENTED.len());
    assert_eq!(ss_model_code(DOCUMENTED.len()), -1);
    let listed: Vec<i32> = (0..ss_model_count()).map(|k| ss_model_code(k)).collect();
    for (name, code, hertz) in DOCUMENTED {
        assert!(listed.contains(&code), "{name} is listed");
        assert_eq!(text(ss_model_name(code)), name);
        assert_eq!(code_of(name), Ok(code));
        assert_eq!(ss_model_is_hertz(code), i32::from(hertz), "{name}");
        let mut law = null_mut();
        // SAFETY: valid pointers.
        assert_eq!(
            unsafe { ss_law_new_f64(&params(code), &mut law) },
            SS_OK,
            "{name}"
        );
        // A Hertz law reads the moduli, a linear one the stiffnesses: zeroing the other
        // family's fields changes nothing, zeroing its own is refused.
        let own = if hertz {
            ss_params {
                normal_stiffness: 0.0,
                effective_modulus: 0.0,
                ..params(code)
            }
        } else {
            ss_params {
                effective_modulus: 0.0,
                normal_stiffness: 0.0,
                ..params(code)
            }
        };
        let other = if hertz {
            ss_params {
                normal_stiffness: 0.0,
                tangential_stiffness: 0.0,
                ..params(code)
            }
        } else {
            ss_params {
                effective_modulus: 0.0,
                effective_shear_modulus: 0.0,
                ..params(code)
            }
        };
        let mut refused = null_mut();
        // SAFETY: valid pointers.
        assert_eq!(
            unsafe { ss_law_new_f64(&own, &mut refused) },
            SS_ERR_NOT_POSITIVE,
            "{name}"
        );
        assert!(refused.is_null());
        let mut built = null_mut();
        // SAFETY: valid pointers.
        assert_eq!(
            unsafe { ss_law_new_f64(&other, &mut built) },
            SS_OK,
            "{name}"
        );
        // SAFETY: handles from ss_law_new_f64.
        unsafe {
            ss_law_free_f64(law);
            ss_law_free_f64(built);
        }
    }
    assert_eq!(ss_model_is_hertz(SS_MODEL_HERTZ_MICROSLIP), 1);
    assert!(ss_model_name(SS_MODEL_HERTZ_MICROSLIP).is_null());
}

#[test]
fn bad_names_and_null_pointers_are_refused() {
    for name in ["", "hertz", "AA", "aa ", "aa/", "hertz/aa/luding/x"] {
        assert_eq!(code_of(name), Err(SS_ERR_UNKNOWN_MODEL), "{name:?}");
    }
    assert!(ss_model_name(-1).is_null());
    assert!(ss_model_name(99).is_null());
    let name = CString::new("aa").unwrap();
    let mut model = 0;
    // SAFETY: null is the point.
    unsafe {
        assert_eq!(ss_model_of_name(null(), &mut model), SS_ERR_NULL);
        assert_eq!(ss_model_of_name(name.as_ptr(), null_mut()), SS_ERR_NULL);
    }
}

#[test]
fn every_parameter_and_error_code_has_its_own_text() {
    let parameters: Vec<String> = (SS_PARAMETER_NORMAL_STIFFNESS..=SS_PARAMETER_INERTIA)
        .map(|p| text(ss_parameter_name(p, SS_MODEL_AA)))
        .collect();
    let fallback = text(ss_parameter_name(-1, SS_MODEL_AA));
    for (k, name) in parameters.iter().enumerate() {
        assert_ne!(name, &fallback, "parameter {}", k + 1);
        assert_eq!(
            parameters.iter().filter(|n| *n == name).count(),
            1,
            "{name}"
        );
    }
    assert_eq!(
        text(ss_parameter_name(SS_PARAMETER_MODULUS, SS_MODEL_HERTZ_AA)),
        "E (Young's modulus)"
    );
    assert_eq!(
        text(ss_parameter_name(
            SS_PARAMETER_DAMPING_FACTOR,
            SS_MODEL_HERTZ_AA
        )),
        "alpha (Hertz damping factor)"
    );
    let parameter_errors = [
        SS_ERR_NON_FINITE_PARAMETER,
        SS_ERR_NOT_POSITIVE,
        SS_ERR_NEGATIVE,
        SS_ERR_RESTITUTION,
        SS_ERR_UNSTABLE_TIME_STEP,
        SS_ERR_UNKNOWN_MODEL,
        SS_ERR_POISSON_RATIO,
    ];
    let unknown = text(ss_parameter_error_text(-1));
    for code in parameter_errors {
        assert_ne!(text(ss_parameter_error_text(code)), unknown, "code {code}");
    }
    let contact_errors = [
        SS_ERR_NULL,
        SS_ERR_NON_FINITE_INPUT,
        SS_ERR_NON_POSITIVE_RADIUS,
        SS_ERR_NON_POSITIVE_MASS,
        SS_ERR_COINCIDENT_CENTRES,
        SS_ERR_NON_FINITE_RESULT,
        SS_ERR_BAD_WALL,
        SS_ERR_PAST_STABLE_STEP,
        SS_ERR_LENGTH,
        SS_ERR_INDEX,
        SS_ERR_MATERIAL,
        SS_ERR_NOT_PREPARED,
        SS_ERR_REPEATED_PAIR,
        SS_ERR_HISTORY_FULL,
    ];
    let rejected = text(ss_contact_error_text(-1));
    let texts: Vec<String> = contact_errors
        .iter()
        .map(|&c| text(ss_contact_error_text(c)))
        .collect();
    for (code, t) in contact_errors.iter().zip(&texts) {
        assert_ne!(t, &rejected, "code {code}");
        assert_eq!(texts.iter().filter(|x| *x == t).count(), 1, "{t}");
    }
}

#[test]
fn the_version_is_the_crates_and_the_headers() {
    // The workspace's version, as Cargo.toml states it and as the header's macros hold it.
    let manifest = include_str!("../../../Cargo.toml");
    let stated = manifest
        .lines()
        .skip_while(|l| *l != "[workspace.package]")
        .find_map(|l| l.strip_prefix("version = \""))
        .and_then(|v| v.strip_suffix('"'))
        .unwrap();
    assert_eq!(text(ss_version()), stated);
    let header = include_str!("../include/soft_sphere.h");
    let mut parts = stated.split('.');
    for macro_name in ["SS_VERSION_MAJOR", "SS_VERSION_MINOR", "SS_VERSION_PATCH"] {
        let line = format!("#define {macro_name} {}\n", parts.next().unwrap());
        assert!(header.contains(&line), "{line}");
    }
    assert!(header.contains(&format!("#define SS_VERSION_STRING \"{stated}\"\n")));
}
