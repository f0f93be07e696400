//! Every tolerance the validation run holds the kernel to, and every known departure, as one
//! table in code (as libm keeps its `precision.rs`). The values are the cases' own constants;
//! `docs/validation.md` quotes [`markdown`], and a test fails when the quote is stale.

use super::{chung_ooi, kharaz, micro_slip, normal, plate, rolling};

/// How a bound is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Measure {
    /// Relative to the reference value.
    Relative,
    /// In the quantity's own units.
    Absolute,
    /// The RMS distance between curves, absolute.
    Rms,
}

/// One enforced bound.
#[derive(Clone, Copy, Debug)]
pub struct Tolerance {
    /// The case (`docs/physics.md`, section 5).
    pub case: &'static str,
    /// What is compared, against what.
    pub check: &'static str,
    /// The bound.
    pub bound: f64,
    /// How the bound is measured.
    pub measure: Measure,
    /// Empty for a bound the physics asks; otherwise why the bound is looser (a known
    /// departure, explained in `docs/validation.md`).
    pub departure: &'static str,
}

const fn bound(case: &'static str, check: &'static str, bound: f64, measure: Measure) -> Tolerance {
    Tolerance {
        case,
        check,
        bound,
        measure,
        departure: "",
    }
}

const fn departure(
    case: &'static str,
    check: &'static str,
    bound: f64,
    measure: Measure,
    departure: &'static str,
) -> Tolerance {
    Tolerance {
        case,
        check,
        bound,
        measure,
        departure,
    }
}

use Measure::{Absolute, Relative, Rms};

