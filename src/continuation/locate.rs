//! Special-point location: folds, branch points, stop values and events
//! inside an accepted step, by the Illinois iteration on its arclength.

use super::corrector::Corrected;
use super::{PointKind, Steps};
use crate::bvp::system::State;
use crate::bvp::{Problem, Solution, newton};
use crate::error::{Error, Result};

/// What the location iteration is tracking.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Watch {
    Fold,
    BranchPoint,
    Stop(usize),
    Event(usize),
    /// A component of the tangent: the rate of the parameter with this
    /// index (the turns of a fold curve).
    Tangent(usize),
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    pub(super) fn watch_value(&self, w: Watch, c: &Corrected, log_ref: f64) -> f64 {
        let q = self.cont.parameter;
        match w {
            Watch::Fold => c.tangent.p[q],
            Watch::BranchPoint => c.det.sign * (c.det.log_abs - log_ref).exp(),
            Watch::Stop(i) => c.x.p[q] - self.cont.stops[i],
            Watch::Event(_) => f64::NAN,
            Watch::Tangent(i) => c.tangent.p[i],
        }
    }

    /// Illinois iteration for the zero of a watched function on the
    /// arclength interval [a, b] of the current step, given its values at
    /// the ends (of opposite signs, or one zero).
    pub(super) fn locate(
        &mut self,
        w: Watch,
        (a, fa): (f64, f64),
        (b, fb): (f64, f64),
        log_ref: f64,
    ) -> Result<(Corrected, f64)> {
        let (mut a, mut fa, mut b, mut fb) = (a, fa, b, fb);
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
                    let nudge = 0.5 * self.locate_tolerance * (b - a).signum();
                    self.correct(s + nudge, false)?
                }
                r => r?,
            };
            let fs = match w {
                Watch::Event(i) => self.event_value(i, &c.x)?,
                _ => self.watch_value(w, &c, log_ref),
            };
            let done = (s - prev).abs() <= self.locate_tolerance || fs == 0.0;
            prev = s;
            best = Some((c, s));
            if done || (b - a).abs() <= self.locate_tolerance {
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
            tolerance: self.locate_tolerance,
        })
    }
}

/// A located special point: the corrected point, its arclength within the
/// step, its kind, and whether it ends the run.
pub(super) type Located = (Corrected, f64, PointKind, bool);

