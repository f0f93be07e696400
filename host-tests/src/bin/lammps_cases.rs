//! Writes the LAMMPS decks of the plugin checks (`examples/lammps/check.sh`) and what the Rust
//! runs give for them: the Kharaz impact with Model AA at 5..85 degrees and the plate case, the
//! same parameters and step as the `validate` run.
//!
//! Usage: `lammps_cases DIR PLUGIN`: writes `DIR/kharaz_ANGLE.in`, `DIR/plate.in`, and
//! `DIR/expected.csv` (`case,e_t_or_u,spin_or_w`).

use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;

use host_tests::impact::{Integrator, incoming_sphere};
use host_tests::validation::kharaz::{self, Model, TALK};
use host_tests::validation::plate;
use soft_sphere::{ContactLaw, Frictionless, LinearSpringDashpot};

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
    std::fs::write(dir.join("expected.csv"), expected)?;
    eprintln!("wrote the decks and expected.csv into {}", dir.display());
    Ok(())
}
