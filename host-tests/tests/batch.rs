//! The batch path (`BoundLaw::sphere_pairs`) against one contact at a time: for every slot, both
//! precisions, both lever arms, with and without rotation, on both square-root routes (`Libm` and
//! `Std`), every lane must give the same bits, the same state and the same error as the pair
//! evaluated alone, whichever lane it sits in and whatever its neighbours are. The one-contact
//! path is the peer: its own physics is checked by the other test files.

use host_tests::pairs::{Pair, in_blocks, one_at_a_time};
use host_tests::strategies::{Collision, collision, config};
use proptest::prelude::*;
use soft_sphere::batch::{BlockGroup, BlockPairs, ContactBlock, LANES, PairBlock};
use soft_sphere::{
    CheckedSphere, ContactError, ContactLaw, Float, Frictionless, Hertz, HertzImpact, Interaction,
    Law, LeverArm, LinearAA, LinearSpringDashpot, MathBackend, MindlinAA, MindlinAALuding,
    MindlinParameters, MindlinSpring, MindlinStateless, ModelA, ModelAA, ModelAALuding, ModelB,
    ModelC, NormalModel, Sphere, SpringDisplacement, Stateless, Std, TangentialModel,
    TangentialParameters, Vec3,
};

/// Runs `steps` steps of the same pairs one at a time (law `one`) and in blocks of `N` (law
/// `block`), from the same states, and demands the same bits for every outcome and state.
fn same_bits<A: Law, B: Law<Float = A::Float, State = A::State>, const N: usize>(
    one: &A,
    block: &B,
    pairs: &[Pair<A::Float>],
    states: &[A::State],
    steps: usize,
) -> Result<(), String> {
    let seconds = <A::Float as Float>::from_f64(1e-7);
    let (Ok(dt_one), Ok(dt_block)) = (
        one.time_step(seconds, <A::Float as Float>::ONE),
        block.time_step(seconds, <A::Float as Float>::ONE),
    ) else {
        return Err("the test's step is unstable".into());
    };
    let (mut a, mut b) = (states.to_vec(), states.to_vec());
    for step in 0..steps {
        let before = a.clone();
        let x = one_at_a_time(one, dt_one, pairs, &mut a);
        let y = in_blocks::<_, N>(block, dt_block, pairs, &mut b);
        // Debug prints the shortest decimal that reads back to the same float: equal text is
        // equal bits, -0.0 included.
        for (k, (x, y)) in x.iter().zip(&y).enumerate() {
            if format!("{x:?}") != format!("{y:?}") {
                return Err(format!("step {step}, pair {k}: one {x:?}, block {y:?}"));
            }
            if format!("{:?}", a[k]) != format!("{:?}", b[k]) {
                return Err(format!(
                    "step {step}, pair {k}: state {:?} vs {:?}",
                    a[k], b[k]
                ));
            }
            if x.is_err() && format!("{:?}", before[k]) != format!("{:?}", b[k]) {
                return Err(format!(
                    "step {step}, pair {k}: a failed lane changed its state"
                ));
            }
        }
    }
    Ok(())
}

