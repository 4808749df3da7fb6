//! `elastica`: every constructor, accessor with an argument, the trace and
//! the series.

use hockle::Error;
use hockle::elastica::{Arm, Branch, Elastica, Trace, bifurcation, secondary_fold, series};
use hockle::error::MAX_POINTS;

use crate::hostile::{Gen, Report, finite};
use crate::special::modulus;

/// Solutions take about a microsecond, folds 25 µs, traces a millisecond:
/// about 4 s in release.
pub const CI_CALLS: u64 = 300_000;

/// Every number a solution reports is finite and the extension is in
/// [−1, 1].
fn check_solution(r: &mut Report, e: &Elastica, what: &dyn Fn() -> String) {
    let v = [
        e.omega(),
        e.omega_excess(),
        e.force(),
        e.force_scaled(),
        e.extension(),
        e.energy(),
        e.start(),
        e.quarter_period(),
        e.end_curvatures()[0],
        e.end_curvatures()[1],
    ];
    r.check(finite(&v) && e.extension().abs() <= 1.0, || {
        format!("{}: non-finite or |Δz| > 1 in {v:?}", what())
    });
}

fn valid_k(k: f64) -> bool {
    (0.0..1.0).contains(&k)
}

/// The errors a documented-valid (n, j, k) may still give on a secondary
/// branch: below the fold, n/j too large for a double, fold lost to
/// rounding.
fn secondary_refusal(e: &Error) -> bool {
    matches!(
        e,
        Error::BelowFold { .. }
            | Error::FoldNotFound { .. }
            | Error::InvalidCount { name: "n", .. }
    )
}

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    let mut round = 0_u64;
    while r.calls < calls {
        round += 1;
        let n = g.u32(8);
        let j = g.u32(10);
        let k = g.arg(0.0, 1.0);
        let what = |f: &str| format!("{f}(n = {n}, j = {j}, k = {k:e})");

        if let Some(res) = r.call(|| what("symmetric"), || Elastica::symmetric(n, k)) {
            let valid = n >= 1 && valid_k(k);
            match res {
                Ok(s) => {
                    r.check(valid, || format!("{} accepted", what("symmetric")));
                    for e in [s.upsilon, s.alpha] {
                        check_solution(r, &e, &|| what("symmetric"));
                        let s_at = g.any_f64();
                        if let Some(c) = r.call(|| what("curvature"), || e.curvature(s_at)) {
                            // documented NaN where Ωs overflows (Ω < 1.4e10)
                            r.check(
                                c.is_finite() || s_at.is_nan() || s_at.abs() >= 1e290,
                                || format!("{} at s = {s_at:e}: {c}", what("curvature")),
                            );
                        }
                        let samples = g.count(40) as usize;
                        let samples = if samples > 200 && samples <= MAX_POINTS {
                            200
                        } else {
                            samples
                        };
                        if let Some(c) = r.call(|| what("centreline"), || e.centreline(samples)) {
                            match c {
                                Ok(p) => r.check(
                                    (2..=MAX_POINTS).contains(&samples)
                                        && p.len() == samples
                                        && p.iter().all(|q| q.x.is_finite() && q.y.is_finite()),
                                    || {
                                        format!(
                                            "{} samples = {samples}: bad Ok",
                                            what("centreline")
                                        )
                                    },
                                ),
                                Err(err) => r.check(!(2..=MAX_POINTS).contains(&samples), || {
                                    format!("{} samples = {samples}: {err}", what("centreline"))
                                }),
                            }
                        }
                    }
                }
                Err(e) => r.check(!valid, || format!("{}: {e}", what("symmetric"))),
            }
        }

        if let Some(md) = modulus(g, r) {
            let valid = n >= 1 && md.complement() > 0.0;
            let which = g.u64() % 3;
            if let Some(res) = r.call(
                || what("symmetric_with/upsilon/alpha"),
                || match which {
                    0 => Elastica::symmetric_with(n, md).map(|s| s.alpha),
                    1 => Elastica::upsilon(n, md),
                    _ => Elastica::alpha(n, md),
                },
            ) {
                match res {
                    Ok(e) => {
                        r.check(valid, || {
                            format!(
                                "{} #{which} accepted m1 = {:e}",
                                what("with"),
                                md.complement()
                            )
                        });
                        check_solution(r, &e, &|| {
                            format!("{} #{which} m1 = {:e}", what("with"), md.complement())
                        });
                    }
                    Err(e) => r.check(!valid, || format!("{} #{which}: {e}", what("with"))),
                }
            }
            let arm = if g.u64() & 1 == 0 {
                Arm::Lower
            } else {
                Arm::Upper
            };
            if let Some(res) = r.call(
                || what("secondary_arm"),
                || Elastica::secondary_arm(n, j, arm, md),
            ) {
                let valid = n >= 1 && j >= 1 && j != n && md.complement() > 0.0;
                match res {
                    Ok(e) => {
                        r.check(valid, || format!("{} accepted", what("secondary_arm")));
                        check_solution(r, &e, &|| what("secondary_arm"));
                    }
                    Err(e) => r.check(!valid || secondary_refusal(&e), || {
                        format!("{} m1 = {:e}: {e}", what("secondary_arm"), md.complement())
                    }),
                }
            }
        }

        if let Some(res) = r.call(|| what("nonsymmetric"), || Elastica::nonsymmetric(n, j, k)) {
            let valid = n >= 1 && j >= 1 && valid_k(k);
            match res {
                Ok(v) => {
                    r.check(valid && v.len() <= 2, || {
                        format!("{} accepted", what("nonsymmetric"))
                    });
                    for e in &v {
                        check_solution(r, e, &|| what("nonsymmetric"));
                    }
                }
                Err(e) => r.check(!valid, || format!("{}: {e}", what("nonsymmetric"))),
            }
        }

        if let Some(res) = r.call(|| what("secondary"), || Elastica::secondary(n, j, k)) {
            let valid = n >= 1 && j >= 1 && j != n && valid_k(k);
            match res {
                Ok(e) => {
                    r.check(valid, || format!("{} accepted", what("secondary")));
                    check_solution(r, &e, &|| what("secondary"));
                }
                Err(e) => r.check(!valid || secondary_refusal(&e), || {
                    format!("{}: {e}", what("secondary"))
                }),
            }
        }

        if round.is_multiple_of(4) {
            if let Some(res) = r.call(|| what("bifurcation"), || bifurcation(n, j)) {
                let valid = n >= 1 && j >= 1 && j != n;
                match res {
                    Ok(b) => {
                        r.check(valid, || format!("{} accepted", what("bifurcation")));
                        check_solution(r, &b.solution(), &|| what("bifurcation"));
                        let v = [b.modulus(), b.force(), b.force_scaled(), b.extension()];
                        r.check(finite(&v), || format!("{}: {v:?}", what("bifurcation")));
                    }
                    Err(e) => r.check(!valid || secondary_refusal(&e), || {
                        format!("{}: {e}", what("bifurcation"))
                    }),
                }
            }
            if let Some(res) = r.call(|| what("secondary_fold"), || secondary_fold(n, j)) {
                let valid = n >= 1 && j >= 1 && j != n;
                match res {
                    Ok(f) => {
                        r.check(valid, || format!("{} accepted", what("secondary_fold")));
                        check_solution(r, &f.solution(), &|| what("secondary_fold"));
                    }
                    Err(e) => r.check(!valid || secondary_refusal(&e), || {
                        format!("{}: {e}", what("secondary_fold"))
                    }),
                }
            }
        }

        for (name, f) in [
            (
                "upsilon_omega",
                series::upsilon_omega as fn(u32, f64) -> f64,
            ),
            ("upsilon_omega_excess", series::upsilon_omega_excess),
            ("upsilon_force", series::upsilon_force),
            ("upsilon_extension", series::upsilon_extension),
            ("alpha_omega", series::alpha_omega),
            ("alpha_omega_excess", series::alpha_omega_excess),
            ("alpha_force", series::alpha_force),
            ("alpha_extension", series::alpha_extension),
            ("theta_force", series::theta_force),
        ] {
            if let Some(v) = r.call(|| what(name), || f(n, k)) {
                r.check(!(n >= 1 && valid_k(k)) || v.is_finite(), || {
                    format!("{} = {v}", what(name))
                });
            }
        }
        if let Some(v) = r.call(|| what("theta_extension"), || series::theta_extension(k)) {
            r.check(!valid_k(k) || v.is_finite(), || {
                format!("{} = {v}", what("theta_extension"))
            });
        }
        if let Some(v) = r.call(
            || what("stiffnesses"),
            || {
                [
                    series::symmetric_stiffness(n),
                    series::nonsymmetric_stiffness(n),
                ]
            },
        ) {
            r.check(n == 0 || finite(&v), || {
                format!("{} = {v:?}", what("stiffnesses"))
            });
        }

        if round.is_multiple_of(40) {
            trace(g, r);
        }
    }
}

