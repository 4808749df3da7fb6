//! `spring`: `Spring::new`/`from_degrees`/`with_intrinsic_strains`, the
//! models' constructors, and every `Model::pull_to` with hostile targets
//! (the rod with a tiny mesh, stopped by an observer after a few points).

use core::f64::consts::FRAC_PI_2;
use std::cell::Cell;
use std::ops::ControlFlow;

use hockle::continuation::{Point, Termination};
use hockle::error::MAX_POINTS as MAX_SAMPLES;
use hockle::nalgebra::Vector3;
use hockle::spring::{
    ElasticaModel, HelixModel, Model, Question, Response, RodModel, Spring, Value,
};
use hockle::{Error, Target};

use crate::curve::response_entries;
use crate::hostile::{Gen, Report, finite};
use crate::rod::{force_in_range, helix_angle, norm_ok, scale_ok, stiffness, target, target_ok};

/// Springs take microseconds, a helix pull tens of microseconds, an
/// elastica pull a millisecond, a stopped rod pull a few, a refused
/// question microseconds: about 2 s.
pub const CI_CALLS: u64 = 50_000;

/// The rod pull is stopped after this many points.
const ROD_POINTS: usize = 4;

/// Most samples a model draws its curve with in the fuzz loop.
const SAMPLES: usize = 50;

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
        let Some(s) = stiffness(g, r) else { continue };
        let n = g.u32(8);
        let degrees = g.u64().is_multiple_of(4);
        let th = if degrees {
            g.arg(0.0, 90.0)
        } else {
            helix_angle(g)
        };
        let what = || {
            format!(
                "Spring::new({n}, {th:e}{}, {s})",
                if degrees { "°" } else { "" }
            )
        };
        let Some(res) = r.call(what, || {
            if degrees {
                Spring::from_degrees(n, th, s)
            } else {
                Spring::new(n, th, s)
            }
        }) else {
            continue;
        };
        let rad = if degrees { th.to_radians() } else { th };
        let valid = scale_ok(n, s.b()) && rad > 0.0 && rad <= FRAC_PI_2;
        let mut spring = match res {
            Ok(sp) => {
                r.check(valid, || format!("{} accepted", what()));
                sp
            }
            Err(e) => {
                r.check(!valid, || format!("{}: {e}", what()));
                continue;
            }
        };
        if g.u64().is_multiple_of(8) {
            let u = Vector3::new(g.arg(-10.0, 10.0), g.any_f64(), g.arg(0.0, 30.0));
            let what = || format!("{spring}: with_intrinsic_strains({u:?})");
            let Some(res) = r.call(what, || spring.with_intrinsic_strains(u)) else {
                continue;
            };
            let ok = u.iter().all(|v| v.is_finite());
            match res {
                Ok(sp) => {
                    r.check(ok, || format!("{} accepted", what()));
                    spring = sp;
                }
                Err(e) => r.check(!ok, || format!("{}: {e}", what())),
            }
        }
        r.check(
            spring.force_scale().is_finite() && spring.force_scale() > 0.0,
            || format!("{spring}: force scale {}", spring.force_scale()),
        );
        models(g, r, &spring);
        if g.u64().is_multiple_of(2) {
            questions(g, r, &spring);
        }
    }
}

/// A hostile `Question` (issue 14): its values drawn near rest, at the
/// ends of their domains, or anything.
fn question(g: &mut Gen, rest: f64) -> Question {
    let values = |g: &mut Gen, around: f64| -> Vec<f64> {
        let len = (g.u64() % 4) as usize;
        (0..len)
            .map(|_| match g.u64() % 3 {
                0 => around + g.arg(-1e-3, 1e-3),
                1 => g.arg(-1.0, 1.0),
                _ => g.any_f64(),
            })
            .collect()
    };
    match g.u64() % 6 {
        0 => Question::Curve {
            max_force: g.any_f64(),
        },
        1 => Question::PopOuts {
            max_force: g.any_f64(),
        },
        2 => Question::ForcesAt(values(g, rest)),
        3 => Question::ExtensionsAt(values(g, 0.0)),
        4 => Question::Shape {
            at: target(g, rest),
        },
        _ => Question::SpringConstant,
    }
}

