use host_tests::{data, impact::oblique_rebound};
use soft_sphere::*;
fn main() {
    let normal = LinearSpringDashpot::new(1.72e7, 1.0).unwrap();
    let p = TangentialParameters::new(1.48e7, 0.0, 0.092).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p));
    let lawp = law.with_lever_arm(LeverArm::ContactPlane);
    for row in data::rows("linear_model_reference_mfix_dem05.csv") {
        let a = row[0];
        let r50 = oblique_rebound(&law, 2.5e-3, 4000.0, 3.9, a, 50.0, |_| {});
        let r1k = oblique_rebound(&law, 2.5e-3, 4000.0, 3.9, a, 1000.0, |_| {});
        let p50 = oblique_rebound(&lawp, 2.5e-3, 4000.0, 3.9, a, 50.0, |_| {});
        println!(
            "{a:5}: mfix {:.4} {:8.3} | R/50 {:.4} ({:+.2}%) {:8.3} ({:+.2}%) | R/1000 {:.4} ({:+.2}%) {:+.2}% | plane/50 {:.4} ({:+.2}%) ({:+.2}%)",
            row[1],
            row[2],
            r50.tangential_restitution,
            100.0 * (r50.tangential_restitution / row[1] - 1.0),
            r50.spin,
            100.0 * (r50.spin / row[2] - 1.0),
            r1k.tangential_restitution,
            100.0 * (r1k.tangential_restitution / row[1] - 1.0),
            100.0 * (r1k.spin / row[2] - 1.0),
            p50.tangential_restitution,
            100.0 * (p50.tangential_restitution / row[1] - 1.0),
            100.0 * (p50.spin / row[2] - 1.0)
        );
    }
}
