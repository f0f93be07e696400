//! The validation run's cases (docs/physics.md, section 5), with the tolerances the `validate` binary
//! enforces: this test fails exactly when `cargo run -p host-tests --bin validate` would exit
//! non-zero.

use host_tests::validation::{CaseOutput, chung_ooi, kharaz, micro_slip, normal, plate};

fn assert_all_pass(case: &CaseOutput) {
    assert!(!case.checks.is_empty(), "the case made no checks");
    let failures: Vec<String> = case.failures().iter().map(|c| c.to_string()).collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn normal_impact_matches_the_closed_forms() {
    let case = normal::case(|_| {});
    assert_all_pass(&case);
    // Free and clamped rebound ratio and duration for 7 restitution coefficients.
    assert_eq!(case.checks.len(), 28);
}

#[test]
fn kharaz_sweep_converges_and_meets_rigid_body_theory() {
    let case = kharaz::talk_sweep(|_| {});
    assert_all_pass(&case);
    // Every model but C is checked above the sliding threshold (about 32.5 deg) ...
    for model in ["stateless", "model_a", "model_b", "model_aa"] {
        assert!(
            case.checks
                .iter()
                .any(|c| c.what.contains(model) && c.what.contains("rigid body")),
            "{model} has no rigid-body check"
        );
    }
    // ... and Model C is shown, not checked: its dashpot never reaches the Coulomb limit.
    assert!(!case.checks.iter().any(|c| c.what.contains("model_c")));
    // Model AA is the closest to the experiment on every measured quantity.
    let rms = case.table("kharaz_rms");
    for column in [
        "rms_tangential_cor",
        "rms_rebound_spin_rad_per_s",
        "rms_rebound_angle_deg",
    ] {
        let values = rms.column(column);
        let aa = values[kharaz::Model::ALL
            .iter()
            .position(|m| *m == kharaz::Model::ModelAA)
            .unwrap()];
        assert!(values.iter().all(|v| *v >= aa), "{column}: {values:?}");
    }
}

#[test]
fn model_aa_matches_the_mfix_reference_within_the_stated_tolerances() {
    let case = kharaz::mfix_check(|_| {});
    assert_all_pass(&case);
    assert_eq!(case.checks.len(), 60);
}

#[test]
fn plate_rolls_at_five_sevenths_on_time_for_aa_b_and_the_stateless_law() {
    let case = plate::case(|_| {});
    assert_all_pass(&case);
    let summary = case.table("plate_summary");
    let (onset, u) = (
        summary.column("rolling_onset_s"),
        summary.column("final_velocity_ratio"),
    );
    let index = |m| kharaz::Model::ALL.iter().position(|x| *x == m).unwrap();
    // Model A's unbounded spring throws the sphere off 5/7 (docs/physics.md, section 5.3) ...
    assert!((u[index(kharaz::Model::ModelA)] - 5.0 / 7.0).abs() > 0.05);
    // ... and Model C's weak dashpot near zero slip reaches rolling late.
    let theory = 2.0 / (7.0 * 0.7 * 9.81);
    assert!(onset[index(kharaz::Model::ModelC)] > 1.1 * theory);
}

#[test]
fn a_check_fails_outside_its_tolerance_and_on_nan() {
    let mut case = CaseOutput::default();
    case.relative("inside", 1.004, 1.0, 5e-3);
    case.relative("outside", 1.006, 1.0, 5e-3);
    case.absolute("nan", f64::NAN, 1.0, 1.0);
    let failed: Vec<&str> = case.failures().iter().map(|c| c.what.as_str()).collect();
    assert_eq!(failed, ["outside", "nan"]);
}

#[test]
fn velocity_verlet_rebounds_with_e_and_converges_at_first_order() {
    use host_tests::impact::Integrator;
    for e in normal::RESTITUTIONS {
        let fine = normal::head_on(e, false, 1000.0, Integrator::VelocityVerlet);
        assert!((fine.rebound.velocity.z - e).abs() < 1e-3, "e = {e}");
    }
    // First order: the error at e = 0.5 halves when the step halves (ratio 2 within 10 %).
    let error = |steps| {
        normal::head_on(0.5, false, steps, Integrator::VelocityVerlet)
            .rebound
            .velocity
            .z
            - 0.5
    };
    let ratio = error(100.0) / error(200.0);
    assert!((ratio - 2.0).abs() < 0.2, "ratio {ratio}");
}

#[test]
fn chung_ooi_tests_1_and_2_follow_hertz() {
    let case = chung_ooi::elastic(|_| {});
    assert_all_pass(&case);
    // Peak overlap, duration and force-overlap curve for four materials.
    assert_eq!(case.checks.len(), 12);
}

#[test]
fn chung_ooi_test_3_rebounds_at_the_input_restitution_at_every_speed() {
    let case = chung_ooi::restitution(|_| {});
    assert_all_pass(&case);
    // Two materials, three speeds a factor 100 apart, eleven restitution coefficients.
    assert_eq!(case.checks.len(), 66);
}

#[test]
fn chung_ooi_tests_4_to_8_meet_rigid_body_theory_in_gross_sliding() {
    let case = chung_ooi::kharaz(|_| {});
    assert_all_pass(&case);
    let case = chung_ooi::oblique(|_| {});
    assert_all_pass(&case);
    for name in ["chung_ooi_test5", "chung_ooi_test6"] {
        assert!(
            case.table(name).rows.len() >= 40,
            "{name} has too few points"
        );
    }
    assert_eq!(case.table("chung_ooi_test5").column("hertz_aa").len(), 48);
}

#[test]
fn micro_slip_cycles_dissipate_mindlin_and_deresiewiczs_energy_at_every_contact_size() {
    let case = micro_slip::case(|_| {});
    assert_all_pass(&case);
    // 4 breakpoint counts, 4 contact radii, 5 amplitudes.
    assert_eq!(case.checks.len(), 80);
    let table = case.table("microslip_loops");
    assert_eq!(table.rows.len(), 80);
    assert_eq!(
        table
            .column("springs")
            .iter()
            .filter(|&&s| s == 16.0)
            .count(),
        20
    );
}

#[test]
fn rolling_resistance_stops_holds_and_accelerates_as_the_closed_forms() {
    let case = host_tests::validation::rolling::case(|_| {});
    assert_all_pass(&case);
    assert_eq!(case.checks.len(), 6);
}

/// LIGGGHTS' tangential dashpot keeps the normal damping ratio: `eta_t / eta_n = sqrt(k_t / k_n)`,
/// which for one material on a rigid wall is Mindlin's `sqrt(2 (1 - nu) / (2 - nu))`, and for two
/// spheres of one material the same.
#[test]
fn matched_tangential_damping_is_mindlins_stiffness_ratio() {
    let nu: f64 = 0.30; // Test 6's and Test 8's aluminium alloy
    let expected = (2.0 * (1.0 - nu) / (2.0 - nu)).sqrt();
    for pair in [chung_ooi::test6_pair(), chung_ooi::test8_pair()] {
        assert_eq!(pair.tangential_dashpot, 0.0);
        let damped = pair.with_matched_damping();
        assert!(
            (damped.tangential_dashpot - expected).abs() < 1e-12,
            "{} against {expected}",
            damped.tangential_dashpot
        );
    }
}

/// `docs/validation.md` quotes the table of tolerances as the code holds it.
/// `UPDATE_DOCS=1 cargo test -p host-tests --test validation tolerances` rewrites the quote.
#[test]
fn tolerances_are_quoted_as_the_code_holds_them() {
    use host_tests::validation::precision;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/validation.md");
    let doc = std::fs::read_to_string(&path).unwrap();
    let (start, end) = (
        "<!-- tolerances: precision.rs -->\n",
        "<!-- end of tolerances -->",
    );
    let (before, rest) = doc.split_once(start).expect("the quote's start marker");
    let (quoted, after) = rest.split_once(end).expect("the quote's end marker");
    let table = precision::markdown();
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(&path, format!("{before}{start}{table}{end}{after}")).unwrap();
    } else {
        assert_eq!(
            quoted, table,
            "docs/validation.md quotes a stale table: run with UPDATE_DOCS=1"
        );
    }
    // Every bound is positive and finite.
    for t in precision::TOLERANCES {
        assert!(t.bound > 0.0 && t.bound.is_finite(), "{t:?}");
    }
}