/// Whether `q` is a valid question for a spring whose rest extension is
/// `rest` (NaN: not known), from `Question`'s docs.
fn question_ok(q: &Question, rest: f64) -> bool {
    // every value at rest or on one side of it, and one off it
    let side = |v: &[f64], at: f64| {
        (v.iter().all(|x| *x >= at) || v.iter().all(|x| *x <= at)) && v.iter().any(|x| *x != at)
    };
    match q {
        Question::Curve { max_force } | Question::PopOuts { max_force } => {
            max_force.is_finite() && *max_force != 0.0
        }
        Question::ForcesAt(x) => {
            !x.is_empty()
                && finite(x)
                && !rest.is_nan()
                && side(x, rest)
                && x.iter().all(|v| *v > -1.0 && *v < 1.0)
        }
        Question::ExtensionsAt(f) => !f.is_empty() && finite(f) && side(f, 0.0),
        Question::Shape { at } => target_ok(*at, rest),
        _ => true,
    }
}

/// `Question::check`/`target` and `Spring::answer` where it costs nothing:
/// a refused question or tolerance is a typed error before any pull, the
/// spring constant a closed form.
fn questions(g: &mut Gen, r: &mut Report, spring: &Spring) {
    let rest = if spring.is_helical() {
        spring.helix_angle().cos()
    } else {
        f64::NAN
    };
    let q = question(g, rest);
    let tol = g.arg(1e-12, 0.1);
    let valid = question_ok(&q, rest);
    let what = || format!("{q:?}.target({rest:e})");
    if let Some(res) = r.call(what, || q.target(rest)) {
        r.check(res.is_ok() == valid, || format!("{}: {res:?}", what()));
    }
    let tol_ok =
        tol.is_finite() && tol > 0.0 && (matches!(q, Question::SpringConstant) || tol <= 0.1);
    let constant = matches!(q, Question::SpringConstant);
    if valid && tol_ok && !constant {
        return; // a pull: the models' entries run those
    }
    let what = || format!("{spring}: answer({q:?}, {tol:e})");
    let Some(res) = r.call(what, || spring.answer(&q, tol)) else {
        return;
    };
    match res {
        Ok(a) => r.check(
            constant
                && tol_ok
                && spring.is_helical()
                && matches!(a.value(), Value::SpringConstant(k) if k.is_finite() && *k > 0.0),
            || format!("{}: {a:?}", what()),
        ),
        Err(e) => r.check(
            !(valid && tol_ok) || matches!(e, Error::Overflow { .. } | Error::OutsideModel { .. }),
            || format!("{}: {e}", what()),
        ),
    }
}

/// The errors a documented-valid pull may give: the model cannot represent
/// this spring or target (a push, custom strains), the elastica branch
/// does not reach the force, the closed form overflows, the solver failed.
fn model_refusal(e: &Error) -> bool {
    matches!(
        e,
        Error::OutsideModel { .. }
            | Error::ForceOutOfReach { .. }
            | Error::Overflow { .. }
            | Error::FoldNotFound { .. }
            | Error::NonFinite { .. }
            | Error::SingularJacobian { .. }
            | Error::NewtonDiverged { .. }
            | Error::NewtonNotConverged { .. }
    )
}

