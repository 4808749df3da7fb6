//! The number of pop-outs of a spring, read off its cusp curves
//! ([`PhaseDiagram`]).

use std::fmt::Write as _;
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

impl LineEnd {
    fn name(self) -> &'static str {
        match self {
            Self::Tip => "tip",
            Self::Range => "range",
            Self::Unfinished(u) => u.name(),
        }
    }

    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "tip" => Self::Tip,
            "range" => Self::Range,
            "unfinished-tangent" => Self::Unfinished(Unfinished::TangentTurned),
            "unfinished-newton" => Self::Unfinished(Unfinished::Newton),
            "unfinished-steps" => Self::Unfinished(Unfinished::StepLimit),
            "unfinished-other" => Self::Unfinished(Unfinished::Other),
            _ => return None,
        })
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
    /// A/B = 10, ν = 0.05), which for n = 2, 3, 4, 6 has n − 1; where it has
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

    /// [`Self::cusp_theta0`] and, where it is a range, why.
    fn bounds(&self, i: usize, a_over_b: f64, nu: f64) -> (RangeInclusive<f64>, &'static str) {
        let mut at: Vec<(f64, &CuspLine)> = self
            .lines
            .iter()
            .filter(|l| l.pop_out == i)
            .filter_map(|l| match l.fixed {
                Fixed::Nu(v) => Some((v, l)),
                Fixed::AOverB(_) => None,
            })
            .collect();
        at.sort_by(|a, b| a.0.total_cmp(&b.0));
        let half_pi = core::f64::consts::FRAC_PI_2;
        let x = a_over_b.ln();
        let b = match at.iter().position(|(v, _)| *v >= nu) {
            None => at.last().map_or(Bounds::exact(half_pi), |a| along(a.1, x)),
            Some(0) => along(at[0].1, x),
            Some(k) => {
                let ((v0, l0), (v1, l1)) = (at[k - 1], at[k]);
                let t = (nu - v0) / (v1 - v0);
                match aligned(l0, l1, t, x) {
                    None => Bounds::exact(half_pi),
                    Some([x0, x1]) => {
                        let (b0, b1) = (along(l0, x0), along(l1, x1));
                        Bounds {
                            lo: b0.lo + t * (b1.lo - b0.lo),
                            hi: b0.hi + t * (b1.hi - b0.hi),
                            why: b0.why.or(b1.why),
                        }
                    }
                }
            }
        };
        (b.lo..=b.hi, b.why.unwrap_or(""))
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

    /// The lines as CSV:
    /// `pop_out,fixed,theta0_deg,a_over_b,nu,force_scaled,ends` (`fixed` is
    /// `nu` or `a_over_b`; `ends` the [`LineEnd`]s of the line's first and
    /// last point, `tip`, `range` or `unfinished-<reason>`, as `first/last`),
    /// one row per cusp, lines and points in order; numbers with 17
    /// significant digits.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let mut out = String::from("pop_out,fixed,theta0_deg,a_over_b,nu,force_scaled,ends\n");
        for l in &self.lines {
            let fixed = match l.fixed {
                Fixed::Nu(_) => "nu",
                Fixed::AOverB(_) => "a_over_b",
            };
            let ends = format!("{}/{}", l.ends[0].name(), l.ends[1].name());
            for p in &l.points {
                let _ = writeln!(
                    out,
                    "{},{fixed},{:.16e},{:.16e},{:.16e},{:.16e},{ends}",
                    l.pop_out,
                    p.theta0.to_degrees(),
                    p.a_over_b,
                    p.nu,
                    p.force_scaled
                );
            }
        }
        out
    }

    /// Reads [`PhaseDiagram::to_csv`]'s format back (a new line starts
    /// where the pop-out, the fixed parameter or its value changes). The
    /// format without `ends` (the first committed diagrams of n = 2, 3, 4,
    /// 6, whose lines are complete) is read too: a line's first end is a
    /// [`LineEnd::Tip`] if its first point is at 90° (to 1e-9 rad), so is
    /// its last end for a line at fixed A/B, every other end a
    /// [`LineEnd::Range`].
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a first line that is not one of the
    /// two headers (`to_csv`'s, or the same without `,ends`: a file without
    /// its header would lose its first row), a malformed row or one whose
    /// number of fields is not its header's (the value is the row's line
    /// number in the file, from 1), and as [`PhaseDiagram::new`].
    pub fn from_csv(coils: u32, csv: &str) -> Result<Self> {
        const HEADER: &str = "pop_out,fixed,theta0_deg,a_over_b,nu,force_scaled";
        let mut rows = csv.lines().enumerate();
        let header = rows
            .next()
            .map(|(_, h)| h.trim_start_matches('\u{feff}').trim());
        let fields = match header {
            Some(h) if h == HEADER => 6,
            Some(h) if h.strip_prefix(HEADER) == Some(",ends") => 7,
            _ => {
                return Err(Error::InvalidArgument {
                    name: "phase diagram CSV header (line 1)",
                    value: 1.0,
                    allowed: "pop_out,fixed,theta0_deg,a_over_b,nu,force_scaled[,ends] \
                              (PhaseDiagram::to_csv)",
                });
            }
        };
        let mut lines: Vec<CuspLine> = Vec::new();
        for (row, text) in rows {
            let bad = || Error::InvalidArgument {
                name: "phase diagram CSV row (line number)",
                value: (row + 1) as f64,
                allowed: "pop_out,fixed (nu|a_over_b),theta0_deg,a_over_b,nu,force_scaled[,ends], \
                          as many fields as the header",
            };
            if text.trim().is_empty() {
                continue;
            }
            let f: Vec<&str> = text.split(',').collect();
            if f.len() != fields {
                return Err(bad());
            }
            let ends = match f.get(6) {
                None => None,
                Some(e) => {
                    let (a, b) = e.trim().split_once('/').ok_or_else(bad)?;
                    Some([
                        LineEnd::parse(a.trim()).ok_or_else(bad)?,
                        LineEnd::parse(b.trim()).ok_or_else(bad)?,
                    ])
                }
            };
            let num = |s: &str| s.trim().parse::<f64>().map_err(|_| bad());
            let pop_out = f[0].trim().parse::<usize>().map_err(|_| bad())?;
            let p = CuspAt {
                theta0: num(f[2])?.to_radians(),
                a_over_b: num(f[3])?,
                nu: num(f[4])?,
                force_scaled: num(f[5])?,
            };
            let fixed = match f[1].trim() {
                "nu" => Fixed::Nu(p.nu),
                "a_over_b" => Fixed::AOverB(p.a_over_b),
                _ => return Err(bad()),
            };
            match lines.last_mut() {
                Some(l) if l.pop_out == pop_out && l.fixed == fixed => l.points.push(p),
                _ => lines.push(CuspLine {
                    pop_out,
                    fixed,
                    points: vec![p],
                    ends: ends.unwrap_or([LineEnd::Range; 2]),
                }),
            }
            if ends.is_none() {
                let l = lines.last_mut().expect("pushed");
                let tip = |p: &CuspAt| p.theta0 >= core::f64::consts::FRAC_PI_2 - 1e-9;
                l.ends[0] = if tip(&l.points[0]) {
                    LineEnd::Tip
                } else {
                    LineEnd::Range
                };
                if let Fixed::AOverB(_) = l.fixed {
                    l.ends[1] = if tip(&p) {
                        LineEnd::Tip
                    } else {
                        LineEnd::Range
                    };
                }
            }
        }
        Self::new(coils, lines)
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

/// Where θ0_c lies, and why it is a range.
#[derive(Debug, Clone, Copy)]
struct Bounds {
    lo: f64,
    hi: f64,
    why: Option<&'static str>,
}

impl Bounds {
    fn exact(t: f64) -> Self {
        Self {
            lo: t,
            hi: t,
            why: None,
        }
    }
}

/// θ0_c along a line at fixed ν at x = ln(A/B), linear in x on each segment of
/// the polyline: beyond the ends as their [`LineEnd`]s say; where several
/// segments cover the A/B (the line turns back at swallowtails), the range
/// of their values.
fn along(line: &CuspLine, x: f64) -> Bounds {
    let half_pi = core::f64::consts::FRAC_PI_2;
    let points = &line.points;
    let beyond = |end: LineEnd, p: &CuspAt| match end {
        LineEnd::Tip => Bounds::exact(half_pi),
        LineEnd::Range => Bounds::exact(p.theta0),
        LineEnd::Unfinished(_) => Bounds {
            lo: 0.0,
            hi: half_pi,
            why: Some("the continuation of its cusp line ended before this scene"),
        },
    };
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return Bounds::exact(half_pi);
    };
    if x < first.a_over_b.ln() {
        return beyond(line.ends[0], first);
    }
    if x > last.a_over_b.ln() || points.len() == 1 {
        return beyond(line.ends[1], last);
    }
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for w in points.windows(2) {
        let (x0, x1) = (w[0].a_over_b.ln(), w[1].a_over_b.ln());
        if x < x0.min(x1) || x > x0.max(x1) {
            continue;
        }
        let t = if x1 == x0 { 0.0 } else { (x - x0) / (x1 - x0) };
        let v = w[0].theta0 + t * (w[1].theta0 - w[0].theta0);
        lo = lo.min(v);
        hi = hi.max(v);
    }
    // A/B is between the first and the last point, so some segment covers it.
    Bounds {
        lo,
        hi,
        why: (hi > lo).then_some(
            "its cusp line turns back over this A/B (swallowtails of the cusp curve) and θ0 lies between its branches",
        ),
    }
}

