//! `rod`: `Rod::new`, `with_intrinsic_strains`, every `Pull` setting and
//! `Target` with hostile values (checked without solving), and real pulls
//! with tiny budgets (a few intervals, at most `PULL_STEPS` steps).

use core::f64::consts::{FRAC_PI_2, PI};

use hockle::continuation::Termination;
use hockle::nalgebra::Vector3;
use hockle::rod::{Equilibrium, Pull, PullRun, Rod};
use hockle::{Error, Stiffness, Target};

use crate::continuation::bratu_start;
use crate::hostile::{Gen, Report, finite};

/// Constructors and checks take microseconds, a real pull (at most 12
/// intervals, 5 steps) a few milliseconds; one valid pull in 8 (522)
/// are run: about 2 s in release.
pub const CI_CALLS: u64 = 60_000;

/// The step budget of a real pull.
pub const PULL_STEPS: usize = 5;

fn positive(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

/// (2πn)²B finite and positive: the force scale exists.
pub fn scale_ok(n: u32, b: f64) -> bool {
    let t = 2.0 * PI * f64::from(n);
    let v = t * t * b;
    n >= 1 && positive(b) && positive(v)
}

/// Stiffnesses: ordinary half the time, else hostile; `None` when the
/// constructor (rightly) refused them.
pub fn stiffness(g: &mut Gen, r: &mut Report) -> Option<Stiffness> {
    if g.u64() & 1 == 0 {
        let ab = g.pick(&[10.0, 1.0, 0.1, 100.0, 0.01]);
        return Stiffness::nikolai(ab, g.pick(&[0.05, 0.0, 0.3])).ok();
    }
    let (a, b, c) = (g.arg(0.0, 1e3), g.arg(0.0, 1e3), g.arg(0.0, 1e3));
    let res = r.call(
        || format!("Stiffness::new({a:e}, {b:e}, {c:e})"),
        || Stiffness::new(a, b, c),
    )?;
    let valid = positive(a) && positive(b) && positive(c);
    r.check(valid == res.is_ok(), || {
        format!("Stiffness::new({a:e}, {b:e}, {c:e}) = {res:?}")
    });
    res.ok()
}

/// A helix angle: an ordinary one, the ends of (0, π/2], or hostile.
pub fn helix_angle(g: &mut Gen) -> f64 {
    match g.u64() % 4 {
        0 => g.pick(&[89.8_f64, 60.0, 30.0, 89.99]).to_radians(),
        _ => g.arg(0.0, FRAC_PI_2),
    }
}

/// A target: ordinary, at the edge of the domain, or hostile.
pub fn target(g: &mut Gen, rest: f64) -> Target {
    let force = g.u64() & 1 == 0;
    let v = match g.u64() % 4 {
        0 if force => g.pick(&[0.5, 1e-4, 1e-9, -0.1, 3.0]),
        0 => g.pick(&[rest + 1e-3, rest, 0.9, -0.5]),
        1 if !force => g.arg(-1.0, 1.0),
        _ => g.any_f64(),
    };
    if force {
        Target::Force(v)
    } else {
        Target::Extension(v)
    }
}

/// Whether a force target's physical value f·(2πn)²B is a double (the
/// rod's pull refuses it otherwise).
pub fn force_in_range(t: Target, scale: f64) -> bool {
    match t {
        Target::Force(f) => (f * scale).is_finite(),
        Target::Extension(_) => true,
    }
}

/// Whether the pull's norm can square the force scale: 1/((2πn)²B)² is a
/// normal double.
pub fn norm_ok(scale: f64) -> bool {
    let theta = 1.0 / (scale * scale);
    theta.is_finite() && theta > 0.0
}

/// Whether a target is in its documented domain for a rest extension.
pub fn target_ok(t: Target, rest: f64) -> bool {
    match t {
        Target::Force(f) => f.is_finite() && f != 0.0,
        Target::Extension(dz) => dz > -1.0 && dz < 1.0 && dz != rest,
    }
}

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    let bratu = bratu_start();
    while r.calls < calls {
        let Some(s) = stiffness(g, r) else { continue };
        let n = g.u32(8);
        let th = helix_angle(g);
        let what = || format!("Rod::new({n}, {th:e}, {s})");
        let Some(res) = r.call(what, || Rod::new(n, th, s)) else {
            continue;
        };
        let valid = scale_ok(n, s.b()) && th > 0.0 && th <= FRAC_PI_2;
        let mut rod = match res {
            Ok(rod) => {
                r.check(valid, || format!("{} accepted", what()));
                rod
            }
            Err(e) => {
                r.check(!valid, || format!("{}: {e}", what()));
                continue;
            }
        };
        let helical = !g.u64().is_multiple_of(4);
        if !helical {
            let u = Vector3::new(g.arg(-10.0, 10.0), g.arg(0.0, 30.0), g.arg(0.0, 30.0));
            let what = || format!("{rod}: with_intrinsic_strains({u:?})");
            let Some(res) = r.call(what, || rod.with_intrinsic_strains(u)) else {
                continue;
            };
            let ok = u.iter().all(|v| v.is_finite());
            match res {
                Ok(with) => {
                    r.check(ok && finite(with.intrinsic_strains().as_slice()), || {
                        format!("{} = {:?}", what(), with.intrinsic_strains())
                    });
                    rod = with;
                }
                Err(e) => r.check(!ok, || format!("{}: {e}", what())),
            }
        }
        let rest = if rod.is_helical() { th.cos() } else { f64::NAN };
        let t = target(g, rest);
        let pull = settings(g, r, rod, t, rest);
        if let Some(pull) = pull
            && g.u64().is_multiple_of(8)
        {
            run(g, r, pull, &bratu);
        }
    }
}

