//! `curve` and `spring::Response`: `ForceScale::new`, `ForceExtension` with
//! hostile points, `Response::with_folds`/`with_loops` with bad indices and
//! lengths, and every reading of a response (pop-outs, stretches, jumps,
//! branch matches) on curves of hostile values.

use hockle::continuation::Termination;
use hockle::curve::{Curvature, Slope};
use hockle::spring::Response;
use hockle::{Control, Error, Fold, FoldKind, ForceExtension, ForcePoint, ForceScale, Target};

use crate::hostile::{Gen, Report, finite};
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
        let (curve, exact) = hostile_curve(g, scale);
        dense_entries(g, r, &curve, exact);
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
/// values (NaN, ∞, repeated points); with no derivatives, slopes, or
/// slopes and curvatures (the dense output's data: exact on the s-curve,
/// hostile elsewhere). Also whether every point is on the s-curve with its
/// exact derivatives (then the dense output is exact: [`dense_entries`]).
fn hostile_curve(g: &mut Gen, scale: ForceScale) -> (ForceExtension, bool) {
    let mut c = ForceExtension::new("fuzz", "t", scale);
    let len = (g.u64() % 41) as usize;
    let smooth = g.u64() & 1 == 0;
    let derivatives = g.u64() % 3;
    let f = scale.value();
    // (with forces of a normal magnitude: near the ends of the double range
    // the data themselves are rounded to a few bits, or their Hermite
    // coefficients overflow)
    let mut exact = smooth && derivatives > 0 && (1e-280..1e280).contains(&f);
    for i in 0..len {
        let t = -3.0 + 6.0 * i as f64 / len.max(2) as f64;
        let on_curve = smooth && !g.u64().is_multiple_of(16);
        exact &= on_curve;
        let p = if on_curve {
            ForcePoint {
                extension: t / 3.0,
                force: (t * t * t - 3.0 * t) * f,
                parameter: t,
            }
        } else {
            ForcePoint {
                extension: g.arg(-1.0, 1.0),
                force: g.any_f64(),
                parameter: g.any_f64(),
            }
        };
        let (slope, curvature) = if on_curve {
            (
                Slope {
                    extension: 1.0 / 3.0,
                    force: (3.0 * t * t - 3.0) * f,
                },
                Curvature {
                    extension: 0.0,
                    force: 6.0 * t * f,
                },
            )
        } else {
            (
                Slope {
                    extension: g.any_f64(),
                    force: g.any_f64(),
                },
                Curvature {
                    extension: g.any_f64(),
                    force: g.any_f64(),
                },
            )
        };
        match derivatives {
            0 => c.push(p),
            1 => c.push_with_slope(p, slope),
            _ => c.push_with_curvature(p, slope, curvature),
        }
    }
    (c, exact)
}

/// `force_at`, `extension_at` and `at` (the dense output, issue 11) at
/// hostile values, at the nodes and one ulp from them: none may panic; on
/// a curve of finite points, slopes and curvatures every value read is
/// finite; on the s-curve x = t/3, F = (t³ − 3t)·(2πn)²B with its exact
/// derivatives (cubic: the Hermite interpolants are exact) every reading
/// is the curve's, with every crossing once (audit15: a node's neighbours
/// were read by neither segment or by both).
pub fn dense_entries(g: &mut Gen, r: &mut Report, curve: &ForceExtension, exact: bool) {
    let pts = curve.points();
    let len = pts.len();
    let finite_data = (0..len).all(|i| {
        let p = pts[i];
        finite(&[p.extension, p.force, p.parameter])
            && curve
                .slope(i)
                .is_none_or(|s| finite(&[s.extension, s.force]))
            && curve
                .curvature(i)
                .is_none_or(|c| finite(&[c.extension, c.force]))
    });
    let scale = curve.scale().value();
    for _ in 0..4 {
        let node = (len > 0).then(|| pts[(g.u64() % len as u64) as usize]);
        let (x, f) = match (g.u64() % 4, node) {
            (0, Some(p)) => (p.extension, p.force),
            (1, Some(p)) => (p.extension.next_up(), p.force.next_down()),
            (2, Some(p)) => (p.extension.next_down(), p.force.next_up()),
            _ => (g.arg(-1.0, 1.0), g.any_f64()),
        };
        let what = || format!("{curve}: force_at({x:e}), extension_at({f:e})");
        let Some((forces, extensions)) =
            r.call(what, || (curve.force_at(x), curve.extension_at(f)))
        else {
            continue;
        };
        // a quintic crosses a value at most five times
        let most = 5 * len.saturating_sub(1) + 1;
        r.check(forces.len() <= most && extensions.len() <= most, || {
            format!(
                "{}: {} and {} values",
                what(),
                forces.len(),
                extensions.len()
            )
        });
        // (a value may be ±∞ where a hostile slope makes the interpolant
        // overshoot the double range; never NaN)
        if finite_data {
            r.check(
                !forces.iter().chain(&extensions).any(|v| v.is_nan()),
                || format!("{}: {forces:?} {extensions:?}", what()),
            );
        }
        if !(exact && len >= 2) {
            continue;
        }
        let (t0, t1) = (pts[0].parameter, pts[len - 1].parameter);
        // the extension t/3 crosses x once inside [t0, t1]: F there to the
        // rounding of the interpolant's sums (≤ 1e-12 of the force scale
        // times the cube of |t| ≤ 3, with a margin)
        let t = 3.0 * x;
        if t > t0 + 1e-12 && t < t1 - 1e-12 {
            let want = (t * t * t - 3.0 * t) * scale;
            r.check(
                forces.len() == 1 && (forces[0] - want).abs() <= 1e-10 * scale,
                || format!("{}: {forces:?}, want [{want:e}]", what()),
            );
        }
        // F/scale = c: the real roots of t³ − 3t − c inside [t0, t1] (away
        // from the ends and from the double roots at c = ±2, where a count
        // is ill-conditioned)
        let c = f / scale;
        if c.is_finite() && (c.abs() - 2.0).abs() > 1e-6 {
            let roots = cubic_roots(c);
            if roots
                .iter()
                .all(|t| (t - t0).abs() > 1e-6 && (t - t1).abs() > 1e-6)
            {
                let inside: Vec<f64> = roots
                    .into_iter()
                    .filter(|t| *t > t0 && *t < t1)
                    .map(|t| t / 3.0)
                    .collect();
                // Δz = t/3 to the bisection's last bit on a slope ≥ 1e-6·3
                // per unit t: 1e-9 is far above it
                r.check(
                    extensions.len() == inside.len()
                        && extensions
                            .iter()
                            .zip(&inside)
                            .all(|(a, b)| (a - b).abs() < 1e-9),
                    || format!("{}: {extensions:?}, want {inside:?}", what()),
                );
            }
        }
    }
}

/// The real roots of t³ − 3t = c in increasing order (trigonometric form
/// for |c| < 2, Cardano's otherwise).
fn cubic_roots(c: f64) -> Vec<f64> {
    if c.abs() < 2.0 {
        let phi = (c / 2.0).acos();
        let mut r: Vec<f64> = (0..3)
            .map(|k| 2.0 * ((phi - 2.0 * core::f64::consts::PI * f64::from(k)) / 3.0).cos())
            .collect();
        r.sort_by(f64::total_cmp);
        r
    } else {
        // t = u + 1/u with u³ = (c + √(c² − 4))/2
        let d = (c * c - 4.0).sqrt();
        let u = (0.5 * (c + c.signum() * d)).cbrt();
        vec![u + 1.0 / u]
    }
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
