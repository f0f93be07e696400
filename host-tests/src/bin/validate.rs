//! The validation run: every case of docs/physics.md, section 5 against theory and data, printed as
//! tables, written as CSV and SVG, and a non-zero exit status when a tolerance is missed.
//!
//! Usage: `cargo run --release -p host-tests --bin validate -- [--out DIR]`
//! (DIR defaults to `target/validation`).

use std::error::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use host_tests::analytic::{rigid_body_oblique, rolling_onset};
use host_tests::data;
use host_tests::plot::{Axes, Mark, Series, chart};
use host_tests::validation::kharaz::{self, Model, TALK};
use host_tests::validation::{
    CaseOutput, Cell, Table, chung_ooi, micro_slip, normal, plate, rolling,
};

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(error) => {
            eprintln!("validate: {error}");
            ExitCode::from(2)
        }
    }
}

fn parse_out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let mut out = PathBuf::from("target/validation");
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out = args.next().ok_or("--out needs a directory")?.into(),
            "-h" | "--help" => {
                println!("usage: validate [--out DIR]   (DIR defaults to target/validation)");
                std::process::exit(0);
            }
            other => return Err(format!("unknown argument {other:?} (try --help)").into()),
        }
    }
    Ok(out)
}

fn run() -> Result<bool, Box<dyn Error>> {
    let out_dir = parse_out_dir()?;
    std::fs::create_dir_all(&out_dir)?;
    let start = Instant::now();
    let progress = |what: &str| eprintln!("[{:6.2} s] {what}", start.elapsed().as_secs_f64());

    let cases = [
        (
            "Normal impact (docs/physics.md, section 5.1)",
            normal::case(progress),
        ),
        (
            "Kharaz oblique impact (docs/physics.md, sections 5.2 and 5.4)",
            kharaz::talk_sweep(progress),
        ),
        (
            "Model AA against the MFiX DEM05 linear reference",
            kharaz::mfix_check(progress),
        ),
        (
            "Sphere sliding on a plate (docs/physics.md, section 5.3)",
            plate::case(progress),
        ),
        (
            "Rolling resistance (docs/physics.md, section 5.6)",
            rolling::case(progress),
        ),
        (
            "Chung & Ooi Tests 1 and 2: elastic impacts (docs/physics.md, section 5.5)",
            chung_ooi::elastic(progress),
        ),
        (
            "Chung & Ooi Test 3: restitution (docs/physics.md, section 5.5)",
            chung_ooi::restitution(progress),
        ),
        (
            "Chung & Ooi Test 4: Kharaz with Hertz-Mindlin (docs/physics.md, section 5.5)",
            chung_ooi::kharaz(progress),
        ),
        (
            "Chung & Ooi Tests 5 to 8: oblique impacts (docs/physics.md, section 5.5)",
            chung_ooi::oblique(progress),
        ),
        (
            "Micro-slip load cycles (docs/physics.md, section 5.7)",
            micro_slip::case(progress),
        ),
    ];
    progress("writing results");
    for (title, case) in &cases {
        print_case(title, case);
        for (name, table) in &case.tables {
            table.write_csv(&out_dir.join(format!("{name}.csv")))?;
        }
    }
    let [_, (_, talk), (_, mfix), (_, plate), .., (_, oblique), _] = &cases;
    plot_kharaz(&out_dir, talk)?;
    plot_mfix(&out_dir, mfix)?;
    plot_plate(&out_dir, plate)?;
    plot_chung_ooi(&out_dir, oblique)?;
    plot_accuracy(&out_dir)?;
    let passed = report_checks(&out_dir, &cases)?;
    progress(&format!("done; results in {}", out_dir.display()));
    Ok(passed)
}

fn print_case(title: &str, case: &CaseOutput) {
    println!("\n== {title}");
    for (name, table) in &case.tables {
        match table.shown_every {
            0 => println!("\n{name}.csv: {} rows, not printed", table.rows.len()),
            1 => println!("\n{name}.csv"),
            n => println!("\n{name}.csv: {} rows, every {n}th shown", table.rows.len()),
        }
        print!("{}", table.to_text());
    }
    for note in &case.notes {
        println!("  note: {note}");
    }
}