/// `Pull::check` with hostile settings: Ok exactly when every setting and
/// the target are in their documented domains. Returns the pull when it is
/// valid (with a small budget, for `run`).
fn settings(g: &mut Gen, r: &mut Report, rod: Rod, t: Target, rest: f64) -> Option<Pull> {
    let hostile = g.u64() & 1 == 0;
    let mut pull = Pull::new(rod, t);
    let intervals = if hostile {
        g.count(12) as usize
    } else {
        4 + (g.u64() % 9) as usize
    };
    let points = if hostile {
        g.count(4) as usize
    } else {
        2 + (g.u64() % 3) as usize
    };
    pull = pull.intervals(intervals).points(points);
    let mut step_ok = true;
    if hostile && g.u64() & 1 == 0 {
        let (ds, lo, hi) = (g.arg(-0.1, 0.1), g.arg(0.0, 0.1), g.arg(0.0, 1.0));
        step_ok = lo > 0.0 && lo <= ds.abs() && ds.abs() <= hi && hi.is_finite();
        pull = pull.step(ds, lo, hi);
    }
    let angle = if hostile && g.u64() & 1 == 0 {
        g.arg(0.0, PI)
    } else {
        0.3
    };
    let max_steps = if hostile {
        g.count(PULL_STEPS as u64) as usize
    } else {
        PULL_STEPS
    };
    pull = pull
        .max_angle(angle)
        .max_steps(max_steps)
        .locate_folds(g.u64() & 1 == 0);
    // the accuracy knob (issue 11; audit15), on the fixed mesh drawn
    let mut tol_ok = true;
    if hostile && g.u64().is_multiple_of(3) {
        let tol = g.arg(1e-12, 0.1);
        tol_ok = (1e-12..=0.1).contains(&tol);
        pull = pull.tolerance(tol);
    }
    let valid = tol_ok
        && rod.theta0() != FRAC_PI_2
        && target_ok(t, rest)
        && force_in_range(t, rod.scale().value())
        && norm_ok(rod.scale().value())
        && reciprocals_ok(&rod)
        && step_ok
        && angle > 0.0
        && angle <= PI
        && max_steps >= 1
        && (1..=hockle::bvp::Mesh::MAX_INTERVALS).contains(&intervals)
        && (2..=7).contains(&points);
    let what = || format!("{pull:?}: check");
    let res = r.call(what, || pull.check())?;
    match res {
        Ok(_) => r.check(valid, || format!("{} accepted", what())),
        Err(e) => {
            r.check(!valid, || format!("{}: {e}", what()));
            return None;
        }
    }
    // the real run: a small mesh and budget
    Some(
        pull.intervals(intervals.min(12))
            .max_steps(max_steps.min(PULL_STEPS)),
    )
}

/// Whether every stiffness of the rod has a finite reciprocal (the
/// strains are M/K; `Pull::check`).
pub(crate) fn reciprocals_ok(rod: &Rod) -> bool {
    let k = rod.stiffness();
    [k.a(), k.b(), k.c()].iter().all(|v| (1.0 / v).is_finite())
}

/// Errors a valid pull may still end in before its first step: the rest
/// state or the first-step equilibrium could not be solved (a hostile
/// stiffness or intrinsic strain), or the norm's weights, scaled by
/// (2πn)²B, left the double range.
fn pull_refusal(e: &Error) -> bool {
    matches!(
        e,
        Error::NonFinite { .. }
            | Error::SingularJacobian { .. }
            | Error::NewtonDiverged { .. }
            | Error::NewtonNotConverged { .. }
            | Error::UnreachableTarget { .. }
            | Error::OutsideModel { .. }
    )
}

