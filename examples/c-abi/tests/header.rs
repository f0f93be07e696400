//! The checked-in C header is what cbindgen makes of `src/lib.rs` now. Regenerate it with
//! `UPDATE_HEADER=1 cargo test -p soft-sphere-ffi --test header`.

use std::path::PathBuf;

#[test]
fn header_is_current() {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).unwrap();
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen parses the crate")
        .write(&mut generated);
    let generated = String::from_utf8(generated).unwrap();
    let path = crate_dir.join("include/soft_sphere.h");
    if std::env::var_os("UPDATE_HEADER").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "include/soft_sphere.h is stale: run UPDATE_HEADER=1 cargo test -p soft-sphere-ffi --test header"
    );
    for symbol in [
        "ss_law_new_f64",
        "ss_sphere_wall_f32",
        "ss_forces_f64",
        "ss_law_f32",
    ] {
        assert!(
            generated.contains(symbol),
            "{symbol} missing from the header"
        );
    }
}