/// The special points of one step, located and sorted by arclength.
pub(super) struct InStep {
    /// The located points.
    pub(super) found: Vec<Located>,
    /// The last error of a location (ends the run after `found`).
    pub(super) error: Option<Error>,
    /// The user events at the end of the step.
    pub(super) events: Vec<f64>,
    /// The solution at the end of the step, if the events needed it.
    pub(super) solution: Option<Solution>,
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// The special points inside the accepted step x₀ → `c` of arclength
    /// `ds`. A stop value is looked for on each piece of the step between
    /// located folds, so that a step over a fold cannot pass over a value
    /// it reaches twice.
    pub(super) fn special_points_in_step(&mut self, c: &Corrected, ds: f64) -> InStep {
        let q = self.cont.parameter;
        let mut found: Vec<Located> = Vec::new();
        let mut error: Option<Error> = None;
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
        for (w, f0, f1) in watches {
            let kind = match w {
                Watch::Fold => PointKind::Fold,
                _ => PointKind::BranchPoint,
            };
            match self.locate(w, (0.0, f0), (ds, f1), log_ref) {
                Ok((cs, s)) => found.push((cs, s, kind, false)),
                Err(e) => error = Some(e),
            }
        }
        // λ at the ends of the pieces between located folds.
        let mut knots = vec![(0.0, self.x0.p[q])];
        knots.extend(
            found
                .iter()
                .filter(|f| f.2 == PointKind::Fold)
                .map(|f| (f.1, f.0.x.p[q])),
        );
        knots.push((ds, c.x.p[q]));
        for i in 0..self.cont.stops.len() {
            let v = self.cont.stops[i];
            let piece = knots.windows(2).find(|k| {
                let (f0, f1) = (k[0].1 - v, k[1].1 - v);
                (f0 != 0.0 || k[0].0 > 0.0) && f0 * f1 <= 0.0
            });
            if let Some(k) = piece {
                let (a, b) = ((k[0].0, k[0].1 - v), (k[1].0, k[1].1 - v));
                match self.locate(Watch::Stop(i), a, b, log_ref) {
                    // (robust10b) a stop that cannot be put on its value
                    // is a failure, not a stop at another value
                    Ok((cs, s)) => match self.pin_parameter(cs, v) {
                        Ok(cs) => found.push((cs, s, PointKind::ParameterValue, true)),
                        Err(e) => error = Some(e),
                    },
                    Err(e) => error = Some(e),
                }
            }
        }
        let mut events = Vec::with_capacity(self.cont.events.len());
        let mut solution = None;
        if !self.cont.events.is_empty() {
            match self.solution(&c.x, Default::default()) {
                Ok(sol) => solution = Some(sol),
                Err(e) => error = Some(e),
            }
        }
        for i in 0..self.cont.events.len() {
            let f0 = self.events0[i];
            let f1 = match solution.as_ref().map(|sol| self.event_at(i, sol)) {
                Some(Ok(f1)) => f1,
                Some(Err(e)) => {
                    error = Some(e);
                    f64::NAN
                }
                None => f64::NAN,
            };
            events.push(f1);
            if f0 != 0.0 && f0 * f1 <= 0.0 {
                match self.locate(Watch::Event(i), (0.0, f0), (ds, f1), log_ref) {
                    Ok((cs, s)) => found.push((cs, s, PointKind::Event(i), true)),
                    Err(e) => error = Some(e),
                }
            }
        }
        found.sort_by(|a, b| a.1.total_cmp(&b.1));
        InStep {
            found,
            error,
            events,
            solution,
        }
    }

    /// Puts a located stop exactly on λ = `value`: Newton on the collocation
    /// equations with λ fixed (the border row λ = value) from the located
    /// point, then λ set to `value` (the corrector left it within rounding).
    /// If that fails (a value at a fold, where λ fixed is singular), the
    /// located point is kept, with λ set to `value`, only when it is on the
    /// value to the Newton tolerance, |λ − value| ≤ tol (1 + |value|);
    /// otherwise the Newton error (robust10b: before, the located point was
    /// kept wherever the location tolerance had left it, and the run ended
    /// with `ParameterValue` of a value nobody asked for).
    fn pin_parameter(&mut self, mut c: Corrected, value: f64) -> Result<Corrected> {
        self.set_parameter_border();
        self.sys.border.target[0] = value;
        let mut x = c.x.clone();
        let q = self.cont.parameter;
        match newton(&mut self.sys, &mut x, self.opts, false) {
            Ok(stats) => {
                self.newton_iterations += u64::from(stats.iterations);
                x.p[q] = value;
                c.x = x;
                c.iterations += stats.iterations;
            }
            Err(_) if (c.x.p[q] - value).abs() <= self.opts.tol * (1.0 + value.abs()) => {
                c.x.p[q] = value;
            }
            Err(e) => return Err(e),
        }
        Ok(c)
    }

    /// The user event `i` at `x`; a non-finite value is an error.
    pub(super) fn event_value(&mut self, i: usize, x: &State) -> Result<f64> {
        let sol = self.solution(x, Default::default())?;
        self.event_at(i, &sol)
    }

    /// The user event `i` on `sol`; a non-finite value is an error.
    pub(super) fn event_at(&self, i: usize, sol: &Solution) -> Result<f64> {
        let v = (self.cont.events[i])(sol);
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::NonFinite {
                what: "stop_when event",
                s: f64::NAN,
            })
        }
    }
}