/// The models' constructors with hostile counts and `pull_to` with hostile
/// targets.
fn models(g: &mut Gen, r: &mut Report, spring: &Spring) {
    let samples = g.count(SAMPLES as u64) as usize;
    let which = g.u64() % 8;
    let rest = if spring.is_helical() {
        spring.helix_angle().cos()
    } else {
        f64::NAN
    };
    let t = target(g, rest);
    let valid_target = target_ok(t, rest);
    let model: Box<dyn Model> = match which {
        0..=3 => {
            let what = || format!("HelixModel::new({samples})");
            let Some(res) = r.call(what, || HelixModel::new(samples)) else {
                return;
            };
            let ok = (2..=MAX_SAMPLES).contains(&samples);
            r.check(ok == res.is_ok(), || format!("{}: {res:?}", what()));
            if !ok {
                return;
            }
            Box::new(HelixModel::new(samples.min(SAMPLES)).expect("valid"))
        }
        4..=6 => {
            let what = || format!("ElasticaModel::new({samples})");
            let Some(res) = r.call(what, || ElasticaModel::new(samples)) else {
                return;
            };
            let ok = (2..=MAX_SAMPLES).contains(&samples);
            r.check(ok == res.is_ok(), || format!("{}: {res:?}", what()));
            if !ok {
                return;
            }
            // the elastica's cost grows with the coils (secondary folds)
            if spring.coils() > 50 && !g.u64().is_multiple_of(4) {
                return;
            }
            let m = ElasticaModel::new(samples.min(SAMPLES)).expect("valid");
            if g.u64().is_multiple_of(4) {
                scaffold(r, &m, spring, t.value());
            }
            Box::new(m)
        }
        _ => {
            rod_pull(g, r, spring, t, valid_target);
            return;
        }
    };
    let what = || format!("{} model: pull_to({spring}, {t})", model.name());
    let Some(res) = r.call(what, || model.pull_to(spring, t)) else {
        return;
    };
    match res {
        Ok(resp) => {
            r.check(valid_target, || format!("{} accepted", what()));
            // (the last model miss, the elastica's subnormal forces, is
            // refused now: found_extremes::elastica_model_with_subnormal_forces_is_refused)
            check_response(r, &resp, true, &what);
            response_entries(g, r, &resp);
        }
        Err(e) => r.check(
            match e {
                // an extension beyond the υ-branch's reach at m₁ = e^−690
                Error::UnreachableTarget {
                    target: Target::Extension(_),
                    ..
                } if model.name() == "elastica" => true,
                // (helix) a force whose physical value f·(2πn)²B overflows
                Error::UnreachableTarget { .. } => {
                    !valid_target || !force_in_range(t, spring.force_scale())
                }
                // the elastica trace refuses a subnormal force limit
                // (elastica docs: not met to 1e-9 in double precision),
                // named as the user's target
                Error::InvalidArgument {
                    name: "target",
                    value,
                    ..
                } => model.name() == "elastica" && value.abs() < f64::MIN_POSITIVE,
                ref e => model_refusal(e) || !valid_target,
            },
            || format!("{}: {e}", what()),
        ),
    }
}

/// `ElasticaModel::scaffold` at a hostile force: Ok only for a finite,
/// positive one, every branch finite.
fn scaffold(r: &mut Report, m: &ElasticaModel, spring: &Spring, force: f64) {
    let what = || format!("{m:?}: scaffold({spring}, {force:e})");
    let Some(res) = r.call(what, || m.scaffold(spring, force)) else {
        return;
    };
    let coils_ok = spring.coils() <= ElasticaModel::MAX_SCAFFOLD_COILS;
    let ok = force.is_finite() && force > 0.0;
    match res {
        Ok(branches) => r.check(
            ok && coils_ok
                && branches.iter().all(|b| {
                    b.points()
                        .iter()
                        .all(|p| finite(&[p.extension, p.force, p.parameter]))
                }),
            || format!("{}: bad Ok", what()),
        ),
        Err(e) => r.check(
            !ok || model_refusal(&e)
                || (force.abs() < f64::MIN_POSITIVE
                    && matches!(
                        e,
                        Error::InvalidArgument {
                            name: "max_force_scaled",
                            ..
                        }
                    ))
                // a secondary branch needs 3 points (both ends and the
                // fold); `ElasticaModel::new(2)` is valid for pulls
                || (spring.coils() > 1
                    && matches!(e, Error::InvalidCount { name: "samples", value: 2, .. }))
                || (!coils_ok && matches!(e, Error::InvalidCount { name: "coils", .. })),
            || format!("{}: {e}", what()),
        ),
    }
}

