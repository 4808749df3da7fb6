//! `continuation`: every `Continuation` setting with hostile values, run on
//! Bratu (`bvp::classic`, 10 intervals) with a small step budget; events
//! that return NaN; observers that stop; branch switching at points that
//! are not branch points.

use std::cell::Cell;
use std::ops::ControlFlow;

use hockle::Error;
use hockle::bvp::classic::Bratu;
use hockle::bvp::{Collocation, Solution};
use hockle::continuation::{
    BranchSide, Continuation, Every, Observer, Output, Point, PointKind, Run, Termination,
};

use crate::bvp::solution_finite;
use crate::hostile::{Gen, Report, finite};

/// A run of at most `MAX_STEPS` steps on Bratu takes about a millisecond
/// (a call is one run, one iterator, one switch or one distance): about
/// 3 s in release.
pub const CI_CALLS: u64 = 10_000;

/// The step budget of a run with a hostile `max_steps` (an observer stops
/// the run there when `max_steps` is larger).
const MAX_STEPS: usize = 6;

/// The settings drawn for one run and whether each is valid
/// (`Continuation::new` documents each domain).
struct Drawn {
    cont: Continuation,
    valid: bool,
    max_steps: usize,
    stops: Vec<f64>,
    events: usize,
    /// The settings `Continuation`'s `Debug` does not show.
    hidden: String,
}

fn draw(g: &mut Gen) -> Drawn {
    let mut valid = true;
    let hostile = g.u64().is_multiple_of(2);
    let parameter = if hostile && g.u64().is_multiple_of(4) {
        g.count(2) as usize
    } else {
        0
    };
    valid &= parameter == 0;
    let mut cont = Continuation::new(parameter);
    let pick = |g: &mut Gen, ordinary: f64, lo: f64, hi: f64| {
        if hostile && g.u64().is_multiple_of(3) {
            g.arg(lo, hi)
        } else {
            ordinary
        }
    };
    let ds = pick(g, 0.1, -1.0, 1.0);
    valid &= ds.is_finite() && ds != 0.0;
    let (ds_min, ds_max) = (pick(g, 1e-8, 0.0, 1.0), pick(g, 0.5, 0.0, 1e3));
    valid &= ds_min > 0.0 && ds_min.is_finite() && ds_max >= ds_min && ds_max.is_finite();
    let theta = pick(g, 1.0, 0.0, 1e3);
    valid &= theta > 0.0 && theta.is_finite();
    let angle = pick(g, 0.35, 0.0, core::f64::consts::PI);
    valid &= angle > 0.0 && angle <= core::f64::consts::PI;
    let locate = pick(g, 1e-10, 0.0, 1.0);
    valid &= locate > 0.0 && locate.is_finite();
    let mut hidden =
        format!("parameter_weight {theta:e}, max_angle {angle:e}, locate_tolerance {locate:e}");
    cont = cont
        .step(ds)
        .step_bounds(ds_min, ds_max)
        .parameter_weight(theta)
        .max_angle(angle)
        .locate_tolerance(locate)
        .detect_folds(g.u64() & 1 == 0)
        .detect_branch_points(g.u64() & 1 == 0);
    let max_steps = if hostile {
        g.count(MAX_STEPS as u64) as usize
    } else {
        MAX_STEPS
    };
    cont = cont.max_steps(max_steps);
    if hostile && g.u64().is_multiple_of(3) {
        let max_newton = g.u32(12);
        valid &= max_newton >= 1;
        hidden += &format!(", max_newton {max_newton}");
        cont = cont.max_newton(max_newton);
    }
    if hostile && g.u64().is_multiple_of(3) {
        let len = (g.u64() % 4) as usize;
        let w: Vec<f64> = (0..len).map(|_| g.arg(0.0, 1e3)).collect();
        valid &= len == 2 && w.iter().all(|v| *v >= 0.0 && v.is_finite());
        hidden += &format!(", weights {w:?}");
        cont = cont.weights(&w);
    }
    if hostile && g.u64().is_multiple_of(4) {
        // the solver's own settings (validated by Collocation) and a free
        // parameter that clashes with λ
        let newton_tolerance = g.arg(1e-14, 1e-2);
        valid &= (1e-14..=1e-2).contains(&newton_tolerance);
        let clash = g.u64().is_multiple_of(4);
        valid &= !clash;
        let free: &[usize] = if clash { &[0] } else { &[] };
        cont = cont.solver(
            Collocation::new()
                .newton_tolerance(newton_tolerance)
                .free_parameters(free),
        );
    }
    if hostile && g.u64().is_multiple_of(3) {
        // the tolerance in the diagram's plane (issue 11): its output, its
        // scales, and whether the mesh adapts (audit15)
        let tol = g.arg(1e-12, 1.0);
        valid &= (1e-12..=1.0).contains(&tol);
        let output = match g.u64() % 3 {
            0 => Output::Norm,
            1 => {
                let component = g.count(2) as usize;
                valid &= component < 2;
                Output::EndValue {
                    component,
                    right: g.u64() & 1 == 0,
                }
            }
            _ => {
                let i = g.count(1) as usize;
                valid &= i < 1;
                Output::Parameter(i)
            }
        };
        let (sl, so) = (g.arg(0.0, 1e3), g.arg(0.0, 1e3));
        valid &= sl > 0.0 && sl.is_finite() && so > 0.0 && so.is_finite();
        let adapt = g.u64() & 1 == 0;
        hidden += &format!(
            ", tolerance {tol:e}, diagram {output:?} × ({sl:e}, {so:e}), adapt_mesh {adapt}"
        );
        cont = cont
            .tolerance(tol)
            .diagram(output, sl, so)
            .adapt_mesh(adapt);
    }
    let mut stops = Vec::new();
    for _ in 0..g.u64() % 3 {
        let v = if hostile { g.arg(-1.0, 4.0) } else { 2.0 };
        valid &= v.is_finite();
        stops.push(v);
        cont = cont.stop_at(v);
    }
    let events = (g.u64() % 3) as usize;
    for i in 0..events {
        // y′(0) minus a level, or a hostile constant
        let level = if g.u64() & 1 == 0 {
            1.0 + 2.0 * g.unit()
        } else {
            g.any_f64()
        };
        let constant = g.u64().is_multiple_of(4);
        hidden += &format!(
            ", event {i}: {} {level:e}",
            if constant { "constant" } else { "y′(0) −" }
        );
        cont = cont.stop_when(move |sol: &Solution| {
            if constant {
                level
            } else {
                sol.at_mesh(0)[1] - level - i as f64
            }
        });
    }
    Drawn {
        cont,
        valid,
        max_steps,
        stops,
        events,
        hidden,
    }
}