/// One pair per status path, each in a pair of 1 mm spheres (`F` precision).
fn status_paths<F: Float>() -> Vec<(&'static str, Sphere<F>, Sphere<F>)> {
    let f = F::from_f64;
    let at = |x: f64, y: f64| Sphere::solid(Vec3::new(f(x), f(y), F::ZERO), f(5e-4), f(2500.0));
    let base = at(0.0, 0.0);
    let mut paths = Vec::new();
    let mut add = |name, i: Sphere<F>, j: Sphere<F>| paths.push((name, i, j));
    let mut stick = at(0.99e-3, 0.0);
    stick.velocity = Vec3::new(f(-0.01), f(1e-4), F::ZERO);
    add("stick", base, stick);
    let mut slide = at(0.99e-3, 0.0);
    slide.velocity = Vec3::new(f(-0.01), f(5.0), f(1.0));
    add("slide", base, slide);
    let mut spin = at(0.7e-3, 0.7e-3);
    spin.angular_velocity = Vec3::new(f(300.0), f(-200.0), f(100.0));
    spin.velocity = Vec3::new(f(0.3), f(-0.2), f(0.1));
    add("spinning, off axis", base, spin);
    let mut light = Sphere::solid(Vec3::new(f(0.85e-3), F::ZERO, F::ZERO), f(4e-4), f(1000.0));
    light.velocity = Vec3::new(f(-0.5), f(50.0), F::ZERO);
    add("another mass and radius", base, light);
    add("apart", base, at(1.5e-3, 0.0));
    add("at the sum of the radii", base, at(1.0e-3, 0.0));
    add("coincident", base, at(0.0, 0.0));
    let mut nan = base;
    nan.position.y = f(f64::NAN);
    add("NaN in i", nan, at(0.99e-3, 0.0));
    let mut infinite = at(0.99e-3, 0.0);
    infinite.angular_velocity.z = F::INFINITY;
    add("infinite spin in j", base, infinite);
    let mut no_radius = base;
    no_radius.radius = F::ZERO;
    add("zero radius in i", no_radius, at(0.99e-3, 0.0));
    let mut negative = at(0.99e-3, 0.0);
    negative.mass = f(-1.0);
    add("negative mass in j", base, negative);
    let mut both = base;
    both.mass = F::ZERO;
    let mut bad_j = at(0.0, 0.0);
    bad_j.position.x = F::INFINITY;
    add("i's mass before j's infinity", both, bad_j);
    let mut huge = at(0.99e-3, 0.0);
    // Finite velocities whose difference overflows.
    let big = if size_of::<F>() == 4 { 3e38 } else { 1.7e308 };
    huge.velocity = Vec3::new(f(-big), f(big), F::ZERO);
    let mut fast = base;
    fast.velocity = Vec3::new(f(big), F::ZERO, F::ZERO);
    add("finite input, force overflows", fast, huge);
    let mut feather = at(0.99e-3, 0.0);
    feather.mass = f(1e-15);
    add("too light for the step", base, feather);
    paths
}

/// A stored displacement for the stored-spring laws, so that reset, kept and advanced differ.
trait Preloaded: Sized {
    fn preloaded(k: usize) -> Self;
}

impl Preloaded for () {
    fn preloaded(_: usize) -> Self {}
}

impl<F: Float> Preloaded for MindlinSpring<F> {
    fn preloaded(k: usize) -> Self {
        let s = F::from_f64(1e-7 * (k as f64 + 1.0));
        Self {
            force: Vec3::new(F::ZERO, s, -s),
            contact_radius: F::from_f64(2e-5 * (k % 3) as f64),
        }
    }
}

impl<F: Float> Preloaded for SpringDisplacement<F> {
    fn preloaded(k: usize) -> Self {
        let s = F::from_f64(1e-7 * (k as f64 + 1.0));
        Self {
            displacement: Vec3::new(F::ZERO, s, -s),
        }
    }
}

