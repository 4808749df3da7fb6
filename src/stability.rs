//! Stability of an equilibrium under a [`Control`]: its index, and the index
//! carried along a force–extension curve from a stable start through its
//! folds.
//!
//! ## What "stable" means here
//!
//! An equilibrium of a conservative elastic body under a quasi-static end
//! load is **stable** when it is a strict local minimum of the total
//! potential energy of the control, i.e. when the second variation of that
//! energy is positive on every admissible perturbation. Its **index** is the
//! number of independent perturbations along which the second variation is
//! negative (the Morse index): 0 for a stable equilibrium, 1 or more for one
//! that a real spring cannot sit at.
//!
//! - **Force control** (dead load F): the energy is U − F Δz; every
//!   perturbation compatible with the supports is admissible, Δz included.
//! - **Extension control** (hard device): the energy is U with Δz fixed; the
//!   admissible perturbations are those that keep Δz. F is then the
//!   multiplier of that constraint.
//!
//! Both controls have the same equilibria (the same curve), but not the same
//! stable ones: fixing Δz removes one admissible direction, so
//! index(extension) ≤ index(force) ≤ index(extension) + 1 (Maddocks 1987).
//!
//! ## The index carried along a curve
//!
//! Let H be the second variation under force control at a regular point
//! (H nonsingular) and z′ the variation of Δz. A change δF moves the
//! equilibrium by H⁻¹z′ δF, so the compliance is dΔz/dF = ⟨z′, H⁻¹ z′⟩. The
//! extension control's second variation is H restricted to ⟨z′, ·⟩ = 0;
//! the inertia of the bordered matrix [[H, z′], [z′ᵀ, 0]] counts it (plus
//! one positive and one negative direction for the border) and equals, by
//! Haynsworth's inertia additivity of the Schur complement −⟨z′, H⁻¹z′⟩,
//!
//! ```text
//!   index(extension) = index(force) − [dΔz/dF < 0]
//! ```
//!
//! (Maddocks, "Stability and folds", 1987: the *distinguished bifurcation
//! diagram* of the load against its conjugate displacement shows stability
//! by its slope.) Along a curve one eigenvalue of H crosses zero, generically,
//! only at a fold of F, where the extension problem is regular; one
//! eigenvalue of the restricted H crosses zero only at a fold of Δz, where
//! the force problem is regular. Hence, from a stable start:
//!
//! - at a fold of F the extension index is kept and the force index becomes
//!   index(extension) + [dΔz/dF < 0] on the far side;
//! - at a fold of Δz the force index is kept and the extension index becomes
//!   index(force) − [dΔz/dF < 0] on the far side;
//! - at a branch point (a symmetric branch crossed by an asymmetric one,
//!   where neither F nor Δz folds) both indices change by the same ±1, which
//!   the curve cannot tell ([`IndexCrossing`]: the caller supplies it, e.g.
//!   from a direct test on either side).
//!
//! The sign of dΔz/dF is the sign of the slope of the curve in the
//! (Δz, F) plane; it flips at every fold of either quantity. This is AUTO's
//! fold test (a sign change of the tangent's parameter component) read with
//! the inertia theorem; it needs only the curve's folds, in order.
//! [`carried`] implements it; [`crate::rod::Equilibrium::stability`] is the
//! independent direct test of the rod (the inertia of its discretised second
//! variation), and the two are checked against each other in the tests.
//!
//! ## References
//!
//! - J. H. Maddocks, *Stability and folds*, Arch. Rational Mech. Anal. 99
//!   (1987) 301–328: index changes at folds, distinguished diagrams.
//! - J. H. Maddocks, *Stability of nonlinearly elastic rods*, Arch. Rational
//!   Mech. Anal. 85 (1984) 311–354: the second variation of rods,
//!   conjugate points, constraints.
//! - A. Lazarus, J. T. Miller, P. M. Reis, *Continuation of equilibria and
//!   stability of slender elastic rods using an asymptotic numerical
//!   method*, J. Mech. Phys. Solids 61 (2013) 1712–1736: stability of rods
//!   from the eigenvalues of the discretised tangent stiffness along a
//!   continuation.
//! - E. Doedel et al., *AUTO-07p*, the fold test of pseudo-arclength
//!   continuation.

use crate::curve::{Fold, FoldKind, ForceExtension};
use crate::load::Control;

/// The index of an equilibrium under one [`Control`]: the number of
/// independent admissible perturbations that lower its potential energy
/// (module docs). Index 0 is stable.
///
/// ```
/// use hockle::stability::Stability;
/// assert!(Stability::new(0).is_stable());
/// assert_eq!(Stability::new(2).to_string(), "unstable (index 2)");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stability {
    index: u32,
}