/// The start of every run: Bratu at λ = 0 on 10 intervals.
pub fn bratu_start() -> Solution {
    Collocation::new()
        .intervals(10)
        .solve(&Bratu::default(), |_s: f64| [0.0, 0.0], &[0.0])
        .expect("Bratu at λ = 0")
}

/// The errors a run with valid settings may end in before its first step:
/// the first tangent failed, or an event is NaN/∞ at the start.
fn start_refusal(e: &Error) -> bool {
    matches!(e, Error::NonFinite { .. } | Error::SingularJacobian { .. })
}

/// The errors documented for `Termination::Failed`.
fn failure(e: &Error) -> bool {
    matches!(
        e,
        Error::NewtonNotConverged { .. }
            | Error::NewtonDiverged { .. }
            | Error::SingularJacobian { .. }
            | Error::NonFinite { .. }
            | Error::StepAngleTooLarge { .. }
    )
}

/// A run keeps its points, each finite, and says why it ended.
fn check_run(r: &mut Report, run: &Run, d: &Drawn, stopped_by_us: bool, what: &dyn Fn() -> String) {
    let pts = run.points();
    let finite_points = pts.iter().all(|p| {
        finite(&[p.parameter(), p.arclength(), p.dparameter_ds()])
            && finite(p.parameters())
            && solution_finite(p.solution())
    });
    r.check(!pts.is_empty() && pts[0].kind() == PointKind::Start, || {
        format!("{}: no start point", what())
    });
    r.check(finite_points, || format!("{}: non-finite point", what()));
    r.check(run.accepted() <= pts.len(), || {
        format!(
            "{}: {} steps but {} points",
            what(),
            run.accepted(),
            pts.len()
        )
    });
    let last = pts.last().map(Point::kind);
    let ok = match run.termination() {
        Termination::MaxSteps(k) => *k == run.accepted() && *k <= d.max_steps,
        Termination::ParameterValue(v) => {
            d.stops.contains(v)
                && last == Some(PointKind::ParameterValue)
                && pts.last().is_some_and(|p| p.parameter() == *v)
        }
        Termination::Event(i) => *i < d.events && last == Some(PointKind::Event(*i)),
        Termination::Stopped => stopped_by_us,
        Termination::Failed { ds, error } => ds.is_finite() && *ds > 0.0 && failure(error),
        _ => false,
    };
    r.check(ok, || {
        format!(
            "{}: termination {:?} after {} points",
            what(),
            run.termination(),
            pts.len()
        )
    });
    if !matches!(run.termination(), Termination::Stopped) {
        r.check(run.accepted() <= d.max_steps, || {
            format!("{}: {} steps > max_steps", what(), run.accepted())
        });
    }
}

/// Stops a run after `limit` points.
struct StopAfter<'a> {
    limit: usize,
    seen: &'a Cell<usize>,
    finished: &'a Cell<bool>,
}