/// Every status path in every lane position: the list, then the list rotated by one, two and
/// three places, in blocks of 1, 3, [`LANES`] and 8.
fn every_status_for<F: Float, N: NormalModel<F>, T: TangentialModel<F>>(
    name: &str,
    law: ContactLaw<F, N, T>,
) -> Result<(), String>
where
    T::State: Preloaded,
    Std: MathBackend<F>,
{
    let paths = status_paths::<F>();
    let mut pairs: Vec<_> = paths.iter().map(|(_, i, j)| (*i, *j)).collect();
    for shift in 0..4 {
        pairs.rotate_left(shift);
        let states: Vec<T::State> = (0..pairs.len()).map(T::State::preloaded).collect();
        for lever in [LeverArm::Radius, LeverArm::ContactPlane] {
            let one = law.with_lever_arm(lever);
            let std = one.with_backend::<Std>();
            let context = |e: String| format!("{name}, {lever:?}, rotated {shift}: {e}");
            same_bits::<_, _, 1>(&one, &one, &pairs, &states, 3).map_err(context)?;
            same_bits::<_, _, 3>(&one, &one, &pairs, &states, 3).map_err(context)?;
            same_bits::<_, _, LANES>(&one, &std, &pairs, &states, 3).map_err(context)?;
            same_bits::<_, _, 8>(&one, &std, &pairs, &states, 3).map_err(context)?;
            let flat = one.without_rotation();
            same_bits::<_, _, LANES>(&flat, &flat.with_backend::<Std>(), &pairs, &states, 3)
                .map_err(context)?;
        }
    }
    Ok(())
}

fn every_status<F: Float>() -> Result<(), String>
where
    Std: MathBackend<F>,
{
    let f = F::from_f64;
    let normal = LinearSpringDashpot::new(f(1000.0), f(0.7)).unwrap();
    let p = TangentialParameters::new(f(285.7), f(0.5), f(0.4)).unwrap();
    every_status_for::<F, _, _>("frictionless", ContactLaw::new(normal, Frictionless))?;
    every_status_for::<F, _, _>("stateless", ContactLaw::new(normal, Stateless(p)))?;
    every_status_for::<F, _, _>("model_c", ContactLaw::new(normal, ModelC(p)))?;
    every_status_for::<F, _, _>("model_a", ContactLaw::new(normal, ModelA(p)))?;
    every_status_for::<F, _, _>("model_b", ContactLaw::new(normal, ModelB(p)))?;
    every_status_for::<F, _, _>("model_aa", ContactLaw::new(normal, ModelAA(p)))?;
    every_status_for::<F, _, _>("model_aa_luding", ContactLaw::new(normal, ModelAALuding(p)))?;
    let clamped = LinearSpringDashpot::clamped_with_rebound(f(1000.0), f(0.7)).unwrap();
    every_status_for::<F, _, _>("model_aa clamped", ContactLaw::new(clamped, ModelAA(p)))?;
    let largest = HertzImpact {
        speed: f(1.0),
        effective_radius: f(1e-3),
    };
    let hertz = Hertz::new(f(5.0e5), f(0.7), largest).unwrap();
    let mindlin = MindlinParameters::new(f(2.0e5), f(0.5), f(0.4)).unwrap();
    every_status_for::<F, _, _>("hertz frictionless", ContactLaw::new(hertz, Frictionless))?;
    every_status_for::<F, _, _>("mindlin_aa", ContactLaw::new(hertz, MindlinAA(mindlin)))?;
    every_status_for::<F, _, _>(
        "mindlin_aa_luding",
        ContactLaw::new(hertz, MindlinAALuding(mindlin)),
    )?;
    every_status_for::<F, _, _>(
        "mindlin_stateless",
        ContactLaw::new(hertz, MindlinStateless(mindlin)),
    )?;
    Ok(())
}

#[test]
fn every_status_path_gives_the_one_contact_bits_f64() {
    every_status::<f64>().unwrap();
}

#[test]
fn every_status_path_gives_the_one_contact_bits_f32() {
    every_status::<f32>().unwrap();
}