/// A trace with hostile options: valid options reach the limit exactly or
/// give a typed refusal; invalid ones never give a curve.
fn trace(g: &mut Gen, r: &mut Report) {
    let n = g.u32(6);
    let j = g.u32(8);
    let points = g.count(30) as usize;
    // valid counts are kept small so a trace costs milliseconds
    let points = if points > 64 && points <= MAX_POINTS {
        64
    } else {
        points
    };
    let limit = g.arg(0.0, 20.0);
    let scale = if g.u64() & 1 == 0 {
        Some(g.u32(8))
    } else {
        None
    };
    let branch = match g.u64() % 5 {
        0 => Branch::Upsilon,
        1 => Branch::Alpha,
        2 => Branch::Theta { j },
        3 => Branch::Secondary { j, arm: Arm::Lower },
        _ => Branch::Secondary { j, arm: Arm::Upper },
    };
    let mut t = Trace::new().points(points).max_force_scaled(limit);
    if let Some(sc) = scale {
        t = t.scale_coils(sc);
    }
    let what = || {
        format!(
            "Trace(points = {points}, limit = {limit:e}, scale = {scale:?}).run({n}, {branch:?}) (or .secondary)"
        )
    };
    // the whole secondary branch j half the time
    let whole = matches!(branch, Branch::Secondary { .. }) && g.u64() & 1 == 0;
    let Some(res) = r.call(what, || {
        if whole {
            t.secondary(n, j)
        } else {
            t.run(n, branch)
        }
    }) else {
        return;
    };
    let min_points = if whole { 3 } else { 2 };
    let valid = n >= 1
        && (min_points..=MAX_POINTS).contains(&points)
        && limit.is_finite()
        && limit > 0.0
        && scale != Some(0);
    match res {
        Ok(c) => {
            let p = c.points();
            let last = c
                .force_scaled(p.len().saturating_sub(1))
                .unwrap_or(f64::NAN);
            r.check(
                valid
                    && p.len() == points
                    && p.iter()
                        .all(|q| finite(&[q.force, q.extension, q.parameter]))
                    && (last / limit - 1.0).abs() < 1e-6,
                || {
                    format!(
                        "{}: bad Ok (len {}, last F/(2πn)² = {last:e})",
                        what(),
                        p.len()
                    )
                },
            );
        }
        Err(e) => r.check(
            !valid
                || secondary_refusal(&e)
                || matches!(
                    e,
                    Error::ForceOutOfReach { .. }
                        | Error::SecondaryNeedsOtherPeriods { .. }
                        | Error::InvalidCount { name: "j", .. }
                        | Error::InvalidArgument {
                            name: "max_force_scaled",
                            ..
                        }
                ),
            || format!("{}: {e}", what()),
        ),
    }
}