/// Every value of a response is finite, its loop counts fit its curve,
/// and a pull that stopped early says why.
/// With `exact` the pull must have reached its target, and its last point
/// must be on it.
pub fn check_response(r: &mut Report, resp: &Response, exact: bool, what: &dyn Fn() -> String) {
    let c = resp.curve();
    r.check(
        c.points()
            .iter()
            .all(|p| finite(&[p.extension, p.force, p.parameter])),
        || format!("{}: non-finite curve point", what()),
    );
    r.check(resp.loops().len() == c.len(), || {
        format!("{}: loop counts do not fit the curve", what())
    });
    r.check(!exact || resp.reached_target(), || {
        format!(
            "{}: did not reach {}: {}",
            what(),
            resp.target(),
            resp.termination()
        )
    });
    if exact {
        let end = c.points().last();
        let at = match resp.target() {
            Target::Force(f) => end.is_some_and(|p| {
                let got = p.force_scaled(c.scale());
                (got - f).abs() <= 1e-8 * f.abs().max(1.0)
            }),
            Target::Extension(dz) => end.is_some_and(|p| (p.extension - dz).abs() <= 1e-8),
        };
        r.check(at, || {
            let scaled = end.map(|p| p.force_scaled(c.scale()));
            format!(
                "{}: reached, but the last point {end:?} (F/((2πn)²B) = {scaled:?}) is not {}",
                what(),
                resp.target()
            )
        });
    }
}

/// `RodModel::pull_observed` on a tiny mesh, stopped by the observer after
/// `ROD_POINTS` points (the model has no step limit of its own).
fn rod_pull(g: &mut Gen, r: &mut Report, spring: &Spring, t: Target, valid_target: bool) {
    let k = spring.stiffness();
    let valid_target = valid_target
        && force_in_range(t, spring.force_scale())
        && norm_ok(spring.force_scale())
        && [k.a(), k.b(), k.c()].iter().all(|v| (1.0 / v).is_finite());
    if !g.u64().is_multiple_of(6) {
        // the driver only: validation without solving
        let what = || format!("RodModel: driver({spring}, {t})");
        if let Some(res) = r.call(what, || RodModel::default().intervals(8).driver(spring, t)) {
            let ok = valid_target && spring.helix_angle() != FRAC_PI_2;
            r.check(ok == res.is_ok(), || format!("{}: {res:?}", what()));
        }
        return;
    }
    let model = RodModel::default()
        .intervals(4 + (g.u64() % 5) as usize)
        .points(2 + (g.u64() % 3) as usize);
    let seen = Cell::new(0);
    let observer = |_p: &Point| {
        seen.set(seen.get() + 1);
        if seen.get() >= ROD_POINTS {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    let what = || format!("{model:?}: pull_observed({spring}, {t})");
    let Some(res) = r.call(what, || model.pull_observed(spring, t, observer)) else {
        return;
    };
    match res {
        Ok(resp) => {
            r.check(valid_target && spring.helix_angle() != FRAC_PI_2, || {
                format!("{} accepted", what())
            });
            check_response(r, &resp, false, &what);
            let ok = match resp.termination() {
                Termination::Stopped => seen.get() >= ROD_POINTS,
                Termination::ParameterValue(_) => true,
                Termination::Failed { error, .. } => {
                    model_refusal(error)
                        || matches!(
                            error,
                            Error::StepAngleTooLarge { .. }
                                | Error::NotARod { .. }
                                | Error::CorrectorDrifted { .. }
                        )
                }
                _ => false,
            };
            r.check(ok && !resp.curve().is_empty(), || {
                format!(
                    "{}: {:?} with {} points",
                    what(),
                    resp.termination(),
                    resp.curve().len()
                )
            });
            response_entries(g, r, &resp);
        }
        Err(e) => r.check(
            !valid_target || model_refusal(&e) || spring.helix_angle() == FRAC_PI_2,
            || format!("{}: {e}", what()),
        ),
    }
}