/// The paths' outcomes as documented, read from the block itself: the list above really covers
/// sticking, sliding, apart and each error, so the comparison cannot pass on a list that misses
/// them.
#[test]
fn the_status_paths_are_the_documented_ones() {
    let normal = LinearSpringDashpot::new(1000.0, 0.7).unwrap();
    let p = TangentialParameters::new(285.7, 0.5, 0.4).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p)).with_backend::<Std>();
    let dt = law.time_step(1e-7, 1.0).unwrap();
    let mut bound = law.at(dt);
    let mut out = ContactBlock::<f64, 1>::default();
    for (name, i, j) in status_paths::<f64>() {
        let mut block = PairBlock::default();
        block.set(0, &i, &j);
        let before = [SpringDisplacement::preloaded(0)];
        let mut states = before;
        bound.sphere_pairs(&block, &mut states, &mut out);
        let outcome = out.outcome(0);
        let expected: Result<Option<bool>, ContactError> = match name {
            "stick" | "spinning, off axis" => Ok(Some(false)),
            "slide" | "another mass and radius" => Ok(Some(true)),
            "apart" | "at the sum of the radii" => Ok(None),
            "coincident" => Err(ContactError::CoincidentCentres),
            "NaN in i" | "infinite spin in j" => Err(ContactError::NonFiniteInput),
            "zero radius in i" => Err(ContactError::NonPositiveRadius),
            "negative mass in j" | "i's mass before j's infinity" => {
                Err(ContactError::NonPositiveMass)
            }
            "finite input, force overflows" => Err(ContactError::NonFiniteResult),
            "too light for the step" => Err(ContactError::PastStableStep),
            other => panic!("unlisted path {other}"),
        };
        let got = outcome.map(|o| o.forces().map(|f| f.sliding));
        assert_eq!(got, expected, "{name}");
        match outcome {
            Ok(Interaction::Apart) => {
                assert_eq!(states[0], SpringDisplacement::default(), "{name}")
            }
            Err(_) => assert_eq!(states, before, "{name}: a failed lane keeps its state"),
            Ok(Interaction::Touching(forces)) => {
                let f = out.force_on_j(0);
                assert!(f.norm_squared() > 0.0, "{name}: a touching pair pushes");
                // The block's total force is the contact's: normal part plus tangential part.
                let expected = forces.normal * forces.normal_force + forces.tangential_force;
                assert_eq!(f, expected, "{name}");
                assert_eq!(f, forces.force_on_j(), "{name}");
            }
        }
        assert_eq!(
            out.touching(0),
            matches!(outcome, Ok(Interaction::Touching(_))),
            "{name}: touching() agrees with the outcome"
        );
        if !matches!(outcome, Ok(Interaction::Touching(_))) {
            assert_eq!(
                out.force_on_j(0),
                Vec3::ZERO,
                "{name}: no force where nothing touches"
            );
        }
    }
}

/// A step that tolerates contacts past its limit evaluates them in a block as one at a time
/// does, with the same bits, and both count the same contacts.
#[test]
fn a_tolerating_step_counts_the_same_contacts_in_blocks() {
    let normal = LinearSpringDashpot::new(1000.0, 0.7).unwrap();
    let p = TangentialParameters::new(285.7, 0.5, 0.4).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p)).with_backend::<Std>();
    let dt = law
        .time_step(1e-7, 1.0)
        .unwrap()
        .tolerating_unstable_contacts();
    let paths = status_paths::<f64>();
    let (mut one, mut blocks) = (law.at(dt), law.at(dt));
    let mut out = ContactBlock::<f64, LANES>::default();
    for chunk in paths.chunks(LANES) {
        let mut block = PairBlock::default();
        let mut states = [SpringDisplacement::preloaded(0); LANES];
        let mut singles = states;
        for (lane, (_, i, j)) in chunk.iter().enumerate() {
            block.set(lane, i, j);
        }
        blocks.sphere_pairs(&block, &mut states, &mut out);
        for (lane, (name, i, j)) in chunk.iter().enumerate() {
            let outcome = CheckedSphere::new(*i).and_then(|i| {
                let j = CheckedSphere::new(*j)?;
                one.sphere_sphere(&i, &j, &mut singles[lane])
            });
            assert_eq!(out.outcome(lane), outcome, "{name}");
            assert_eq!(states[lane], singles[lane], "{name}");
            if *name == "too light for the step" {
                assert!(matches!(outcome, Ok(Interaction::Touching(_))), "{name}");
            }
        }
    }
    assert_eq!(one.inaccurate_contacts(), 1);
    assert_eq!(blocks.inaccurate_contacts(), 1);
}

