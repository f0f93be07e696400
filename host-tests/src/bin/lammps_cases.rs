//! Writes the LAMMPS decks of the plugin checks (`examples/lammps/check.sh`) and what the Rust
//! runs give for them: the Kharaz impact with Model AA at 5..85 degrees and the plate case, the
//! same parameters and step as the `validate` run.
//!
//! It also writes Chung & Ooi's Test 5 as two identical steel spheres for LAMMPS's own
//! `pair granular hertz/material ... tangential mindlin_rescale/force`, the peer of the kernel's
//! Hertz law with `MindlinAA` (the relative motion of two identical spheres is the sphere-wall
//! case's), with what the kernel's Test 5 gives for it.
//!
//! Usage: `lammps_cases DIR PLUGIN`: writes `DIR/kharaz_ANGLE.in`, `DIR/plate.in`,
//! `DIR/chung_ooi_test5_K.in` and `DIR/expected.csv` (`case,first,second`).

use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;

use host_tests::impact::{Integrator, incoming_sphere};
use host_tests::validation::chung_ooi::{self, Contact};
use host_tests::validation::kharaz::{self, Model, TALK};
use host_tests::validation::plate;
use soft_sphere::prelude::{ContactLaw, Frictionless, LinearSpringDashpot};

/// The deck of one sphere against the floor `zplane 0`, reporting its final velocity and spin.
fn deck(
    plugin: &str,
    wall: &str,
    sphere: [f64; 8],
    (dt, steps): (f64, usize),
    gravity: bool,
) -> String {
    let [z, vx, vz, diameter, density, box_half, top, _] = sphere;
    let mut d = String::new();
    let _ = writeln!(
        d,
        "units si\natom_style sphere\natom_modify map array\nboundary f f f\ncomm_modify vel yes"
    );
    let _ = writeln!(
        d,
        "region box block {} {} {} {} -0.001 {top}",
        -box_half, box_half, -box_half, box_half
    );
    let _ = writeln!(d, "create_box 1 box\ncreate_atoms 1 single 0 0 {z:e}");
    let _ = writeln!(d, "set atom 1 diameter {diameter:e} density {density:e}");
    let _ = writeln!(d, "velocity all set {vx:e} 0 {vz:e}");
    let _ = writeln!(d, "plugin load {plugin}");
    let _ = writeln!(
        d,
        "pair_style soft/sphere frictionless 1000 0.98 0 0 0\npair_coeff * *"
    );
    let _ = writeln!(d, "neighbor 1e-4 bin");
    let _ = writeln!(d, "fix integrate all nve/sphere");
    let _ = writeln!(d, "fix floor all wall/soft/sphere {wall} zplane 0.0 NULL");
    if gravity {
        let _ = writeln!(d, "fix weight all gravity 9.81 vector 0 0 -1");
    }
    // The spin compute is current after the run because thermo invokes it on the last step.
    let _ = writeln!(
        d,
        "compute spin all property/atom omegay\nvariable u equal vx[1]\nvariable w equal c_spin[1]\n\
         variable u17 format u %.17g\nvariable w17 format w %.17g\n\
         thermo_style custom step v_u v_w\nthermo {steps}\ntimestep {dt:e}\nrun {steps}\n\
         print \"RESULT ${{u17}} ${{w17}}\""
    );
    d
}

/// The `psi` of the LAMMPS Test 5 decks: sticking, partly sliding, and sliding throughout.
const TEST5_PSI: [f64; 6] = [0.1, 1.0, 2.0, 4.0, 6.0, 10.0];

