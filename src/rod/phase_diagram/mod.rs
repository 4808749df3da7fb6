//! The number of pop-outs of a spring, read off its cusp curves
//! ([`PhaseDiagram`]).

mod csv;
mod reading;

use std::ops::RangeInclusive;

use crate::continuation::Termination;
use crate::error::{Error, Result};

/// A point of a cusp curve: where the two folds of a pop-out meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CuspAt {
    /// Helix angle θ0 (radians).
    pub theta0: f64,
    /// Anisotropy A/B.
    pub a_over_b: f64,
    /// Poisson ratio ν.
    pub nu: f64,
    /// The force of the meeting folds, F/((2πn)²B) (NaN where it was not
    /// recorded: the single point of a line at fixed ν whose pop-out does
    /// not exist up to A/B = 100, or whose θ0_c is not known there).
    pub force_scaled: f64,
}

/// Which parameter is held fixed along a [`CuspLine`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fixed {
    /// ν fixed: the line runs in (θ0, A/B).
    Nu(f64),
    /// A/B fixed: the line runs in (θ0, ν).
    AOverB(f64),
}

/// How a [`CuspLine`] ends on one side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineEnd {
    /// θ0 reached 90° (the tip of the pop-out's region,
    /// [`super::CuspSearch::cusp_curve`]): beyond it the pop-out does not
    /// exist.
    Tip,
    /// The computed range of the free parameter ended there: beyond it the
    /// end value is taken.
    Range,
    /// The continuation stopped before either: beyond it θ0_c is not known
    /// ([`Error::NotMapped`]).
    Unfinished(Unfinished),
}

/// Why the continuation of a cusp line stopped early ([`LineEnd`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unfinished {
    /// The tangent kept turning by more than the maximum angle even at the
    /// minimum step ([`Error::StepAngleTooLarge`]).
    TangentTurned,
    /// Newton's corrector failed even at the minimum step.
    Newton,
    /// The step limit was reached.
    StepLimit,
    /// Any other failure (a located turn or event that could not be
    /// found, a singular or non-finite system).
    Other,
}

impl Unfinished {
    /// The reason of a cusp-curve run that ended with `t` (neither at its
    /// stop value nor at an event).
    #[must_use]
    pub fn of(t: &Termination) -> Self {
        match t {
            Termination::MaxSteps(_) => Self::StepLimit,
            Termination::Failed {
                error: Error::StepAngleTooLarge { .. },
                ..
            } => Self::TangentTurned,
            Termination::Failed {
                error: Error::NewtonDiverged { .. } | Error::NewtonNotConverged { .. },
                ..
            } => Self::Newton,
            _ => Self::Other,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Self::TangentTurned => "unfinished-tangent",
            Self::Newton => "unfinished-newton",
            Self::StepLimit => "unfinished-steps",
            Self::Other => "unfinished-other",
        }
    }
}

/// One cusp curve of one pop-out.
#[derive(Debug, Clone, PartialEq)]
pub struct CuspLine {
    /// The pop-out (0 for the first of the pull).
    pub pop_out: usize,
    /// The parameter held fixed.
    pub fixed: Fixed,
    /// The cusps in the order continuation traced them (a polyline), the
    /// free parameter (A/B or ν) increasing from the first to the last
    /// ([`PhaseDiagram::new`] reverses a line given the other way). Where
    /// the free parameter turns back (at a swallowtail, where the cusp
    /// curve has a cusp of its own) the line covers some A/B twice or
    /// more.
    pub points: Vec<CuspAt>,
    /// How the line ends at its first and at its last point.
    pub ends: [LineEnd; 2],
}