/// A host's pairs for [`BlockGroup`]: each place's spheres and state, and what was scattered
/// to it, in order.
struct Places {
    pairs: Vec<(Sphere<f64>, Sphere<f64>)>,
    states: Vec<SpringDisplacement<f64>>,
    scattered: Vec<(usize, Result<Interaction<f64>, ContactError>)>,
}

impl<L: Law<Float = f64, State = SpringDisplacement<f64>>> BlockPairs<L> for Places {
    fn gather(&self, k: usize) -> (Sphere<f64>, Sphere<f64>, SpringDisplacement<f64>) {
        (self.pairs[k].0, self.pairs[k].1, self.states[k])
    }

    fn scatter(
        &mut self,
        k: usize,
        outcome: Result<Interaction<f64>, ContactError>,
        state: &SpringDisplacement<f64>,
    ) {
        self.states[k] = *state;
        self.scattered.push((k, outcome));
    }
}

/// A group of blocks over a host's arrays, for runs longer and shorter than the group holds
/// (3, 8 x [`LANES`] and more, never a whole number of blocks in the longest) and places in
/// any order: each named place scattered once, in the order named, with the outcome and state
/// the pair alone gives (errors keeping their state), and no other place read or written.
#[test]
fn a_block_group_gives_each_place_the_one_contact_outcome() {
    let normal = LinearSpringDashpot::new(1000.0, 0.7).unwrap();
    let p = TangentialParameters::new(285.7, 0.5, 0.4).unwrap();
    let law = ContactLaw::new(normal, ModelAA(p)).with_backend::<Std>();
    let dt = law.time_step(1e-7, 1.0).unwrap();
    let paths: Vec<_> = status_paths::<f64>()
        .iter()
        .map(|&(_, i, j)| (i, j))
        .collect();
    let pairs: Vec<_> = paths
        .iter()
        .cycle()
        .take(5 * paths.len() + 3)
        .copied()
        .collect();
    assert!(pairs.len() > 8 * LANES && pairs.len() % LANES != 0);
    let states: Vec<_> = (0..pairs.len())
        .map(SpringDisplacement::preloaded)
        .collect();
    let mut group = BlockGroup::default();
    let every: Vec<usize> = (0..pairs.len()).rev().collect();
    let odd: Vec<usize> = (1..pairs.len()).step_by(2).collect();
    for places in [&every[..], &odd[..], &[7, 2, 40][..], &[][..]] {
        let mut host = Places {
            pairs: pairs.clone(),
            states: states.clone(),
            scattered: Vec::new(),
        };
        let mut bound = law.at(dt);
        group.evaluate(&mut bound, places.iter().copied(), &mut host);
        let order: Vec<usize> = host.scattered.iter().map(|&(k, _)| k).collect();
        assert_eq!(order, places, "each place once, in order");
        let mut one = law.at(dt);
        for (k, outcome) in &host.scattered {
            let mut state = states[*k];
            let (i, j) = pairs[*k];
            let alone = CheckedSphere::new(i).and_then(|i| {
                let j = CheckedSphere::new(j)?;
                one.sphere_sphere(&i, &j, &mut state)
            });
            assert_eq!(format!("{outcome:?}"), format!("{alone:?}"), "place {k}");
            assert_eq!(host.states[*k], state, "place {k}");
        }
        for k in (0..pairs.len()).filter(|k| !places.contains(k)) {
            assert_eq!(host.states[k], states[k], "place {k} was not named");
        }
        let errors = host.scattered.iter().filter(|(_, o)| o.is_err()).count();
        assert!(places.len() < 4 || errors > 0, "the run holds bad pairs");
    }
}

