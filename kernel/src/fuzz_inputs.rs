//! `arbitrary::Arbitrary` for the kernel's inputs (feature `arbitrary`), so that a cargo-fuzz or
//! bolero target builds them from the fuzzer's bytes.
//!
//! Vectors, spheres and per-contact states take any bit pattern: the kernel must answer each
//! with a value or an error. Walls and law parameters are built through their checked
//! constructors, and bytes they refuse are `arbitrary::Error::IncorrectFormat`, so a target
//! skips them: a refused constructor is tested by the kernel's own tests.

use arbitrary::{Arbitrary, Error, Result, Unstructured};

use crate::law::normal::{Hertz, HertzImpact, LinearSpringDashpot};
use crate::law::rolling::RollingSpring;
use crate::law::tangential::{
    MicroSlipSprings, MindlinParameters, MindlinSpring, SpringDisplacement, TangentialParameters,
};
use crate::value::body::Sphere;
use crate::value::float::Float;
use crate::value::material::Material;
use crate::value::vector::Vec3;
use crate::value::wall::Wall;

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for Vec3<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(Vec3::new(u.arbitrary()?, u.arbitrary()?, u.arbitrary()?))
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for Sphere<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(Sphere {
            position: u.arbitrary()?,
            velocity: u.arbitrary()?,
            angular_velocity: u.arbitrary()?,
            radius: u.arbitrary()?,
            mass: u.arbitrary()?,
        })
    }
}

/// A checked constructor's refusal, as bytes the target should skip.
fn refused<T, E>(built: core::result::Result<T, E>) -> Result<T> {
    built.map_err(|_| Error::IncorrectFormat)
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for Wall<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let (point, direction) = (u.arbitrary()?, u.arbitrary()?);
        let wall = if u.arbitrary()? {
            refused(Wall::cylinder(point, direction, u.arbitrary()?))?
        } else {
            refused(Wall::new(point, direction))?
        };
        let (velocity, spin) = (u.arbitrary()?, u.arbitrary()?);
        refused(wall.with_velocity(velocity).and_then(|w| w.with_spin(spin)))
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for HertzImpact<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(HertzImpact {
            speed: u.arbitrary()?,
            effective_radius: u.arbitrary()?,
        })
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for SpringDisplacement<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(SpringDisplacement {
            displacement: u.arbitrary()?,
        })
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for MindlinSpring<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(MindlinSpring {
            force: u.arbitrary()?,
            contact_radius: u.arbitrary()?,
        })
    }
}

impl<'a, F: Float + Arbitrary<'a>, const SPRINGS: usize> Arbitrary<'a>
    for MicroSlipSprings<F, SPRINGS>
{
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let mut springs = MicroSlipSprings {
            normal: u.arbitrary()?,
            contact_radius: u.arbitrary()?,
            ..Default::default()
        };
        for position in &mut springs.positions {
            *position = u.arbitrary()?;
        }
        for displacement in &mut springs.displacements {
            *displacement = u.arbitrary()?;
        }
        Ok(springs)
    }
}

impl<'a, S: Arbitrary<'a>, F: Float + Arbitrary<'a>> Arbitrary<'a> for RollingSpring<S, F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(RollingSpring {
            tangential: u.arbitrary()?,
            torque: u.arbitrary()?,
        })
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for LinearSpringDashpot<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        refused(LinearSpringDashpot::new(u.arbitrary()?, u.arbitrary()?))
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for Hertz<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        refused(Hertz::new(u.arbitrary()?, u.arbitrary()?, u.arbitrary()?))
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for TangentialParameters<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        refused(TangentialParameters::new(
            u.arbitrary()?,
            u.arbitrary()?,
            u.arbitrary()?,
        ))
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for MindlinParameters<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        refused(MindlinParameters::new(
            u.arbitrary()?,
            u.arbitrary()?,
            u.arbitrary()?,
        ))
    }
}

impl<'a, F: Float + Arbitrary<'a>> Arbitrary<'a> for Material<F> {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        refused(Material::new(u.arbitrary()?, u.arbitrary()?))
    }
}
