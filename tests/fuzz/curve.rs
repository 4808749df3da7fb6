//! `curve` and `spring::Response`: `ForceScale::new`, `ForceExtension` with
//! hostile points, `Response::with_folds`/`with_loops` with bad indices and
//! lengths, and every reading of a response (pop-outs, stretches, jumps,
//! branch matches) on curves of hostile values.

use hockle::continuation::Termination;
use hockle::spring::Response;
use hockle::{Control, Error, Fold, FoldKind, ForceExtension, ForcePoint, ForceScale, Target};

use crate::hostile::{Gen, Report};
use crate::rod::scale_ok;

/// Curves of at most 40 points: about a second in release.
pub const CI_CALLS: u64 = 200_000;

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
        let n = g.u32(8);
        let b = g.arg(0.0, 1e3);
        let what = || format!("ForceScale::new({n}, {b:e})");
        let Some(res) = r.call(what, || ForceScale::new(n, b)) else {
            continue;
        };
        let valid = scale_ok(n, b);
        let scale = match res {
            Ok(s) => {
                r.check(valid && s.value().is_finite() && s.value() > 0.0, || {
                    format!("{} = {s:?}", what())
                });
                s
            }
            Err(e) => {
                r.check(!valid, || format!("{}: {e}", what()));
                continue;
            }
        };
        let curve = hostile_curve(g, scale);
        let what = || format!("{curve}: force_scaled, folds, write_csv");
        let len = curve.len();
        let i = g.count(len as u64 + 1) as usize;
        if let Some((fs, folds, csv)) = r.call(what, || {
            let mut out = Vec::new();
            let csv = curve.write_csv(&mut out).is_ok();
            (curve.force_scaled(i), curve.folds(), csv)
        }) {
            r.check(fs.is_some() == (i < len) && csv, || {
                format!("{}: force_scaled({i}) = {fs:?}", what())
            });
            r.check(folds.iter().all(|f| f.index < len), || {
                format!("{}: fold index past the curve", what())
            });
        }
        let target = if g.u64() & 1 == 0 {
            Target::Force(g.any_f64())
        } else {
            Target::Extension(g.any_f64())
        };
        let termination = match g.u64() % 3 {
            0 => Termination::ParameterValue(1.0),
            1 => Termination::MaxSteps(3),
            _ => Termination::Stopped,
        };
        let resp = Response::new("fuzz", target, curve, termination);
        response_entries(g, r, &resp);
    }
}

/// A curve of up to 40 points: a smooth s-curve with folds, or hostile
/// values (NaN, ∞, repeated points).
fn hostile_curve(g: &mut Gen, scale: ForceScale) -> ForceExtension {
    let mut c = ForceExtension::new("fuzz", "t", scale);
    let len = (g.u64() % 41) as usize;
    let smooth = g.u64() & 1 == 0;
    for i in 0..len {
        let t = -3.0 + 6.0 * i as f64 / len.max(2) as f64;
        let p = if smooth && !g.u64().is_multiple_of(16) {
            ForcePoint {
                extension: t / 3.0,
                force: (t * t * t - 3.0 * t) * scale.value(),
                parameter: t,
            }
        } else {
            ForcePoint {
                extension: g.arg(-1.0, 1.0),
                force: g.any_f64(),
                parameter: g.any_f64(),
            }
        };
        c.push(p);
    }
    c
}

/// `with_folds`/`with_loops` with hostile folds and counts (Ok exactly when
/// every index is on the curve and there is one count per point), then
/// every reading of the result: none may panic.
pub fn response_entries(g: &mut Gen, r: &mut Report, resp: &Response) {
    let len = resp.curve().len();
    let folds: Vec<Fold> = (0..g.u64() % 4)
        .map(|_| Fold {
            kind: g.pick(&[
                FoldKind::MaxForce,
                FoldKind::MinForce,
                FoldKind::MaxExtension,
                FoldKind::MinExtension,
            ]),
            index: g.count(len as u64 + 1) as usize,
            point: ForcePoint {
                extension: g.arg(-1.0, 1.0),
                force: g.any_f64(),
                parameter: g.any_f64(),
            },
        })
        .collect();
    let folds_ok = folds.iter().all(|f| f.index < len);
    let what = || format!("{resp}: with_folds({folds:?})");
    let Some(res) = r.call(what, || resp.clone().with_folds(folds.clone())) else {
        return;
    };
    let resp = match res {
        Ok(x) => {
            r.check(folds_ok, || format!("{} accepted", what()));
            x
        }
        Err(e) => {
            r.check(!folds_ok && matches!(e, Error::InvalidCount { .. }), || {
                format!("{}: {e}", what())
            });
            resp.clone()
        }
    };
    let count = if g.u64() & 1 == 0 {
        len
    } else {
        g.count(len as u64 + 2) as usize % (len + 3)
    };
    let loops: Vec<Option<u32>> = (0..count)
        .map(|_| (g.u64() & 1 == 0).then(|| g.u32(4)))
        .collect();
    let what = || format!("{resp}: with_loops(len {count})");
    let Some(res) = r.call(what, || resp.clone().with_loops(loops)) else {
        return;
    };
    let resp = match res {
        Ok(x) => {
            r.check(count == len, || format!("{} accepted", what()));
            x
        }
        Err(e) => {
            r.check(
                count != len && matches!(e, Error::LengthMismatch { .. }),
                || format!("{}: {e}", what()),
            );
            resp
        }
    };
    let branches = vec![
        resp.curve().clone(),
        ForceExtension::new("empty", "k", resp.curve().scale()),
    ];
    let what = || format!("{resp}: pop_outs, stretches, loops_lost, jumps, match_branches");
    if let Some((pops, stretches)) = r.call(what, || {
        let pops = resp.pop_outs();
        let stretches = resp.stretches();
        let _ = resp.loops_lost();
        let _ = resp.jumps(Control::Force);
        let _ = resp.jumps(Control::Extension);
        let _ = resp.match_branches(&branches);
        let _ = resp.to_string();
        (pops, stretches)
    }) {
        r.check(
            pops.iter().all(|p| p.max.index < len && p.min.index < len)
                && stretches.iter().all(|s| s.range.end <= len),
            || format!("{}: index past the curve", what()),
        );
    }
}
