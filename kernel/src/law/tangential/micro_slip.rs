//! Micro-slip under a [`Hertz`](crate::Hertz) contact: Mindlin & Deresiewicz's tangential
//! contact, computed by Popov & Heß's method of dimensionality reduction (MDR).
//!
//! The axisymmetric contact becomes a bed of independent springs along a line, on the profile
//! `g(x) = x^2 / R*`. The spring at `x` presses with `E* (delta - g(x)) dx` (their sum is Hertz's
//! `(4/3) E* a delta`), shears with stiffness `8 G* dx` for both sides of the line (their sum is
//! Mindlin's `8 G* a`) and slips on its own once its shear reaches `mu` times its press: its
//! displacement stays within `l(t) = delta_s (1 - t^2)`, `t = x / a`, `delta_s = 3 mu |F_n| /
//! (16 G* a)` the full-slip displacement. A spring that comes into contact starts free of shear
//! (Maw, Barber & Fawcett 1976); one that leaves takes its shear with it (`docs/physics.md`,
//! section 3.3).
//!
//! Every spring sees the same tangential motion, so along one direction the displacement is a
//! function of a spring's limit alone: piecewise linear in `lambda = 1 - t^2`, with kinks only
//! at the slip fronts that Masing's turning points leave. The bed keeps that profile as up to
//! `SPRINGS` breakpoints, which follow the fronts as they move and the contact as it grows and
//! shrinks (a contact radius `a` to `a'` scales every position by `a / a'`, which keeps the
//! profile linear in `lambda`): exact along one direction at a steady load while the turning
//! points fit, whatever the contact's size. Where a step turns the springs of a slipping
//! stretch apart, the spring midway becomes a breakpoint too; where the breakpoints do not
//! suffice (more remembered turning points than room, a direction that keeps turning, a
//! changing normal load), the one whose removal changes the profile least is dropped.

use super::{
    ContactState, MindlinParameters, Slide, TangentialInput, TangentialModel, TangentialOutput,
    coulomb,
};
use crate::law::normal::NormalContact;
use crate::value::backend::MathBackend;
use crate::value::float::{Float, inverse_root};
use crate::value::vector::Vec3;

/// The springs of one micro-slip contact: the breakpoints of its displacement profile, and the
/// normal and contact radius they were last updated at. `4 SPRINGS + 4` floats, all zero before
/// first touch; the caller owns it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct MicroSlipSprings<F, const SPRINGS: usize> {
    /// The unit normal at the last update (zero before first touch).
    pub normal: Vec3<F>,
    /// The contact radius `a` (m) at the last update (zero before first touch).
    pub contact_radius: F,
    /// Each breakpoint's position `t = x / a`, rising from the centre (0); a position not above
    /// the one before it or not below the rim (1) ends the profile.
    pub positions: [F; SPRINGS],
    /// Each breakpoint's tangential displacement (m), j relative to i, in the tangent plane of
    /// `normal`; a spring at `t` between two breakpoints has the value linear in `1 - t^2`
    /// between theirs, and the rim none. The shear force on j is `-8 G* a` times its mean.
    pub displacements: [Vec3<F>; SPRINGS],
}

impl<F: Float, const SPRINGS: usize> Default for MicroSlipSprings<F, SPRINGS> {
    fn default() -> Self {
        Self {
            normal: Vec3::ZERO,
            contact_radius: F::ZERO,
            positions: [F::ZERO; SPRINGS],
            displacements: [Vec3::ZERO; SPRINGS],
        }
    }
}

impl<F: Float, const SPRINGS: usize> ContactState for MicroSlipSprings<F, SPRINGS> {
    fn is_finite(&self) -> bool {
        self.normal.is_finite()
            && self.contact_radius.is_finite()
            && self.positions.iter().all(|t| t.is_finite())
            && self.displacements.iter().all(|u| u.is_finite())
    }
    fn same_bits(&self, other: &Self) -> bool {
        self.normal.same_bits(other.normal)
            && self.contact_radius.to_bits_u64() == other.contact_radius.to_bits_u64()
            && (self.positions.iter())
                .zip(other.positions.iter())
                .all(|(a, b)| a.to_bits_u64() == b.to_bits_u64())
            && (self.displacements.iter())
                .zip(other.displacements.iter())
                .all(|(a, b)| a.same_bits(*b))
    }
}

