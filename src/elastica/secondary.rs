//! Secondary symmetric branches: born at ϑ_j, not through the ring.

use super::bifurcation::bifurcation;
use super::family::{Family, Member};
use super::solution::{Arm, Branch, Elastica, check_j, check_modulus, check_n, modulus_from_k};
use crate::error::{Error, Result};
use crate::special::{Modulus, ellip_k};

/// The fold of a secondary branch: its smallest modulus, where its two arms
/// meet.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SecondaryFold {
    solution: Elastica,
}

impl SecondaryFold {
    /// The modulus k of the fold.
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.solution.modulus()
    }

    /// Physical tension at the fold.
    #[must_use]
    pub fn force(&self) -> f64 {
        self.solution.force()
    }

    /// Extension at the fold.
    #[must_use]
    pub fn extension(&self) -> f64 {
        self.solution.extension()
    }

    /// The solution at the fold (reported on the bifurcating arm).
    #[must_use]
    pub fn solution(&self) -> Elastica {
        self.solution
    }
}

impl core::fmt::Display for SecondaryFold {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "fold of {}", self.solution)
    }
}

/// Family, sign conventions and bracket of one arm.
fn setup(n: u32, j: u32, modulus: Modulus) -> Member {
    let family = if j < n {
        Family::Upsilon
    } else {
        Family::Alpha
    };
    Member::new(family, j, n, ellip_k(modulus), modulus)
}

/// t* if the branch exists at this modulus (the extremum of g is beyond πn).
fn extremum_beyond(member: &Member) -> Option<f64> {
    let t = member.extremum()?;
    let g = member.eval(t).0;
    let ok = match member.family {
        Family::Upsilon => g >= 0.0,
        Family::Alpha => g <= 0.0,
    };
    ok.then_some(t)
}

fn solve_arm(n: u32, j: u32, arm: Arm, modulus: Modulus) -> Option<Elastica> {
    let member = setup(n, j, modulus);
    let t_star = extremum_beyond(&member)?;
    let big_k = member.big_k;
    let upsilon = member.family == Family::Upsilon;
    let bifurcating = arm == Arm::bifurcating(n, j);
    // bifurcating arm on [t*, K], the other on [−K, t*]
    let (t, jac) = if bifurcating {
        member.solve(t_star, big_k, upsilon, 0.0)
    } else {
        member.solve(-big_k, t_star, !upsilon, 0.5 * (t_star - big_k))
    };
    Some(Elastica::from_parts(
        n,
        modulus,
        big_k,
        member.omega(t),
        member.excess(t),
        member.start(t),
        member.ends(jac),
        Branch::Secondary { j, arm },
    ))
}

fn check_secondary(n: u32, j: u32) -> Result<()> {
    check_n(n)?;
    check_j(j)?;
    if j == n {
        return Err(Error::SecondaryNeedsOtherPeriods { n });
    }
    Ok(())
}

impl Elastica {
    /// The secondary symmetric solution j for n coils at modulus k, on the
    /// arm that carries the bifurcation point with ϑ_j
    /// ([`Arm::bifurcating`]: υ-shapes for j < n, α-shapes for j > n).
    ///
    /// ```text
    /// eq7 with m = j (j < n) or m = j + 1 (j > n):
    /// j < n (υ): Ω = 2(jK − t),  πn = Ω dn t
    /// j > n (α): Ω = 2(jK + t),  πn = Ω k' nd t
    /// ```
    ///
    /// t is the end's distance from the curvature extremum; t = 0 is the
    /// bifurcation point (where this branch crosses ϑ_j). The left side has
    /// an extremum t* in (−K, 0); the branch exists once that extremum
    /// reaches πn, at the fold k_f ([`secondary_fold`]), and splits there into
    /// the arms t ∈ [t*, K] (the bifurcating one) and t ∈ [−K, t*]
    /// ([`Elastica::secondary_arm`]). Each arm is solved by safeguarded Newton
    /// in its bracket.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for n = 0 or j = 0;
    /// [`Error::SecondaryNeedsOtherPeriods`] for j = n;
    /// [`Error::InvalidModulus`] / [`Error::ModulusNotBelowOne`] for k outside
    /// [0, 1); [`Error::BelowFold`] for k below the fold;
    /// [`Error::FoldNotFound`] if the fold cannot be located in double
    /// precision (not seen for n ≤ 50, j < 2³²).
    ///
    /// # Example
    /// ```
    /// use hockle::elastica::{Elastica, bifurcation, Arm, Branch};
    /// let b = bifurcation(4, 3)?;
    /// let e = Elastica::secondary(4, 3, b.modulus())?;
    /// assert!((e.force() - b.force()).abs() < 1e-9 * b.force());
    /// assert_eq!(e.branch(), Branch::Secondary { j: 3, arm: Arm::Lower });
    /// assert!(Elastica::secondary(4, 3, 0.5).is_err()); // below the fold k ≈ 0.8284
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn secondary(n: u32, j: u32, k: f64) -> Result<Elastica> {
        check_secondary(n, j)?;
        Self::secondary_arm(n, j, Arm::bifurcating(n, j), modulus_from_k(k)?)
    }