fn report_checks(out_dir: &Path, cases: &[(&str, CaseOutput)]) -> Result<bool, Box<dyn Error>> {
    let mut table = Table::new(&[
        "check",
        "measured",
        "expected",
        "deviation",
        "tolerance",
        "relative",
        "passed",
    ]);
    let (mut total, mut failed) = (0, 0);
    println!("\n== Tolerance checks");
    for (title, case) in cases {
        let failures = case.failures();
        total += case.checks.len();
        failed += failures.len();
        let worst = case
            .checks
            .iter()
            .map(|c| c.deviation() / c.tolerance)
            .fold(0.0, f64::max);
        println!(
            "  {title}: {} of {} checks passed (worst at {:.0} % of its tolerance)",
            case.checks.len() - failures.len(),
            case.checks.len(),
            100.0 * worst
        );
        for check in failures {
            println!("    FAILED {check}");
        }
        for c in &case.checks {
            table.push(vec![
                Cell::Text(c.what.replace(',', ";")),
                c.measured.into(),
                c.expected.into(),
                c.deviation().into(),
                c.tolerance.into(),
                f64::from(u8::from(c.relative)).into(),
                f64::from(u8::from(c.passed())).into(),
            ]);
        }
    }
    table.write_csv(&out_dir.join("checks.csv"))?;
    if failed == 0 {
        println!("  all {total} checks passed");
    } else {
        println!("  {failed} of {total} checks FAILED");
    }
    Ok(failed == 0)
}

fn xy(table: &Table, x: &str, y: &str) -> Vec<(f64, f64)> {
    table.column(x).into_iter().zip(table.column(y)).collect()
}

fn data_points(file: &str) -> Vec<(f64, f64)> {
    data::rows(file).into_iter().map(|r| (r[0], r[1])).collect()
}

fn plot_kharaz(out_dir: &Path, talk: &CaseOutput) -> Result<(), Box<dyn Error>> {
    let angles: Vec<f64> = (1..=890).map(|a| f64::from(a) / 10.0).collect();
    let theory = |quantity: fn(f64, (f64, f64)) -> f64| {
        angles
            .iter()
            .map(|&a| {
                (
                    a,
                    quantity(a, rigid_body_oblique(a, TALK.restitution, TALK.friction)),
                )
            })
            .collect::<Vec<_>>()
    };
    // (file, column, axis label, experiment file, rigid-body curve)
    type Panel = (
        &'static str,
        &'static str,
        &'static str,
        &'static str,
        Vec<(f64, f64)>,
    );
    let panels: [Panel; 3] = [
        (
            "kharaz_tangential_cor",
            "tangential_cor",
            "tangential restitution e_t",
            "kharaz2001_tangential_cor.csv",
            theory(|_, (e_t, _)| e_t),
        ),
        (
            "kharaz_rebound_spin",
            "rebound_spin_rad_per_s",
            "rebound spin (rad/s)",
            "kharaz2001_rebound_spin.csv",
            theory(|_, (_, w)| w * TALK.speed / TALK.radius),
        ),
        (
            "kharaz_rebound_angle",
            "rebound_angle_deg",
            "rebound angle (deg)",
            "kharaz2001_rebound_angle.csv",
            theory(|a, (e_t, _)| {
                let theta = a.to_radians();
                (e_t * theta.sin())
                    .atan2(TALK.restitution * theta.cos())
                    .to_degrees()
            }),
        ),
    ];
    for (file, column, y_label, experiment, rigid) in panels {
        let mut series: Vec<Series> = Model::ALL
            .iter()
            .map(|m| {
                let table = talk.table(&format!("kharaz_{}", m.name()));
                Series::new(m.name(), xy(table, "impact_angle_deg", column), Mark::Line)
            })
            .collect();
        series.push(Series::new("rigid body", rigid, Mark::Theory));
        series.push(Series::new(
            "Kharaz et al. 2001",
            data_points(experiment),
            Mark::Points,
        ));
        chart(
            &out_dir.join(format!("{file}.svg")),
            &format!("Kharaz oblique impact: {y_label} (talk's parameters, dt = t_c/50)"),
            ("impact angle from the normal (deg)", y_label),
            &series,
            Axes::Linear,
        )?;
    }
    Ok(())
}

fn plot_mfix(out_dir: &Path, mfix: &CaseOutput) -> Result<(), Box<dyn Error>> {
    let table = mfix.table("kharaz_mfix_side_by_side");
    for (file, ours, theirs, label) in [
        (
            "kharaz_mfix_check_tangential_cor",
            "tangential_cor",
            "mfix_tangential_cor",
            "tangential restitution e_t",
        ),
        (
            "kharaz_mfix_check_spin",
            "rebound_spin_rad_per_s",
            "mfix_rebound_spin_rad_per_s",
            "rebound spin (rad/s)",
        ),
    ] {
        let series = [
            Series::new(
                "Model AA (this kernel)",
                xy(table, "impact_angle_deg", ours),
                Mark::Line,
            ),
            Series::new(
                "MFiX DEM05 reference",
                xy(table, "impact_angle_deg", theirs),
                Mark::Points,
            ),
        ];
        chart(
            &out_dir.join(format!("{file}.svg")),
            &format!("Model AA vs MFiX DEM05 linear model: {label}"),
            ("impact angle from the normal (deg)", label),
            &series,
            Axes::Linear,
        )?;
    }
    Ok(())
}