/// Test 5 at `psi` as two identical steel spheres (R = 10 mm, 7850 kg/m3, E = 208 GPa, nu = 0.3,
/// mu = 0.3, no damping) approaching at 5 m/s, in LAMMPS's own granular pair style; prints the
/// relative contact-point `V_s' / (mu V_n')`.
fn test5_deck(psi: f64) -> String {
    let half = 0.5 * psi * 0.3 * 5.0;
    format!(
        "units si\natom_style sphere\natom_modify map array\nboundary p p p\ncomm_modify vel yes\n\
         region box block -1 1 -1 1 -1 1\ncreate_box 1 box\n\
         create_atoms 1 single 0 0 0.0100000001\ncreate_atoms 1 single 0 0 -0.0100000001\n\
         set atom * diameter 0.02 density 7850\n\
         pair_style granular\n\
         pair_coeff * * hertz/material 208e9 0.0 0.3 tangential mindlin_rescale/force NULL 0.0 0.3 damping viscoelastic\n\
         neighbor 0.001 bin\n\
         set atom 1 vx {half:e} vz -2.5\nset atom 2 vx {minus:e} vz 2.5\n\
         fix integrate all nve/sphere\ntimestep 2e-9\n\
         compute spin all property/atom omegay\n\
         variable ratio equal ((vx[1]-c_spin[1]*0.01)-(vx[2]+c_spin[2]*0.01))/(0.3*(vz[1]-vz[2]))\n\
         variable r17 format ratio %.17g\n\
         thermo_style custom step v_ratio\nthermo 40000\nrun 40000\nprint \"RESULT ${{r17}}\"\n",
        minus = -half
    )
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let (Some(dir), Some(plugin)) = (args.next(), args.next()) else {
        return Err("usage: lammps_cases DIR PLUGIN".into());
    };
    let dir = PathBuf::from(dir);
    std::fs::create_dir_all(&dir)?;
    let mut expected = String::from("case,first,second\n");
    let setup = &TALK;
    let law = ContactLaw::new(
        LinearSpringDashpot::new(setup.normal_stiffness, setup.restitution)?,
        Frictionless,
    );
    for angle in (5..=85).step_by(5) {
        let angle = f64::from(angle);
        let sphere = incoming_sphere(setup.radius, setup.density, setup.speed, angle);
        // The validation run's step: t_c / 50 of the sphere against the wall.
        let dt = law.contact_duration(sphere.mass) / 50.0;
        let o = kharaz::impact(
            Model::ModelAA,
            setup,
            angle,
            50.0,
            Integrator::SymplecticEuler,
        );
        let _ = writeln!(
            expected,
            "kharaz_{angle},{:e},{:e}",
            o.tangential_cor, o.spin
        );
        let wall = format!(
            "aa {} {} {} {} {}",
            setup.normal_stiffness,
            setup.restitution,
            setup.tangential_stiffness,
            setup.dashpot_ratio,
            setup.friction
        );
        let geometry = [
            setup.radius,
            sphere.velocity.x,
            sphere.velocity.z,
            2.0 * setup.radius,
            setup.density,
            0.05,
            0.05,
            0.0,
        ];
        std::fs::write(
            dir.join(format!("kharaz_{angle}.in")),
            deck(&plugin, &wall, geometry, (dt, 150), false),
        )?;
        // The incoming velocity, to turn LAMMPS's final velocity into e_t.
        let _ = writeln!(expected, "incoming_{angle},{:e},0", sphere.velocity.x);
    }
    let (dt, steps, start) = plate::timing();
    let run = plate::slide(Model::ModelAA);
    let last = run.series.last().ok_or("an empty plate run")?;
    let _ = writeln!(expected, "plate,{:e},{:e}", last[1], last[2]);
    let wall = format!(
        "aa {} {} {} {} {}",
        plate::NORMAL_STIFFNESS,
        plate::RESTITUTION,
        plate::TANGENTIAL_STIFFNESS,
        plate::DASHPOT_RATIO,
        plate::FRICTION
    );
    let geometry = [
        start,
        plate::INITIAL_SPEED,
        0.0,
        2.0 * plate::RADIUS,
        plate::DENSITY,
        0.2,
        0.05,
        0.0,
    ];
    std::fs::write(
        dir.join("plate.in"),
        deck(&plugin, &wall, geometry, (dt, steps), true),
    )?;
    for (k, psi) in TEST5_PSI.iter().enumerate() {
        // Fine steps: LAMMPS runs about 22000 per contact.
        let ratio = chung_ooi::test5_spheres(Contact::HertzAA, *psi, 8000.0);
        let _ = writeln!(expected, "chung_ooi_test5_{k},{psi:e},{ratio:e}");
        std::fs::write(
            dir.join(format!("chung_ooi_test5_{k}.in")),
            test5_deck(*psi),
        )?;
    }
    std::fs::write(dir.join("expected.csv"), expected)?;
    eprintln!("wrote the decks and expected.csv into {}", dir.display());
    Ok(())
}
