//! The number of pop-outs of a spring, read off its cusp curves
//! ([`PhaseDiagram`]).

use std::fmt::Write as _;

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
    /// The force of the meeting folds, F/((2πn)²B).
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

/// One cusp curve of one pop-out, in the order continuation traced it.
#[derive(Debug, Clone, PartialEq)]
pub struct CuspLine {
    /// The pop-out (0 for the first of the pull).
    pub pop_out: usize,
    /// The parameter held fixed.
    pub fixed: Fixed,
    /// The cusps, ordered by the free parameter (A/B or ν) increasing.
    pub points: Vec<CuspAt>,
}

/// The cusp curves of a spring's pop-outs (n coils, C by the Nikolai
/// equality), and the number of pop-outs they predict.
///
/// A pop-out i exists where θ0 lies above its cusp curve θ0_c,i(A/B, ν)
/// (closer to 90°): the region's boundary is its cusp curve, and the
/// region ends where the curve reaches θ0 = 90°. [`PhaseDiagram::pop_outs`]
/// reads θ0_c,i off the lines at fixed ν ([`Fixed::Nu`]): linearly in
/// ln(A/B) along each line, then linearly in ν between the two lines of
/// the nearest ν on either side.
///
/// Outside the lines' range the nearest line end is taken (the limits
/// A/B → ∞ and ν → −1 converge: the docs give how far the end values are
/// from those limits); below the smallest A/B of a line (where it reaches
/// θ0 = 90°) the pop-out does not exist.
#[derive(Debug, Clone, PartialEq)]
pub struct PhaseDiagram {
    coils: u32,
    lines: Vec<CuspLine>,
}