/// Chung & Ooi's Tests 5 and 6: every law against the paper's reference curves and rigid-body
/// theory in gross sliding.
fn plot_chung_ooi(out_dir: &Path, oblique: &CaseOutput) -> Result<(), Box<dyn Error>> {
    let panels = [
        (
            "chung_ooi_test5",
            "psi",
            &[
                (
                    "Chung & Ooi (2011) steel (a DEM output)",
                    "chung_ooi2011_test5_steel.csv",
                ),
                (
                    "Chung & Ooi (2011) finite elements",
                    "chung_ooi2011_test5_fem.csv",
                ),
            ][..],
            "Chung & Ooi Test 5 (steel): V_s'/(mu V_n') against psi = V_s/(mu V_n)",
            ("psi", "V_s' / (mu V_n')"),
        ),
        (
            "chung_ooi_test6",
            "x",
            &[(
                "Chung & Ooi (2011) Al alloy",
                "chung_ooi2011_test6_al_alloy.csv",
            )][..],
            "Chung & Ooi Test 6 (Al alloy): beta against x = 3.5 mu (1 + e) V_n / V_s",
            ("x", "beta"),
        ),
    ];
    for (name, abscissa, references, title, labels) in panels {
        let table = oblique.table(name);
        let mut series: Vec<Series> = chung_ooi::Contact::ALL
            .iter()
            .map(|c| Series::new(c.name(), xy(table, abscissa, c.name()), Mark::Line))
            .collect();
        for (label, reference) in references {
            series.push(Series::new(*label, data_points(reference), Mark::Points));
        }
        let rigid: Vec<(f64, f64)> = table
            .column(abscissa)
            .into_iter()
            .filter_map(|x| {
                let y = if name == "chung_ooi_test5" {
                    chung_ooi::test5_rigid(x)
                } else {
                    chung_ooi::beta_rigid(x)
                };
                y.map(|y| (x, y))
            })
            .collect();
        series.push(Series::new(
            "rigid body, gross sliding",
            rigid,
            Mark::Theory,
        ));
        chart(
            &out_dir.join(format!("{name}.svg")),
            title,
            labels,
            &series,
            Axes::Linear,
        )?;
    }
    // Which spring count to pick: Test 5's distance from the finite elements against the count,
    // beside the single-spring laws' distances.
    let springs = oblique.table("chung_ooi_test5_micro_slip_springs");
    let counts = springs.column("springs");
    let (low, high) = (counts[0], counts[counts.len() - 1]);
    let fem = oblique.table("chung_ooi_test5_fem_distances");
    let mut series = vec![Series::new(
        "hertz_microslip",
        xy(springs, "springs", "rms_to_fem"),
        Mark::Line,
    )];
    for row in &fem.rows {
        if let [Cell::Text(law), Cell::Number(d)] = &row[..] {
            if law == "hertz_aa" || law == "linear_aa" {
                series.push(Series::new(
                    law.clone(),
                    vec![(low, *d), (high, *d)],
                    Mark::Theory,
                ));
            }
        }
    }
    series.push(Series::new(
        "the curve's digitisation scatter",
        vec![(low, 0.065), (high, 0.065)],
        Mark::Theory,
    ));
    chart(
        &out_dir.join("chung_ooi_test5_micro_slip_springs.svg"),
        "Chung & Ooi Test 5: RMS distance from the finite-element curve against micro-slip springs",
        ("springs across the largest contact radius", "RMS distance"),
        &series,
        Axes::LogLog,
    )?;
    Ok(())
}