impl<F: Float, const SPRINGS: usize> MicroSlipSprings<F, SPRINGS> {
    /// How many breakpoints the profile has: the centre, then each one above the last and below
    /// the rim.
    fn used(&self) -> usize {
        let mut used = 1;
        while used < SPRINGS
            && self.positions[used] > self.positions[used - 1]
            && self.positions[used] < F::ONE
        {
            used += 1;
        }
        used
    }
}

/// Hertz-Mindlin with micro-slip (Mindlin & Deresiewicz 1953), its profile kept in up to
/// `SPRINGS` breakpoints (at least 3: the centre and the two fronts of a load cycle).
///
/// The tangential dashpot `eta_t = r eta_n` acts on the whole contact, and the total is held to
/// `mu |F_n|` along its own direction, as in [`MindlinAA`](crate::MindlinAA). The springs' limits
/// follow Hertz's pressure and sum to `mu |F_n|`, the normal dashpot included.
///
/// ```
/// use soft_sphere::prelude::{
///     ContactLaw, Hertz, HertzImpact, Material, MicroSlip, MindlinParameters,
/// };
/// let steel = Material::new(2.08e11_f64, 0.3).unwrap();
/// let largest = HertzImpact { speed: 5.0, effective_radius: 0.01 };
/// let normal = Hertz::new(steel.modulus_against_rigid(), 1.0, largest).unwrap();
/// let mindlin = MindlinParameters::new(steel.shear_modulus_against_rigid(), 0.0, 0.3).unwrap();
/// let law = ContactLaw::new(normal, MicroSlip::<f64, 16>::new(mindlin));
/// # let _ = law;
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MicroSlip<F, const SPRINGS: usize> {
    parameters: MindlinParameters<F>,
}

impl<F: Float, const SPRINGS: usize> MicroSlip<F, SPRINGS> {
    /// Mindlin's parameters, the profile in up to `SPRINGS` breakpoints.
    pub fn new(parameters: MindlinParameters<F>) -> Self {
        const {
            assert!(
                SPRINGS >= 3,
                "a micro-slip bed needs at least 3 breakpoints"
            )
        };
        Self { parameters }
    }

    /// Mindlin's parameters.
    pub fn parameters(&self) -> &MindlinParameters<F> {
        &self.parameters
    }
}

/// The squared sine of the angle between two slipping breakpoints' trials past which the
/// spring midway becomes a breakpoint too (an angle of 0.01: the line between them then strays
/// from the limit by at most 1.3e-5 of it).
const TURNED: f64 = 1e-4;

/// One breakpoint of the profile being built: its position, displacement and limit, and
/// whether it is at its limit (slipping).
#[derive(Clone, Copy, Debug)]
struct Breakpoint<F> {
    position: F,
    displacement: Vec3<F>,
    limit: F,
    at_limit: bool,
}

impl<F: Float> Breakpoint<F> {
    /// A trial displacement at `position` under the limit profile `full_slip (1 - t^2)`.
    #[inline(always)]
    fn trial(position: F, displacement: Vec3<F>, full_slip: F) -> Self {
        let limit = full_slip * (F::ONE - position * position);
        Self {
            position,
            displacement,
            limit,
            at_limit: displacement.norm_squared() >= limit * limit,
        }
    }

    /// The displacement a fraction `w` of the way from this breakpoint to `next` in
    /// `lambda = 1 - t^2`, along which the profile is linear.
    #[inline(always)]
    fn displacement_towards(&self, next: &Self, w: F) -> Vec3<F> {
        self.displacement + (next.displacement - self.displacement) * w
    }

    /// The trial held to its limit: a slipping spring keeps `l` along its trial.
    #[inline(always)]
    fn clipped<M: MathBackend<F>>(self) -> Self {
        let squared = self.displacement.norm_squared();
        if self.at_limit && squared > F::ZERO {
            Self {
                displacement: self.displacement * (self.limit * inverse_root::<F, M>(squared)),
                ..self
            }
        } else {
            self
        }
    }
}