/// Where to read two lines at fixed ν0 < ν1 for the scene x = ln(A/B) at
/// ν = ν0 + t (ν1 − ν0): at the same relative place between their ends,
/// `None` where the pop-out does not exist there.
///
/// A region of a pop-out ends at a tip in A/B (the cusp curve reaches
/// θ0 = 90°, [`LineEnd::Tip`]), and the tip moves with ν: read at the
/// scene's own A/B, the line whose tip lies above it says 90° and the
/// other a θ0_c well below, so that interpolating the two in ν put a
/// shallow ramp where the region has a steep edge (n = 4 at
/// (89.943°, A/B = 2.89, ν = −0.061): read 89.72° and counted 3, where a
/// pull sees 2). So where both lines end at a tip on the
/// same side, the tip is interpolated in ν (in ln A/B) and each line is
/// read at the scene's relative place between the interpolated ends,
/// mapped onto its own ends (an affine map in ln A/B); beyond an
/// interpolated tip the pop-out does not exist. An end that is not a tip
/// on both lines is a common anchor (the smaller first, the larger last
/// ln A/B of the two), so that the map is the identity where neither end
/// is. Outside the anchored span the reading is shifted with its nearest
/// end. Leave-one-out on the committed diagrams (a line at fixed ν read
/// from its neighbours, ν spacing ≤ 0.2): the largest error of θ0_c falls
/// from 0.55°, 1.04°, 1.02°, 0.96°, 0.98° to 0.22°, 0.16°, 0.30°, 0.53°,
/// 0.47° for n = 2, 3, 4, 6, 8, and the scenes read on the wrong side of
/// a tip from 62, 213, 478, 1946, 4214 to 2, 11, 64, 653, 1781 of
/// 2406–16842 (docs/ACCURACY.md).
fn aligned(l0: &CuspLine, l1: &CuspLine, t: f64, x: f64) -> Option<[f64; 2]> {
    let ends = |l: &CuspLine| -> Option<(f64, f64)> {
        Some((
            l.points.first()?.a_over_b.ln(),
            l.points.last()?.a_over_b.ln(),
        ))
    };
    let (Some((a0, b0)), Some((a1, b1))) = (ends(l0), ends(l1)) else {
        return Some([x, x]);
    };
    let tip = |l: &CuspLine, side: usize| l.ends[side] == LineEnd::Tip;
    let (low_tips, high_tips) = (tip(l0, 0) && tip(l1, 0), tip(l0, 1) && tip(l1, 1));
    let low = if low_tips { [a0, a1] } else { [a0.min(a1); 2] };
    let high = if high_tips { [b0, b1] } else { [b0.max(b1); 2] };
    let lerp = |e: [f64; 2]| e[0] + t * (e[1] - e[0]);
    let (lo, hi) = (lerp(low), lerp(high));
    if (low_tips && x < lo) || (high_tips && x > hi) {
        return None;
    }
    let read = |k: usize| {
        if x < lo {
            x - lo + low[k]
        } else if x > hi {
            x - hi + high[k]
        } else if hi > lo {
            low[k] + (x - lo) * (high[k] - low[k]) / (hi - lo)
        } else {
            low[k]
        }
    };
    Some([read(0), read(1)])
}