/// The cusp curves of a spring's pop-outs (n coils, C by the Nikolai
/// equality), and the number of pop-outs they predict.
///
/// A pop-out i exists where θ0 lies above its cusp curve θ0_c,i(A/B, ν)
/// (closer to 90°): the region's boundary is its cusp curve, and the
/// region ends where the curve reaches θ0 = 90°. [`PhaseDiagram::pop_outs`]
/// reads θ0_c,i off the lines at fixed ν ([`Fixed::Nu`]): linearly in
/// ln(A/B) along each line, then linearly in ν between the two lines of
/// the nearest ν on either side, each read at the same relative place
/// between its ends where both end at a tip on that side (the region's
/// edge in A/B, interpolated in ν: beyond it the pop-out does not exist),
/// not at the scene's own A/B, which put a shallow ramp in θ0_c where the
/// region has a steep edge.
///
/// Beyond a line's ends its [`LineEnd`] decides: beyond a [`LineEnd::Tip`]
/// (where the line reaches θ0 = 90°) the pop-out does not exist; beyond a
/// [`LineEnd::Range`] the end value is taken (the limits A/B → ∞ and
/// ν → −1 converge: the docs give how far the end values are from those
/// limits); beyond a [`LineEnd::Unfinished`] θ0_c is not known. Where a
/// line covers an A/B more than once (it turns back in A/B at
/// swallowtails of the cusp curve), θ0_c is known only to lie between its
/// values there: scenes between them are not mapped
/// ([`PhaseDiagram::cusp_theta0`], [`Error::NotMapped`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PhaseDiagram {
    coils: u32,
    lines: Vec<CuspLine>,
}

impl PhaseDiagram {
    /// A diagram of a spring of `coils` coils from its cusp lines; a line
    /// whose free parameter ends lower than it starts is reversed (points
    /// and ends), repeated points are dropped.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if a line has no point, a point outside
    /// θ0 ∈ (0, π/2], A/B > 0 finite, ν ∈ (−1, ½], a fixed value outside
    /// those ranges, or a pop-out index of `coils` or more.
    pub fn new(coils: u32, mut lines: Vec<CuspLine>) -> Result<Self> {
        for line in &mut lines {
            match line.fixed {
                Fixed::Nu(v) if !(v > -1.0 && v <= 0.5) => {
                    return Err(Error::InvalidArgument {
                        name: "cusp line fixed ν",
                        value: v,
                        allowed: "a Poisson ratio in (−1, ½]",
                    });
                }
                Fixed::AOverB(v) if !(v > 0.0 && v.is_finite()) => {
                    return Err(Error::InvalidArgument {
                        name: "cusp line fixed A/B",
                        value: v,
                        allowed: "a finite positive ratio A/B",
                    });
                }
                _ => {}
            }
            if line.points.is_empty() {
                return Err(Error::InvalidArgument {
                    name: "cusp line points",
                    value: 0.0,
                    allowed: "at least one cusp per line",
                });
            }
            // (a spring of n coils loses at most n − 1 loops: its pop-outs
            // are numbered 0 … n − 2; a larger index is not a diagram's and
            // would make every reading loop over it)
            if line.pop_out >= coils as usize {
                return Err(Error::InvalidArgument {
                    name: "cusp line pop-out",
                    value: line.pop_out as f64,
                    allowed: "pop-out indices below the number of coils",
                });
            }
            for p in &line.points {
                if !(p.theta0 > 0.0
                    && p.theta0 <= core::f64::consts::FRAC_PI_2 + 1e-12
                    && p.a_over_b > 0.0
                    && p.a_over_b.is_finite()
                    && p.nu > -1.0
                    && p.nu <= 0.5)
                {
                    return Err(Error::InvalidArgument {
                        name: "cusp point θ0",
                        value: p.theta0,
                        allowed: "cusps at θ0 in (0, π/2], A/B > 0 finite, ν in (−1, ½]",
                    });
                }
            }
            let fixed = line.fixed;
            let (first, last) = (line.points[0], line.points[line.points.len() - 1]);
            if key(fixed, &first) > key(fixed, &last) {
                line.points.reverse();
                line.ends.reverse();
            }
            line.points.dedup();
        }
        Ok(Self { coils, lines })
    }