/// The law of a random collision: `k_n` from its overlap fraction, the rest from its material.
fn law_of<F: Float>(c: &Collision) -> LinearAA<F> {
    let (i, j) = c.pair::<f64>();
    let k_n = c.normal_stiffness(i.mass * j.mass / (i.mass + j.mass));
    let m = c.material;
    let f = F::from_f64;
    ContactLaw::new(
        LinearSpringDashpot::new(f(k_n), f(m.restitution)).unwrap(),
        ModelAA(
            TangentialParameters::new(
                f(m.stiffness_ratio * k_n),
                f(m.dashpot_ratio),
                f(m.friction),
            )
            .unwrap(),
        ),
    )
}

/// Random collisions pushed into overlap, blocks of them under one random law, several steps.
fn random_blocks<F: Float>(input: &(Vec<Collision>, Vec<f64>)) -> Result<(), TestCaseError>
where
    Std: MathBackend<F>,
{
    let (collisions, depths) = input;
    let law = law_of::<F>(&collisions[0]);
    let pairs: Vec<_> = collisions
        .iter()
        .zip(depths)
        .map(|(c, depth)| {
            let (i, mut j) = c.pair::<F>();
            // Into overlap along the line of centres, by up to 2 % of the smaller radius.
            let reach = (i.radius + j.radius).to_f64();
            let keep = F::from_f64(1.0 - depth * 0.02 * i.radius.min_of(j.radius).to_f64() / reach);
            j.position = j.position * keep;
            (i, j)
        })
        .collect();
    let states = vec![SpringDisplacement::default(); pairs.len()];
    let std = law.with_backend::<Std>();
    same_bits::<_, _, LANES>(&law, &std, &pairs, &states, 5).map_err(TestCaseError::fail)?;
    let plane = law.with_lever_arm(LeverArm::ContactPlane);
    same_bits::<_, _, 8>(&plane, &plane.with_backend::<Std>(), &pairs, &states, 5)
        .map_err(TestCaseError::fail)?;
    Ok(())
}

fn collisions() -> impl Strategy<Value = (Vec<Collision>, Vec<f64>)> {
    (1usize..20).prop_flat_map(|n| {
        (
            prop::collection::vec(collision(), n),
            prop::collection::vec(0.0..1.0f64, n),
        )
    })
}

proptest! {
    #![proptest_config(config())]
    #[test]
    fn random_blocks_give_the_one_contact_bits_f64(input in collisions()) {
        random_blocks::<f64>(&input)?;
    }
    #[test]
    fn random_blocks_give_the_one_contact_bits_f32(input in collisions()) {
        random_blocks::<f32>(&input)?;
    }
    /// Arbitrary bit patterns in every field of every lane: never a panic, and each lane what
    /// the pair alone gives.
    #[test]
    fn arbitrary_bits_give_the_one_contact_outcome(bits in prop::collection::vec(any::<u64>(), 22 * 5)) {
        let x = |k: usize| f64::from_bits(bits[k]);
        let sphere = |k: usize| Sphere {
            position: Vec3::new(x(k), x(k + 1), x(k + 2)),
            velocity: Vec3::new(x(k + 3), x(k + 4), x(k + 5)),
            angular_velocity: Vec3::new(x(k + 6), x(k + 7), x(k + 8)),
            radius: x(k + 9),
            mass: x(k + 10),
        };
        let pairs: Vec<_> = (0..5).map(|l| (sphere(22 * l), sphere(22 * l + 11))).collect();
        let normal = LinearSpringDashpot::new(1000.0, 0.7).unwrap();
        let p = TangentialParameters::new(285.7, 0.5, 0.4).unwrap();
        let law = ContactLaw::new(normal, ModelAA(p));
        let states = vec![SpringDisplacement::preloaded(1); pairs.len()];
        same_bits::<_, _, LANES>(&law, &law.with_backend::<Std>(), &pairs, &states, 1)
            .map_err(TestCaseError::fail)?;
    }
}