/// Whether two displacements point the same way (to rounding): the limit profile between two
/// slipping breakpoints along one direction is then the straight line they are both on.
#[inline(always)]
fn aligned<F: Float>(a: Vec3<F>, b: Vec3<F>) -> bool {
    let dot = a.dot(b);
    let tolerance = F::ONE - F::from_f64(64.0) * F::EPSILON;
    dot > F::ZERO && dot * dot >= tolerance * a.norm_squared() * b.norm_squared()
}

/// The breakpoints of the profile being built, from the centre out: at most `SPRINGS` kept (in
/// the arrays the state takes, unused ones at the rim), and the last one held back until the
/// next shows whether it stays.
struct Profile<F, const SPRINGS: usize> {
    positions: [F; SPRINGS],
    displacements: [Vec3<F>; SPRINGS],
    slipping: [bool; SPRINGS],
    used: usize,
    last: Breakpoint<F>,
    /// What the drops so far have added to the integral of `|u|^2` over `t` (negative: taken
    /// away).
    dropped_energy: F,
}

impl<F: Float, const SPRINGS: usize> Profile<F, SPRINGS> {
    /// A profile that starts at `centre`.
    #[inline(always)]
    fn new(centre: Breakpoint<F>) -> Self {
        Self {
            positions: [F::ONE; SPRINGS],
            displacements: [Vec3::ZERO; SPRINGS],
            slipping: [false; SPRINGS],
            used: 0,
            last: centre,
            dropped_energy: F::ZERO,
        }
    }

    /// Appends `next`. A slipping breakpoint between two slipping ones along one direction lies
    /// on their line and goes.
    #[inline(always)]
    fn push(&mut self, next: Breakpoint<F>) {
        if !(next.at_limit && self.last_on_line(next.displacement)) {
            self.keep_last(next.position, next.displacement);
        }
        self.last = next;
    }

    /// Between two slipping breakpoints the springs turn each by its own angle when the step
    /// is not along them (the weaker, the more), away from the line between the two: where the
    /// two trials' directions differ by more than [`TURNED`] (squared sine), the spring midway
    /// in `1 - t^2` is kept too. Along one direction it never is.
    #[inline(always)]
    fn refine<M: MathBackend<F>>(&mut self, a: &Breakpoint<F>, b: &Breakpoint<F>, full_slip: F) {
        let (u, v) = (a.displacement, b.displacement);
        let sine_squared = u.cross(v).norm_squared();
        let turned = sine_squared > F::from_f64(TURNED) * u.norm_squared() * v.norm_squared();
        let squared = (a.position * a.position + b.position * b.position) * F::HALF;
        let position = M::sqrt(squared);
        if turned && position > a.position && position < b.position {
            self.push(Breakpoint::trial(position, (u + v) * F::HALF, full_slip).clipped::<M>());
        }
    }

    /// Ends the profile at the rim, where every spring is at its (zero) limit.
    #[inline(always)]
    fn finish(&mut self) {
        if !self.last_on_line(Vec3::ZERO) {
            self.keep_last(F::ONE, Vec3::ZERO);
        }
    }

    /// A drop replaces a breakpoint by the line through its neighbours, which lies above the
    /// springs it stands for where the profile bends up (a contact growing under a slowing
    /// push): that would store energy no motion put in. When the drops of a step added to what
    /// the springs hold, the whole profile is scaled down to hold what it would have held
    /// without them. Scaling down keeps every spring within its limit and the profile's shape.
    #[inline(always)]
    fn give_back_dropped_energy<M: MathBackend<F>>(&mut self) {
        if self.dropped_energy <= F::ZERO {
            return;
        }
        let held = square_integral(&self.positions, &self.displacements, self.used);
        let ratio = if held > F::ZERO {
            (held - self.dropped_energy) / held
        } else {
            F::ZERO
        };
        let scale = if ratio > F::ZERO {
            M::sqrt(ratio)
        } else {
            F::ZERO
        };
        for u in &mut self.displacements[..self.used] {
            *u = *u * scale;
        }
    }

    /// Whether the last breakpoint (never the centre) slips between the one before it and a
    /// slipping `next` along one direction (`next` zero: the rim, on every such line).
    #[inline(always)]
    fn last_on_line(&self, next: Vec3<F>) -> bool {
        if self.used == 0 {
            return false;
        }
        let before = self.displacements[self.used - 1];
        self.slipping[self.used - 1]
            && self.last.at_limit
            && aligned(before, self.last.displacement)
            && (next == Vec3::ZERO || aligned(self.last.displacement, next))
    }