    /// Number of coils.
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.coils
    }

    /// Every cusp line.
    #[must_use]
    pub fn lines(&self) -> &[CuspLine] {
        &self.lines
    }

    /// Whether the lines map every loop but the last: n − 1 pop-outs, as
    /// many as a spring of n coils can have. The lines are traced from the
    /// pop-outs of a reference spring (`examples/phase_diagram`: θ0 = 89.8°,
    /// A/B = 10, ν = 0.05), which for n = 2, 3, 4, 5, 6 has n − 1; where it has
    /// fewer (n = 8: 3 of 7 loops pop out there, the others unloop without
    /// a fold) the others are seeded from a scene where they pop out
    /// (n = 8: θ0 = 89.5°, A/B = 50; n = 7: 89°, 20, found by the
    /// example's check pulls). Until every loop is mapped,
    /// [`Self::pop_outs`] counts the mapped ones: a lower bound.
    #[must_use]
    pub fn is_complete(&self) -> bool {
        self.pop_out_count() + 1 >= self.coils as usize
    }

    /// The number of pop-outs mapped (lines traced).
    #[must_use]
    pub fn pop_out_count(&self) -> usize {
        self.lines.iter().map(|l| l.pop_out + 1).max().unwrap_or(0)
    }

    /// θ0_c of pop-out `i` at (A/B, ν) read off the lines at fixed ν (type
    /// docs): a single value (start = end) where the lines know it, the
    /// range it lies in where they do not (0 to π/2 beyond an unfinished
    /// line); π/2 where the pop-out does not exist at any θ0 < 90°.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless A/B > 0 finite and ν ∈ (−1, ½)
    /// (outside them the reading was an empty range, ∞ to −∞, or the
    /// nearest line's).
    pub fn cusp_theta0(&self, i: usize, a_over_b: f64, nu: f64) -> Result<RangeInclusive<f64>> {
        check_material(a_over_b, nu)?;
        Ok(self.bounds(i, a_over_b, nu).0)
    }

    /// The number of pop-outs of the spring (θ0, A/B, ν): how many cusp
    /// curves θ0 lies above (type docs). Of an incomplete diagram
    /// ([`Self::is_complete`]) it counts the mapped pop-outs only: a lower
    /// bound.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless θ0 ∈ (0, π/2), A/B > 0 finite and
    /// ν ∈ (−1, ½); [`Error::NotMapped`] where θ0 lies within the range of
    /// a pop-out's θ0_c that the diagram does not resolve
    /// ([`Self::cusp_theta0`]).
    pub fn pop_outs(&self, theta0: f64, a_over_b: f64, nu: f64) -> Result<usize> {
        if !(theta0 > 0.0 && theta0 < core::f64::consts::FRAC_PI_2) {
            return Err(Error::InvalidArgument {
                name: "theta0",
                value: theta0,
                allowed: "a helix angle in (0°, 90°)",
            });
        }
        check_material(a_over_b, nu)?;
        // only the pop-outs that have lines (an index without one lies at
        // 90°, above every scene); not 0..pop_out_count(), which a
        // diagram of many coils with one line of a large index made a
        // loop of billions of readings
        let mut mapped: Vec<usize> = self.lines.iter().map(|l| l.pop_out).collect();
        mapped.sort_unstable();
        mapped.dedup();
        let mut count = 0;
        for i in mapped {
            let (r, why) = self.bounds(i, a_over_b, nu);
            if theta0 > *r.end() {
                count += 1;
            } else if theta0 > *r.start() {
                return Err(Error::NotMapped {
                    pop_out: i as u64,
                    from_deg: r.start().to_degrees(),
                    to_deg: r.end().to_degrees(),
                    why,
                });
            }
        }
        Ok(count)
    }
}

/// The A/B and ν a diagram is read at.
fn check_material(a_over_b: f64, nu: f64) -> Result<()> {
    if !(a_over_b > 0.0 && a_over_b.is_finite()) {
        return Err(Error::InvalidArgument {
            name: "a_over_b",
            value: a_over_b,
            allowed: "a finite positive ratio A/B",
        });
    }
    if !(nu > -1.0 && nu < 0.5) {
        return Err(Error::InvalidArgument {
            name: "nu",
            value: nu,
            allowed: "a Poisson ratio in (−1, 0.5)",
        });
    }
    Ok(())
}

/// The free parameter of a line.
fn key(fixed: Fixed, p: &CuspAt) -> f64 {
    match fixed {
        Fixed::Nu(_) => p.a_over_b,
        Fixed::AOverB(_) => p.nu,
    }
}