/// A pull that ran keeps its points, each finite, and says why it ended.
pub fn check_pull(r: &mut Report, run: &PullRun, max_steps: usize, what: &dyn Fn() -> String) {
    let c = run.curve();
    let pts_ok = c
        .points()
        .iter()
        .all(|p| finite(&[p.extension, p.force, p.parameter]) && p.extension.abs() <= 1.0 + 1e-9);
    r.check(!c.is_empty() && pts_ok, || {
        let worst = c
            .points()
            .iter()
            .map(|p| p.extension.abs())
            .fold(0.0, f64::max);
        format!("{}: bad curve {c}, largest |Δz| = {worst:e}", what())
    });
    r.check(run.loops().len() == c.len(), || {
        format!(
            "{}: {} loop counts for {} points",
            what(),
            run.loops().len(),
            c.len()
        )
    });
    r.check(run.folds().iter().all(|f| f.index < c.len()), || {
        format!("{}: fold index past the curve", what())
    });
    let ok = match run.termination() {
        Termination::ParameterValue(_) => {
            let last = c.points().last().map(|p| p.force_scaled(c.scale()));
            let end = match run.target() {
                Target::Force(f) => last.is_some_and(|l| (l - f).abs() <= 1e-9 * f.abs().max(1.0)),
                Target::Extension(dz) => c
                    .points()
                    .last()
                    .is_some_and(|p| (p.extension - dz).abs() <= 1e-9),
            };
            end && run.reached_target()
        }
        Termination::MaxSteps(k) => *k == run.steps() && *k <= max_steps,
        Termination::Failed { ds, error } => {
            ds.is_finite()
                && *ds > 0.0
                && matches!(
                    error,
                    Error::NewtonNotConverged { .. }
                        | Error::NewtonDiverged { .. }
                        | Error::SingularJacobian { .. }
                        | Error::NonFinite { .. }
                        | Error::StepAngleTooLarge { .. }
                        | Error::NotARod { .. }
                        | Error::CorrectorDrifted { .. }
                )
        }
        _ => false,
    };
    r.check(ok, || {
        format!(
            "{}: termination {:?} ({} points)",
            what(),
            run.termination(),
            c.len()
        )
    });
}

/// A real pull with a tiny budget, its step iterator, and the outputs of
/// its last equilibrium at hostile arclengths.
fn run(g: &mut Gen, r: &mut Report, pull: Pull, bratu: &hockle::bvp::Solution) {
    let what = || format!("{pull:?}: run");
    let Some(res) = r.call(what, || pull.run(())) else {
        return;
    };
    let run = match res {
        Ok(run) => run,
        Err(e) => {
            r.check(pull_refusal(&e), || format!("{}: {e}", what()));
            return;
        }
    };
    check_pull(r, &run, PULL_STEPS, &what);
    let what = || format!("{pull:?}: start().steps()");
    if let Some(res) = r.call(what, || {
        pull.start().and_then(|s| Ok(s.steps()?.take(3).count()))
    }) {
        r.check(res.as_ref().is_ok_and(|k| *k >= 1), || {
            format!("{}: {res:?}", what())
        });
    }
    // the outputs of the rest state
    let what = || format!("{pull:?}: Equilibrium of the rest state");
    let Some(Ok(eq)) = r.call(what, || {
        pull.start()
            .and_then(|s| Equilibrium::new(*pull.rod(), s.rest().clone()))
    }) else {
        r.check(false, || format!("{}: failed after a run", what()));
        return;
    };
    for _ in 0..4 {
        let s = g.arg(0.0, 1.0);
        let inside = (0.0..=1.0).contains(&s);
        let what = || format!("{pull:?}: rest outputs at s = {s:e}");
        if let Some(v) = r.call(what, || {
            let u = eq.strains(s)?;
            let r = eq.centreline(s)?;
            Ok::<_, Error>([
                eq.state(s)?[9],
                r.x,
                r.y,
                r.z,
                eq.frame(s)?.angle(),
                u.x,
                u.y,
                u.z,
                eq.curvature(s)?,
                eq.twist(s)?,
            ])
        }) {
            match v {
                Ok(v) => r.check(inside && finite(&v), || format!("{} = {v:?}", what())),
                Err(e) => r.check(
                    !inside && matches!(e, Error::InvalidArgument { name: "s", .. }),
                    || format!("{}: {e}", what()),
                ),
            }
        }
    }
    let samples = g.count(20) as usize;
    let samples = if samples > 200 && samples <= (hockle::error::MAX_POINTS - 1) {
        200
    } else {
        samples
    };
    let what = || format!("{pull:?}: centreline_samples({samples})");
    if let Some(res) = r.call(what, || eq.centreline_samples(samples)) {
        match res {
            Ok(c) => r.check(
                (1..=(hockle::error::MAX_POINTS - 1)).contains(&samples)
                    && c.len() == samples + 1
                    && c.iter().all(|p| finite(p.as_slice())),
                || format!("{}: bad Ok", what()),
            ),
            Err(e) => r.check(
                !(1..=(hockle::error::MAX_POINTS - 1)).contains(&samples),
                || format!("{}: {e}", what()),
            ),
        }
    }
    let scalars = [
        eq.energy(),
        eq.planarity(),
        eq.turning_number(),
        eq.axial_turns(),
        eq.quaternion_drift(),
        eq.force_scaled(),
        eq.extension(),
    ];
    r.check(finite(&scalars), || {
        format!("{pull:?}: rest scalars {scalars:?}")
    });
    // a solution of another problem is not an equilibrium
    let what = || "Equilibrium::new(rod, a Bratu solution)".to_string();
    if let Some(res) = r.call(what, || Equilibrium::new(*pull.rod(), bratu.clone())) {
        r.check(matches!(res, Err(Error::InvalidCount { .. })), || {
            format!("{}: {res:?}", what())
        });
    }
}