    /// The secondary solution j on a given arm, at a [`Modulus`].
    ///
    /// # Errors
    /// As [`Elastica::secondary`].
    pub fn secondary_arm(n: u32, j: u32, arm: Arm, modulus: Modulus) -> Result<Elastica> {
        check_secondary(n, j)?;
        let modulus = check_modulus(modulus)?;
        match solve_arm(n, j, arm, modulus) {
            Some(e) => Ok(e),
            None => Err(Error::BelowFold {
                n,
                j,
                k: modulus.k(),
                fold: fold_modulus(n, j)?.k(),
            }),
        }
    }
}

/// The fold of secondary branch j for n coils: the smallest modulus at which
/// the branch exists, where its two arms meet (g(t*) = πn and g′(t*) = 0 in
/// the notation of [`Elastica::secondary`]).
///
/// Located by bisection in ln m₁ between the bifurcation point (where the
/// branch exists) and smaller k, to full double precision; about 100
/// evaluations of the extremum, so ~0.3 ms.
///
/// # Errors
/// As [`bifurcation`]; [`Error::FoldNotFound`] if rounding hides the branch
/// near its bifurcation point (not seen for n ≤ 50, j < 2³²).
///
/// # Example
/// ```
/// use hockle::elastica::{secondary_fold, bifurcation};
/// let f = secondary_fold(4, 3)?;
/// assert!(f.modulus() < bifurcation(4, 3)?.modulus());
/// assert!((f.modulus() - 0.828_428_829_573_529).abs() < 1e-12);
/// # Ok::<(), hockle::Error>(())
/// ```
pub fn secondary_fold(n: u32, j: u32) -> Result<SecondaryFold> {
    let modulus = fold_modulus(n, j)?;
    // `fold_modulus` checked that the branch exists there; rounding in the
    // arm's own solve is the only way to miss it
    let solution =
        solve_arm(n, j, Arm::bifurcating(n, j), modulus).ok_or(Error::FoldNotFound { n, j })?;
    Ok(SecondaryFold { solution })
}

/// The modulus of the fold (see [`secondary_fold`]): the last modulus of a
/// bisection in ln m₁ at which the branch exists. Never calls the arm
/// solver, so [`Elastica::secondary_arm`] can report the fold in its error.
fn fold_modulus(n: u32, j: u32) -> Result<Modulus> {
    check_secondary(n, j)?;
    let b = bifurcation(n, j)?;
    let exists = |x: f64| -> Result<bool> {
        let modulus = check_modulus(Modulus::from_complement(x.exp())?)?;
        Ok(extremum_beyond(&setup(n, j, modulus)).is_some())
    };
    // The branch passes through the bifurcation point, but there (and at the
    // fold) its extremum equals πn up to rounding: for j ≫ n the test is a
    // coin flip. Start a little beyond the bifurcation (larger k), where the
    // branch exists robustly; give up after a 1 % step in ln m₁.
    let x_b = b.elliptic_modulus().complement().ln();
    let mut lo = x_b;
    let mut shift = 1e-12;
    while !exists(lo)? {
        if shift > 1e-2 {
            return Err(Error::FoldNotFound { n, j });
        }
        lo = x_b * (1.0 + shift);
        shift *= 10.0;
    }
    let mut hi = lo;
    // walk towards k = 0 (x → 0) until the branch no longer exists
    loop {
        hi *= 0.5;
        if hi > -1e-12 {
            hi = -1e-300;
            break;
        }
        if !exists(hi)? {
            break;
        }
        lo = hi;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if exists(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    check_modulus(Modulus::from_complement(lo.exp())?)
}
