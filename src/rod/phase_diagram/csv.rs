//! The diagram's lines as CSV and back ([`PhaseDiagram::to_csv`],
//! [`PhaseDiagram::from_csv`]).

use std::fmt::Write as _;

use super::{CuspAt, CuspLine, Fixed, LineEnd, PhaseDiagram, Unfinished};
use crate::error::{Error, Result};

impl PhaseDiagram {
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
