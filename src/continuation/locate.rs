//! Special-point location: folds, branch points, stop values and events
//! inside an accepted step, by the Illinois iteration on its arclength.

use super::corrector::Corrected;
use super::{PointKind, Steps};
use crate::bvp::Problem;
use crate::bvp::system::State;
use crate::error::{Error, Result};

/// What the location iteration is tracking.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Watch {
    Fold,
    BranchPoint,
    Stop(usize),
    Event(usize),
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    pub(super) fn watch_value(&self, w: Watch, c: &Corrected, log_ref: f64) -> f64 {
        let q = self.cont.parameter;
        match w {
            Watch::Fold => c.tangent.p[q],
            Watch::BranchPoint => c.det.sign * (c.det.log_abs - log_ref).exp(),
            Watch::Stop(i) => c.x.p[q] - self.cont.stops[i],
            Watch::Event(_) => f64::NAN,
        }
    }

    pub(super) fn event_value(&mut self, i: usize, x: &State) -> Result<f64> {
        let sol = self.solution(x, Default::default())?;
        Ok((self.cont.events[i])(&sol))
    }

    /// Illinois iteration for the zero of a watched function on [0, ds].
    pub(super) fn locate(
        &mut self,
        w: Watch,
        f0: f64,
        f1: f64,
        ds: f64,
        log_ref: f64,
    ) -> Result<(Corrected, f64)> {
        let (mut a, mut fa, mut b, mut fb) = (0.0, f0, ds, f1);
        let mut best: Option<(Corrected, f64)> = None;
        let mut prev = f64::NAN;
        for _ in 0..60 {
            let mut s = (a * fb - b * fa) / (fb - fa);
            if !s.is_finite() || s <= a.min(b) || s >= a.max(b) {
                s = 0.5 * (a + b);
            }
            let c = match self.correct(s, false) {
                Err(Error::SingularJacobian { .. }) => {
                    // Landed exactly on the singular point: step off it by
                    // a fraction of the tolerance.
                    let nudge = 0.5 * self.cont.locate_tolerance * (b - a).signum();
                    self.correct(s + nudge, false)?
                }
                r => r?,
            };
            let fs = match w {
                Watch::Event(i) => self.event_value(i, &c.x)?,
                _ => self.watch_value(w, &c, log_ref),
            };
            let done = (s - prev).abs() <= self.cont.locate_tolerance || fs == 0.0;
            prev = s;
            best = Some((c, s));
            if done || (b - a).abs() <= self.cont.locate_tolerance {
                break;
            }
            if fs * fb < 0.0 {
                a = b;
                fa = fb;
            } else {
                fa *= 0.5;
            }
            b = s;
            fb = fs;
        }
        best.ok_or(Error::NewtonNotConverged {
            iterations: 0,
            correction: f64::NAN,
            tolerance: self.cont.locate_tolerance,
        })
    }
}

/// A located special point: the corrected point, its arclength within the
/// step, its kind, and whether it ends the run.
pub(super) type Located = (Corrected, f64, PointKind, bool);

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// The special points inside the accepted step x₀ → `c` of arclength
    /// `ds`, located and sorted by arclength, with the last location error.
    pub(super) fn special_points_in_step(
        &mut self,
        c: &Corrected,
        ds: f64,
    ) -> (Vec<Located>, Option<Error>) {
        let q = self.cont.parameter;
        let mut found: Vec<Located> = Vec::new();
        let mut err: Option<Error> = None;
        let log_ref = self.det0.log_abs;
        let mut watches: Vec<(Watch, f64, f64)> = Vec::new();
        if !self.skip_detection {
            if self.cont.folds && self.t0.p[q] * c.tangent.p[q] < 0.0 {
                watches.push((Watch::Fold, self.t0.p[q], c.tangent.p[q]));
            }
            // (A NaN sign means the sparse fallback factorised: no test.)
            if self.cont.branch_points && self.det0.sign * c.det.sign < 0.0 {
                let f1 = c.det.sign * (c.det.log_abs - log_ref).exp();
                watches.push((Watch::BranchPoint, self.det0.sign, f1));
            }
        }
        for (i, v) in self.cont.stops.iter().enumerate() {
            let (f0, f1) = (self.x0.p[q] - v, c.x.p[q] - v);
            if f0 != 0.0 && f0 * f1 <= 0.0 {
                watches.push((Watch::Stop(i), f0, f1));
            }
        }
        for i in 0..self.cont.events.len() {
            let x0 = self.x0.clone();
            let f0 = self.event_value(i, &x0);
            let f1 = self.event_value(i, &c.x);
            match (f0, f1) {
                (Ok(f0), Ok(f1)) if f0 != 0.0 && f0 * f1 <= 0.0 => {
                    watches.push((Watch::Event(i), f0, f1))
                }
                (Err(e), _) | (_, Err(e)) => err = Some(e),
                _ => {}
            }
        }
        for (w, f0, f1) in watches {
            let kind = match w {
                Watch::Fold => PointKind::Fold,
                Watch::BranchPoint => PointKind::BranchPoint,
                Watch::Stop(_) => PointKind::ParameterValue,
                Watch::Event(i) => PointKind::Event(i),
            };
            let stop = matches!(w, Watch::Stop(_) | Watch::Event(_));
            match self.locate(w, f0, f1, ds, log_ref) {
                Ok((cs, s)) => found.push((cs, s, kind, stop)),
                Err(e) => {
                    err = Some(e);
                }
            }
        }
        found.sort_by(|a, b| a.1.total_cmp(&b.1));
        (found, err)
    }
}