    /// Keeps the last breakpoint, the next at `position` with `displacement`. When the profile
    /// is full, the breakpoint (not the centre) whose value is nearest the line through its
    /// neighbours, weighted by the span they cover, makes room; that may be the last one itself.
    fn keep_last(&mut self, position: F, displacement: Vec3<F>) {
        let last = self.last;
        if self.used < SPRINGS {
            self.positions[self.used] = last.position;
            self.displacements[self.used] = last.displacement;
            self.slipping[self.used] = last.at_limit;
            self.used += 1;
            return;
        }
        let at = |k: usize| {
            if k < SPRINGS {
                (self.positions[k], self.displacements[k])
            } else if k == SPRINGS {
                (last.position, last.displacement)
            } else {
                (position, displacement)
            }
        };
        let mut least = F::INFINITY;
        let mut drop = SPRINGS;
        for k in 1..=SPRINGS {
            let ((a, left), (b, point), (c, right)) = (at(k - 1), at(k), at(k + 1));
            let span = (c - a) * (c + a);
            let weight = if span > F::ZERO {
                (b - a) * (b + a) / span
            } else {
                F::ZERO
            };
            let line = left + (right - left) * weight;
            let change = (point - line).norm_squared() * (c - a);
            if change < least {
                least = change;
                drop = k;
            }
        }
        let ((a, left), (b, point), (c, right)) = (at(drop - 1), at(drop), at(drop + 1));
        self.dropped_energy += segment_square(a, left, c, right)
            - segment_square(a, left, b, point)
            - segment_square(b, point, c, right);
        if drop < SPRINGS {
            for k in drop..SPRINGS - 1 {
                self.positions[k] = self.positions[k + 1];
                self.displacements[k] = self.displacements[k + 1];
                self.slipping[k] = self.slipping[k + 1];
            }
            self.positions[SPRINGS - 1] = last.position;
            self.displacements[SPRINGS - 1] = last.displacement;
            self.slipping[SPRINGS - 1] = last.at_limit;
        }
    }
}

/// Where the trial profile between breakpoints `a` and `b` crosses the limit, as fractions of
/// the way in `1 - t^2` (where both are linear): none, one or two, rising. `|v|^2 - l^2` is a
/// quadratic `A w^2 + 2 B w + C` there, convex in `|v|` against a straight `l`, so two breakpoints
/// within their limits have none between them.
#[inline(always)]
fn crossings<F: Float, M: MathBackend<F>>(a: &Breakpoint<F>, b: &Breakpoint<F>) -> [Option<F>; 2] {
    let dv = b.displacement - a.displacement;
    let dl = b.limit - a.limit;
    let quadratic = dv.norm_squared() - dl * dl;
    let linear = a.displacement.dot(dv) - a.limit * dl;
    let constant = a.displacement.norm_squared() - a.limit * a.limit;
    let end = quadratic + F::TWO * linear + constant;
    let (first_inside, last_inside) = (constant < F::ZERO, end < F::ZERO);
    // Both inside: none; both at the limit: a dip needs the quadratic's least value between
    // them, `B < 0 < A + B`.
    let no_dip =
        !first_inside && !last_inside && (linear >= F::ZERO || quadratic + linear <= F::ZERO);
    if (first_inside && last_inside) || no_dip {
        return [None, None];
    }
    // `B^2 - A C`, written without the cancellation of its `l^4` terms.
    let discriminant = (dv * a.limit - a.displacement * dl).norm_squared()
        - a.displacement.cross(dv).norm_squared();
    if discriminant < F::ZERO || !discriminant.is_finite() {
        return [None, None];
    }
    let root = M::sqrt(discriminant);
    // The two roots without cancellation: q / A and C / q.
    let q = if linear >= F::ZERO {
        -(linear + root)
    } else {
        root - linear
    };
    let inside = |w: F| w > F::ZERO && w < F::ONE;
    let (first, second) = (
        if quadratic != F::ZERO {
            q / quadratic
        } else {
            F::INFINITY
        },
        if q != F::ZERO {
            constant / q
        } else {
            F::INFINITY
        },
    );
    let (low, high) = if first <= second {
        (first, second)
    } else {
        (second, first)
    };
    if first_inside != last_inside {
        // One end inside, one at the limit: one crossing.
        let w = if inside(low) { low } else { high };
        [inside(w).then_some(w), None]
    } else if inside(low) && inside(high) {
        // Both ends at the limit, turned apart: the profile dips inside between them.
        [Some(low), Some(high)]
    } else {
        [None, None]
    }
}