impl Stability {
    /// A stable equilibrium (index 0).
    pub const STABLE: Stability = Stability { index: 0 };

    /// An equilibrium of the given index.
    #[must_use]
    pub fn new(index: u32) -> Self {
        Self { index }
    }

    /// The number of unstable directions.
    #[must_use]
    pub fn index(&self) -> u32 {
        self.index
    }

    /// Whether a real spring can sit here (index 0).
    #[must_use]
    pub fn is_stable(&self) -> bool {
        self.index == 0
    }
}

impl core::fmt::Display for Stability {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.is_stable() {
            f.write_str("stable")
        } else {
            write!(f, "unstable (index {})", self.index)
        }
    }
}

/// A place on a curve where both indices change without a fold: a branch
/// point crossed by the curve (module docs). The change takes effect at the
/// points after `after`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct IndexCrossing {
    /// The last curve point before the crossing.
    pub after: usize,
    /// +1 if an unstable direction appears, −1 if one disappears.
    pub change: i32,
}

/// The index under `control` of every point of `curve`, carried from the
/// first point, taken stable under force control, through `folds` (both
/// kinds, in any order; each takes effect at the points after its `index`,
/// as [`Fold::index`] defines it for located and detected folds alike) and
/// the `crossings` (module docs).
///
/// The sign of the curve's slope at the start is that of its first segment
/// along which force and extension both change. A count that would go
/// below zero (folds missing from the list, or a start that is not stable)
/// is kept at zero.
///
/// ```
/// use hockle::stability::carried;
/// use hockle::{Control, ForceExtension, ForcePoint, ForceScale};
/// // F = t³ − 3t against Δz = t: a maximum of F at t = −1, a minimum at 1.
/// let mut curve = ForceExtension::new("s", "t", ForceScale::of_coils(1)?);
/// for i in 0..=60 {
///     let t = -3.0 + 0.1 * f64::from(i);
///     curve.push(ForcePoint { extension: t, force: t * t * t - 3.0 * t, parameter: t });
/// }
/// let folds = curve.folds();
/// let force = carried(&curve, &folds, &[], Control::Force);
/// let hard = carried(&curve, &folds, &[], Control::Extension);
/// assert!(force[10].is_stable() && !force[30].is_stable() && force[50].is_stable());
/// assert!(hard.iter().all(|s| s.is_stable())); // a hard device holds every point
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn carried(
    curve: &ForceExtension,
    folds: &[Fold],
    crossings: &[IndexCrossing],
    control: Control,
) -> Vec<Stability> {
    let pts = curve.points();
    let n = pts.len();
    // Signs of dF and dΔz along the curve at the start.
    let first = pts.windows(2).find_map(|w| {
        let (df, dz) = (w[1].force - w[0].force, w[1].extension - w[0].extension);
        (df != 0.0 && dz != 0.0).then_some((df > 0.0, dz > 0.0))
    });
    let Some((mut force_up, mut extension_up)) = first else {
        return vec![Stability::STABLE; n];
    };
    enum Event {
        Fold(FoldKind),
        Crossing(i32),
    }
    let mut events: Vec<(usize, f64, Event)> = folds
        .iter()
        .map(|f| (f.index, f.point.parameter, Event::Fold(f.kind)))
        .chain(crossings.iter().map(|c| {
            let t = pts.get(c.after).map_or(f64::INFINITY, |p| p.parameter);
            (c.after, t, Event::Crossing(c.change))
        }))
        .collect();
    events.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));

    let negative = |f: bool, z: bool| i64::from(f != z);
    let (mut force_index, mut extension_index) = (0_i64, -negative(force_up, extension_up));
    let mut out = Vec::with_capacity(n);
    let mut next = events.iter().peekable();
    for i in 0..n {
        let index = match control {
            Control::Force => force_index,
            Control::Extension => extension_index,
        };
        out.push(Stability::new(
            u32::try_from(index.max(0)).unwrap_or(u32::MAX),
        ));
        while let Some((_, _, event)) = next.next_if(|e| e.0 <= i) {
            match event {
                Event::Fold(kind @ (FoldKind::MaxForce | FoldKind::MinForce)) => {
                    force_up = *kind == FoldKind::MinForce;
                    force_index = extension_index + negative(force_up, extension_up);
                }
                Event::Fold(kind) => {
                    extension_up = *kind == FoldKind::MinExtension;
                    extension_index = force_index - negative(force_up, extension_up);
                }
                Event::Crossing(change) => {
                    force_index += i64::from(*change);
                    extension_index += i64::from(*change);
                }
            }
        }
    }
    out
}