/// The table.
pub const TOLERANCES: &[Tolerance] = &[
    bound(
        "normal impact",
        "rebound ratio against `e`, `t_c/1000`",
        normal::REBOUND_TOLERANCE,
        Absolute,
    ),
    bound(
        "normal impact",
        "contact duration against `t_c`",
        normal::DURATION_TOLERANCE,
        Relative,
    ),
    bound(
        "Kharaz",
        "`e_t`, spin, rebound angle at `t_c/50` against `t_c/1000`",
        kharaz::CONVERGENCE_TOLERANCE,
        Relative,
    ),
    departure(
        "Kharaz",
        "the same below 3 deg",
        kharaz::SMALL_ANGLE_CONVERGENCE_TOLERANCE,
        Relative,
        "the spin is under 3 % of its peak; the exit step moves it by up to 0.7 %",
    ),
    bound(
        "Kharaz",
        "`e_t` and spin above the sliding threshold against rigid-body theory",
        kharaz::SLIDING_TOLERANCE,
        Relative,
    ),
    bound(
        "Kharaz",
        "stateless law below the threshold against rigid-body theory",
        kharaz::STATELESS_TOLERANCE,
        Relative,
    ),
    bound(
        "MFiX DEM05",
        "Model AA `e_t` against MFiX, from 25 deg",
        kharaz::MFIX_TOLERANCE[0],
        Relative,
    ),
    bound(
        "MFiX DEM05",
        "Model AA spin against MFiX, from 25 deg",
        kharaz::MFIX_TOLERANCE[1],
        Relative,
    ),
    bound(
        "MFiX DEM05",
        "Model AA `e_t` against MFiX, 5-25 deg",
        kharaz::MFIX_MEDIUM_ANGLE_TOLERANCE[0],
        Relative,
    ),
    bound(
        "MFiX DEM05",
        "Model AA spin against MFiX, 5-25 deg",
        kharaz::MFIX_MEDIUM_ANGLE_TOLERANCE[1],
        Relative,
    ),
    departure(
        "MFiX DEM05",
        "Model AA `e_t` against MFiX, below 5 deg",
        kharaz::MFIX_SMALL_ANGLE_BOUND[0],
        Relative,
        "MFiX's published small-angle values depend on the entry phase",
    ),
    departure(
        "MFiX DEM05",
        "Model AA spin against MFiX, below 5 deg",
        kharaz::MFIX_SMALL_ANGLE_BOUND[1],
        Relative,
        "as above",
    ),
    bound(
        "plate",
        "final `u/u0` and `w R/u0` against 5/7",
        plate::RATIO_TOLERANCE,
        Relative,
    ),
    bound(
        "plate",
        "rolling onset against `2 u0 / (7 mu g)`",
        plate::ONSET_TOLERANCE,
        Relative,
    ),
    bound(
        "rolling resistance",
        "stop time and distance, acceleration down a slope",
        rolling::TOLERANCE,
        Relative,
    ),
    bound(
        "rolling resistance",
        "creep of a sphere held on a slope (m/s)",
        rolling::CREEP_BOUND,
        Absolute,
    ),
    bound(
        "Chung & Ooi 1-2",
        "peak overlap, duration, force-overlap curve against Hertz",
        chung_ooi::HERTZ_TOLERANCE,
        Relative,
    ),
    bound(
        "Chung & Ooi 3",
        "rebound ratio against the input `e` (absolute at `e` = 0)",
        chung_ooi::RESTITUTION_TOLERANCE,
        Relative,
    ),
    bound(
        "Chung & Ooi 4",
        "`e_t` in gross sliding against rigid-body theory",
        chung_ooi::SLIDING_TOLERANCE,
        Relative,
    ),
    bound(
        "Chung & Ooi 5",
        "gross sliding against rigid-body theory, `e` = 1",
        chung_ooi::ELASTIC_SLIDING_TOLERANCE,
        Rms,
    ),
    bound(
        "Chung & Ooi 7",
        "contact points moving together: tangential velocity against zero (m/s)",
        chung_ooi::NO_EXCHANGE_TOLERANCE,
        Absolute,
    ),
    bound(
        "Chung & Ooi 7",
        "contact points moving together: spin kept",
        chung_ooi::NO_EXCHANGE_TOLERANCE,
        Relative,
    ),
    departure(
        "Chung & Ooi 6, 8",
        "gross sliding against rigid-body theory, `e` = 0.5; Test 6 at 16x LIGGGHTS' dashpot against the overdamped limit",
        chung_ooi::DAMPED_SLIDING_TOLERANCE,
        Rms,
        "the Coulomb limit includes the normal dashpot",
    ),
    bound(
        "Chung & Ooi 5",
        "Hertz-Mindlin against LAMMPS `pair granular` (peer)",
        chung_ooi::PEER_TOLERANCE,
        Absolute,
    ),
    bound(
        "Chung & Ooi 5",
        "micro-slip against the finite-element curve",
        chung_ooi::MICRO_SLIP_FEM_TOLERANCE,
        Rms,
    ),
    departure(
        "Chung & Ooi 6",
        "micro-slip with LIGGGHTS' dashpot against the Al alloy curve",
        chung_ooi::MICRO_SLIP_TEST6_TOLERANCE,
        Rms,
        "0.152 measured: the curve (a DEM output) reverses where a stuck contact does not",
    ),
    bound(
        "micro-slip cycles",
        "loop energy against Mindlin & Deresiewicz, every `tau`, breakpoint count and contact size",
        micro_slip::LOOP_ENERGY_TOLERANCE,
        Relative,
    ),
];

/// The table as Markdown, as `docs/validation.md` quotes it.
pub fn markdown() -> String {
    let mut out =
        String::from("| case | check | bound | measured as | departure |\n|---|---|---|---|---|\n");
    for t in TOLERANCES {
        let measure = match t.measure {
            Relative => "relative",
            Absolute => "absolute",
            Rms => "RMS",
        };
        let departure = if t.departure.is_empty() {
            ""
        } else {
            t.departure
        };
        out.push_str(&format!(
            "| {} | {} | {:e} | {measure} | {departure} |\n",
            t.case, t.check, t.bound
        ));
    }
    out
}