impl<F: Float, const SPRINGS: usize> TangentialModel<F> for MicroSlip<F, SPRINGS> {
    type State = MicroSlipSprings<F, SPRINGS>;
    const NEEDS_CONTACT_RADIUS: bool = true;

    fn force<M: MathBackend<F>>(
        &self,
        state: &Self::State,
        contact: &TangentialInput<F>,
    ) -> TangentialOutput<F, Self::State> {
        let radius = contact.contact_radius;
        // The smallest rotation taking the last normal to this one, applied to every breakpoint:
        // `R u = c u + w x u + w (w . u) / (1 + c)`, `c` the cosine and `w` the cross product.
        let n = contact.normal;
        let cosine = state.normal.dot(n);
        let axis = state.normal.cross(n);
        let turned = F::ONE + cosine;
        let scale = state.contact_radius / radius;
        // Before first touch (no normal or radius yet) or on a reversed normal, no spring
        // survives.
        let keep = turned > F::MIN_POSITIVE && state.contact_radius > F::ZERO && scale.is_finite();
        let inverse_turned = if keep { F::ONE / turned } else { F::ZERO };
        let rotate =
            |u: Vec3<F>| u * cosine + axis.cross(u) + axis * (axis.dot(u) * inverse_turned);

        let limit = self.parameters.limit(contact);
        let stiffness = self.parameters.stiffness(radius);
        let full_slip = if stiffness > F::ZERO {
            limit * F::from_f64(1.5) / stiffness
        } else {
            F::ZERO
        };
        let step = contact.slip_velocity * contact.time_step;

        // The stored breakpoints at this contact's scale, then the old rim (free of shear), then
        // the new area out to the rim, laid down free of shear.
        let stored = if keep { state.used() } else { 1 };
        let old_rim = if keep { scale } else { F::ONE };
        let source = |k: usize| -> (F, Vec3<F>) {
            if k == 0 {
                let centre = if keep {
                    rotate(state.displacements[0])
                } else {
                    Vec3::ZERO
                };
                (F::ZERO, centre)
            } else if k < stored {
                (state.positions[k] * scale, rotate(state.displacements[k]))
            } else if k == stored {
                (old_rim, Vec3::ZERO)
            } else {
                (F::ONE, Vec3::ZERO)
            }
        };

        let (centre, centre_value) = source(0);
        let mut previous = Breakpoint::trial(centre, centre_value + step, full_slip);
        let mut profile = Profile::<F, SPRINGS>::new(previous.clipped::<M>());
        for k in 1..stored + 2 {
            let (position, value) = source(k);
            let mut next = Breakpoint::trial(position, value + step, full_slip);
            let past_rim = position >= F::ONE;
            if past_rim {
                // The rim cuts the segment: its value there, linear in 1 - t^2.
                let (a, b) = (previous.position, position);
                let span = (b - a) * (b + a);
                let w = if span > F::ZERO && span.is_finite() {
                    (F::ONE - a) * (F::ONE + a) / span
                } else {
                    F::ZERO
                };
                let rim = previous.displacement_towards(&next, w);
                next = Breakpoint::trial(F::ONE, rim, full_slip);
            }
            let crossed = crossings::<F, M>(&previous, &next);
            if crossed[0].is_none() && previous.at_limit && next.at_limit {
                profile.refine::<M>(&previous, &next, full_slip);
            }
            for w in crossed.into_iter().flatten() {
                let (a, b) = (previous.position, next.position);
                let squared = a * a + w * (b - a) * (b + a);
                let position = M::sqrt(squared);
                if position > a && position < b {
                    let displacement = previous.displacement_towards(&next, w);
                    let limit = previous.limit + (next.limit - previous.limit) * w;
                    let crossing = Breakpoint {
                        position,
                        displacement,
                        limit,
                        at_limit: true,
                    };
                    profile.push(crossing.clipped::<M>());
                }
            }
            if past_rim {
                break;
            }
            profile.push(next.clipped::<M>());
            previous = next;
        }
        profile.finish();
        profile.give_back_dropped_energy::<M>();

        let used = profile.used;
        let mut mean = Vec3::ZERO;
        for k in 0..used {
            let (b, v) = if k + 1 < used {
                (profile.positions[k + 1], profile.displacements[k + 1])
            } else {
                (F::ONE, Vec3::ZERO)
            };
            mean += segment_mean(profile.positions[k], profile.displacements[k], b, v);
        }
        let every_spring_slid = profile.slipping[..used].iter().all(|&s| s);
        let next = Self::State {
            normal: n,
            contact_radius: radius,
            positions: profile.positions,
            displacements: profile.displacements,
        };
        let spring_force = mean * -stiffness;
        let dashpot = contact.slip_velocity * self.parameters.dashpot(&contact.oscillator);
        let (force, capped) = coulomb::<F, M>(
            spring_force - dashpot,
            contact.slip_velocity,
            limit,
            Slide::AlongTrial,
        );
        TangentialOutput {
            force,
            state: next,
            sliding: capped || every_spring_slid,
        }
    }