impl Observer for StopAfter<'_> {
    fn point(&mut self, _point: &Point) -> ControlFlow<()> {
        self.seen.set(self.seen.get() + 1);
        if self.seen.get() >= self.limit {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    }

    fn finish(&mut self, _termination: &Termination) {
        self.finished.set(true);
    }
}

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    let start = bratu_start();
    let problem = Bratu::default();
    while r.calls < calls {
        let d = draw(g);
        let what = || format!("{:?} ({}) on Bratu", d.cont, d.hidden);
        // more steps than the budget: an observer stops the run
        let limit = MAX_STEPS + 1;
        let (seen, finished) = (Cell::new(0), Cell::new(false));
        let every = g.pick(&[0, 1, 3]);
        let observer = Every::new(
            every,
            StopAfter {
                limit,
                seen: &seen,
                finished: &finished,
            },
        );
        let Some(res) = r.call(what, || d.cont.run(&problem, &start, observer)) else {
            continue;
        };
        match res {
            Ok(run) => {
                r.check(d.valid, || format!("{}: accepted", what()));
                r.check(finished.get(), || format!("{}: finish not called", what()));
                let stopped = seen.get() >= limit;
                check_run(r, &run, &d, stopped, &what);
                if let Some(p) = run
                    .points()
                    .iter()
                    .find(|p| p.kind() != PointKind::BranchPoint)
                {
                    not_a_branch_point(r, &d.cont, &problem, p);
                }
                if let Some(p) = run.points().last() {
                    distance(r, &d.cont, &start, p.solution());
                }
            }
            Err(e) => r.check(!d.valid || start_refusal(&e), || format!("{}: {e}", what())),
        }
        if g.u64().is_multiple_of(4) {
            steps(g, r, &d, &problem, &start);
        }
    }
}

/// The iterator form: the same settings, driven by hand for a few items.
fn steps(g: &mut Gen, r: &mut Report, d: &Drawn, problem: &Bratu, start: &Solution) {
    let take = (g.u64() % 8) as usize;
    let what = || format!("{:?}: steps().take({take})", d.cont);
    let Some(res) = r.call(what, || {
        d.cont.steps(problem, start).map(|mut s| {
            let pts: Vec<Point> = s.by_ref().take(take).collect();
            let done = s.termination().cloned();
            (pts, done, s.accepted(), s.step_size())
        })
    }) else {
        return;
    };
    match res {
        Ok((pts, done, accepted, ds)) => {
            r.check(d.valid, || format!("{}: accepted", what()));
            r.check(
                pts.iter().all(|p| solution_finite(p.solution()))
                    && accepted <= d.max_steps
                    && ds.is_finite()
                    && ds > 0.0
                    && (done.is_none() || pts.len() <= take),
                || format!("{}: bad iterator state", what()),
            );
        }
        Err(e) => r.check(!d.valid || start_refusal(&e), || format!("{}: {e}", what())),
    }
}

/// Switching at a point that is not a branch point is `NotABranchPoint`
/// (or the settings' own error).
fn not_a_branch_point(r: &mut Report, cont: &Continuation, problem: &Bratu, p: &Point) {
    for side in [BranchSide::Positive, BranchSide::Negative] {
        let what = || format!("{cont:?}: run_from_branch_point at a {:?} point", p.kind());
        if let Some(res) = r.call(what, || cont.run_from_branch_point(problem, p, side, ())) {
            r.check(matches!(res, Err(Error::NotABranchPoint { .. })), || {
                format!("{}: {res:?}", what())
            });
        }
    }
}

/// The distance of two solutions on the same mesh is finite and ≥ 0; on
/// different meshes an error.
fn distance(r: &mut Report, cont: &Continuation, a: &Solution, b: &Solution) {
    let what = || format!("{cont:?}: distance");
    // (a run with a tolerance remeshes: its points may lie on other meshes
    // than the start, whose distance is refused)
    let same_mesh = a.mesh() == b.mesh() && a.points_per_interval() == b.points_per_interval();
    if let Some(res) = r.call(what, || cont.distance(a, b)) {
        r.check(
            if same_mesh {
                res.as_ref().is_ok_and(|v| v.is_finite() && *v >= 0.0)
            } else {
                matches!(
                    res,
                    Err(Error::InvalidCount { .. } | Error::LengthMismatch { .. })
                )
            },
            || format!("{}: {res:?}", what()),
        );
    }
    let other = Collocation::new()
        .intervals(7)
        .solve(&Bratu::default(), |_s: f64| [0.0, 0.0], &[0.5])
        .expect("Bratu at λ = ½");
    if let Some(res) = r.call(what, || cont.distance(a, &other)) {
        r.check(res.is_err(), || {
            format!("{}: different meshes: {res:?}", what())
        });
    }
}