fn plot_plate(out_dir: &Path, plate: &CaseOutput) -> Result<(), Box<dyn Error>> {
    let onset = rolling_onset(1.0, 0.7, 9.81);
    let times: Vec<f64> = (0..=1000).map(|i| f64::from(i) * 1e-4).collect();
    let theory_u = times
        .iter()
        .map(|&t| {
            (
                t,
                if t < onset {
                    1.0 - 0.7 * 9.81 * t
                } else {
                    5.0 / 7.0
                },
            )
        })
        .collect();
    let theory_w = times
        .iter()
        .map(|&t| {
            (
                t,
                if t < onset {
                    2.5 * 0.7 * 9.81 * t
                } else {
                    5.0 / 7.0
                },
            )
        })
        .collect();
    for (file, column, label, theory) in [
        ("plate_velocity_ratio", "velocity_ratio", "u / u0", theory_u),
        ("plate_spin_ratio", "spin_ratio", "w R / u0", theory_w),
    ] {
        let mut series: Vec<Series> = Model::ALL
            .iter()
            .map(|m| {
                let table = plate.table(&format!("plate_{}", m.name()));
                Series::new(m.name(), xy(table, "time_s", column), Mark::Line)
            })
            .collect();
        series.push(Series::new("theory", theory, Mark::Theory));
        chart(
            &out_dir.join(format!("{file}.svg")),
            &format!("Sphere sliding on a plate: {label}"),
            ("time (s)", label),
            &series,
            Axes::Linear,
        )?;
    }
    Ok(())
}

/// The worst rebound over 16 entry phases of a head-on wall impact, less the law's restitution,
/// against the step as a fraction of the stability limit (docs/physics.md, section 4.4), with
/// each law's accuracy limit marked: `accuracy_rebound.csv` and `.svg`.
fn plot_accuracy(out_dir: &Path) -> Result<(), Box<dyn Error>> {
    use host_tests::impact::{floor, incoming_sphere, wall_impact};
    use soft_sphere::prelude::{
        ContactLaw, Frictionless, Hertz, HertzImpact, LinearSpringDashpot, NormalModel,
    };

    fn sweep<N: NormalModel<f64>>(
        law: &ContactLaw<f64, N, Frictionless>,
        e: f64,
    ) -> (Vec<(f64, f64)>, f64) {
        let sphere = incoming_sphere::<f64>(2.5e-3, 2700.0, 1.0, 0.0);
        let limit = law.critical_time_step(sphere.mass);
        let points = (1..=99)
            .map(|k| {
                let fraction = f64::from(k) / 100.0;
                let dt = law
                    .coarse_time_step(fraction * limit, sphere.mass)
                    .expect("below the stability limit")
                    .tolerating_unstable_contacts();
                let worst = (0..16)
                    .map(|phase| {
                        let mut s = sphere;
                        s.position.z += dt.seconds() * (1.0 - f64::from(phase) / 16.0);
                        wall_impact(law, s, &floor(), dt, 1_000_000, |_| {})
                            .map_or(f64::NAN, |o| o.rebound.velocity.z)
                    })
                    .fold(f64::NEG_INFINITY, f64::max);
                (fraction, worst - e)
            })
            .collect();
        (points, law.accurate_time_step(sphere.mass) / limit)
    }
    let linear = |e: f64| {
        ContactLaw::new(
            LinearSpringDashpot::new(1000.0, e).expect("a law"),
            Frictionless,
        )
    };
    let hertz = |e: f64| {
        let impact = HertzImpact {
            speed: 1.0,
            effective_radius: 2.5e-3,
        };
        ContactLaw::new(
            Hertz::new(70e9 / 1.5, e, impact).expect("a law"),
            Frictionless,
        )
    };
    let mut runs = Vec::new();
    for e in [0.3, 0.7, 1.0] {
        runs.push((format!("linear e {e}"), sweep(&linear(e), e)));
    }
    runs.push(("Hertz e 0.7".to_string(), sweep(&hertz(0.7), 0.7)));
    let mut csv =
        String::from("law,fraction_of_stability_limit,worst_rebound_above_e,accurate_fraction\n");
    let mut series = Vec::new();
    let mut limits = Vec::new();
    for (name, (points, accurate)) in &runs {
        for (x, y) in points {
            csv.push_str(&format!("{name},{x},{y},{accurate}\n"));
        }
        series.push(Series::new(name.clone(), points.clone(), Mark::Line));
        limits.push((*accurate, 0.02));
    }
    series.push(Series::new("accuracy limits", limits, Mark::Points));
    series.push(Series::new(
        "0.02",
        vec![(0.0, 0.02), (1.0, 0.02)],
        Mark::Theory,
    ));
    std::fs::write(out_dir.join("accuracy_rebound.csv"), csv)?;
    chart(
        &out_dir.join("accuracy_rebound.svg"),
        "Head-on impact, worst of 16 phases: rebound above e",
        (
            "step / stability limit",
            "worst rebound - e (of the impact speed)",
        ),
        &series,
        Axes::Linear,
    )?;
    Ok(())
}