impl PhaseDiagram {
    /// A diagram of a spring of `coils` coils from its cusp lines.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if a line at fixed ν is not monotone in
    /// A/B (then θ0_c is not a function of A/B and this reading does not
    /// apply) or has a point outside θ0 ∈ (0, π/2], A/B > 0, ν ∈ (−1, ½].
    pub fn new(coils: u32, mut lines: Vec<CuspLine>) -> Result<Self> {
        for line in &mut lines {
            for p in &line.points {
                if !(p.theta0 > 0.0
                    && p.theta0 <= core::f64::consts::FRAC_PI_2 + 1e-12
                    && p.a_over_b > 0.0
                    && p.nu > -1.0
                    && p.nu <= 0.5)
                {
                    return Err(Error::InvalidArgument {
                        name: "cusp point θ0",
                        value: p.theta0,
                        allowed: "cusps at θ0 in (0, π/2], A/B > 0, ν in (−1, ½]",
                    });
                }
            }
            let key = |p: &CuspAt| match line.fixed {
                Fixed::Nu(_) => p.a_over_b,
                Fixed::AOverB(_) => p.nu,
            };
            line.points.sort_by(|a, b| key(a).total_cmp(&key(b)));
            line.points.dedup_by(|a, b| key(a) == key(b));
            if let Fixed::Nu(_) = line.fixed {
                let rising = line.points.windows(2).all(|w| w[1].theta0 <= w[0].theta0);
                if !rising {
                    return Err(Error::InvalidArgument {
                        name: "cusp line at fixed ν",
                        value: line.points.first().map_or(f64::NAN, |p| p.nu),
                        allowed: "θ0_c decreasing as A/B increases along the line",
                    });
                }
            }
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

    /// The number of pop-outs.
    #[must_use]
    pub fn pop_out_count(&self) -> usize {
        self.lines.iter().map(|l| l.pop_out + 1).max().unwrap_or(0)
    }

    /// θ0_c of pop-out `i` at (A/B, ν) read off the lines at fixed ν (type
    /// docs); π/2 where the pop-out does not exist at any θ0 < 90°.
    #[must_use]
    pub fn cusp_theta0(&self, i: usize, a_over_b: f64, nu: f64) -> f64 {
        let mut at: Vec<(f64, f64)> = self
            .lines
            .iter()
            .filter(|l| l.pop_out == i)
            .filter_map(|l| match l.fixed {
                Fixed::Nu(v) => Some((v, along(&l.points, a_over_b))),
                Fixed::AOverB(_) => None,
            })
            .collect();
        at.sort_by(|a, b| a.0.total_cmp(&b.0));
        let half_pi = core::f64::consts::FRAC_PI_2;
        match at.iter().position(|(v, _)| *v >= nu) {
            None => at.last().map_or(half_pi, |a| a.1),
            Some(0) => at[0].1,
            Some(k) => {
                let ((v0, t0), (v1, t1)) = (at[k - 1], at[k]);
                let t = (nu - v0) / (v1 - v0);
                t0 + t * (t1 - t0)
            }
        }
    }

    /// The number of pop-outs of the spring (θ0, A/B, ν): how many cusp
    /// curves θ0 lies above (type docs).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless θ0 ∈ (0, π/2), A/B > 0 finite and
    /// ν ∈ (−1, ½).
    pub fn pop_outs(&self, theta0: f64, a_over_b: f64, nu: f64) -> Result<usize> {
        if !(theta0 > 0.0 && theta0 < core::f64::consts::FRAC_PI_2) {
            return Err(Error::InvalidArgument {
                name: "theta0",
                value: theta0,
                allowed: "a helix angle in (0°, 90°)",
            });
        }
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
        Ok((0..self.pop_out_count())
            .filter(|&i| theta0 > self.cusp_theta0(i, a_over_b, nu))
            .count())
    }

    /// The lines as CSV: `pop_out,fixed,theta0_deg,a_over_b,nu,force_scaled`
    /// (`fixed` is `nu` or `a_over_b`), one row per cusp, lines in order;
    /// numbers with 17 significant digits.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let mut out = String::from("pop_out,fixed,theta0_deg,a_over_b,nu,force_scaled\n");
        for l in &self.lines {
            let fixed = match l.fixed {
                Fixed::Nu(_) => "nu",
                Fixed::AOverB(_) => "a_over_b",
            };
            for p in &l.points {
                let _ = writeln!(
                    out,
                    "{},{fixed},{:.16e},{:.16e},{:.16e},{:.16e}",
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
    /// where the pop-out, the fixed parameter or its value changes).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a malformed row (its number is the
    /// value), and as [`PhaseDiagram::new`].
    pub fn from_csv(coils: u32, csv: &str) -> Result<Self> {
        let mut lines: Vec<CuspLine> = Vec::new();
        for (row, text) in csv.lines().enumerate().skip(1) {
            let bad = || Error::InvalidArgument {
                name: "phase diagram CSV row",
                value: row as f64,
                allowed: "pop_out,fixed (nu|a_over_b),theta0_deg,a_over_b,nu,force_scaled",
            };
            if text.trim().is_empty() {
                continue;
            }
            let f: Vec<&str> = text.split(',').collect();
            if f.len() != 6 {
                return Err(bad());
            }
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
                }),
            }
        }
        Self::new(coils, lines)
    }
}

/// θ0_c along a line at fixed ν (points by A/B increasing), linear in
/// ln(A/B): π/2 below the line's first A/B if that end is at θ0 = 90°,
/// the end values beyond its ends otherwise.
fn along(points: &[CuspAt], a_over_b: f64) -> f64 {
    let half_pi = core::f64::consts::FRAC_PI_2;
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return half_pi;
    };
    if a_over_b < first.a_over_b {
        // the line ends at 90° (the region's tip) or at the computed range
        return if first.theta0 >= half_pi - 1e-9 {
            half_pi
        } else {
            first.theta0
        };
    }
    if a_over_b >= last.a_over_b {
        return last.theta0;
    }
    let k = points.partition_point(|p| p.a_over_b <= a_over_b);
    let (p0, p1) = (points[k - 1], points[k]);
    let t = (a_over_b.ln() - p0.a_over_b.ln()) / (p1.a_over_b.ln() - p0.a_over_b.ln());
    p0.theta0 + t * (p1.theta0 - p0.theta0)
}