    /// `8 G* a / 2` times the integral of `|u|^2` along the line, at the state's contact
    /// radius.
    fn stored_energy(&self, state: &Self::State) -> F {
        if state.contact_radius <= F::ZERO || !state.contact_radius.is_finite() {
            return F::ZERO;
        }
        let integral = square_integral(&state.positions, &state.displacements, state.used());
        self.parameters.stiffness(state.contact_radius) * integral * F::HALF
    }

    /// Mindlin's no-slip stiffness at the stiffest contact: the springs never exceed it.
    fn critical_time_step(&self, design: &NormalContact<F>, tangential_mass: F) -> F {
        self.parameters.critical_step(design, tangential_mass)
    }
}

/// The integral over `t` in `[a, b]` of a displacement linear in `1 - t^2` from `u` to `v`:
/// `h (u + (v - u) (3a + h) / (3 (2a + h)))`, `h = b - a`.
#[inline(always)]
fn segment_mean<F: Float>(a: F, u: Vec3<F>, b: F, v: Vec3<F>) -> Vec3<F> {
    let h = b - a;
    if h <= F::ZERO || !h.is_finite() {
        return Vec3::ZERO;
    }
    let three = F::from_f64(3.0);
    let weight = (three * a + h) / (three * (a + b));
    (u + (v - u) * weight) * h
}

/// The integral of `|u|^2` over `0 <= t <= 1` for the first `used` breakpoints of a profile (the
/// first at the centre, whatever its stored position; the rim after the last).
fn square_integral<F: Float>(positions: &[F], displacements: &[Vec3<F>], used: usize) -> F {
    let mut integral = F::ZERO;
    for k in 0..used {
        let start = if k == 0 { F::ZERO } else { positions[k] };
        let (end, v) = if k + 1 < used {
            (positions[k + 1], displacements[k + 1])
        } else {
            (F::ONE, Vec3::ZERO)
        };
        integral += segment_square(start, displacements[k], end, v);
    }
    integral
}

/// The integral over `t` in `[a, b]` of `|w|^2`, `w` linear in `1 - t^2` from `u` to `v`.
fn segment_square<F: Float>(a: F, u: Vec3<F>, b: F, v: Vec3<F>) -> F {
    let h = b - a;
    if h <= F::ZERO || !h.is_finite() {
        return F::ZERO;
    }
    let three = F::from_f64(3.0);
    let sum = a + b;
    // The weight's integral and its square's, with s = t - a: the weight is
    // s (2a + s) / (h (2a + h)).
    let first = h * (three * a + h) / (three * sum);
    let second =
        h * (F::from_f64(4.0 / 3.0) * a * a + a * h + h * h / F::from_f64(5.0)) / (sum * sum);
    let d = v - u;
    u.norm_squared() * h + F::TWO * u.dot(d) * first + d.norm_squared() * second
}
