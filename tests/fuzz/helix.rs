//! `helix`: the stiffness, the helix and its closed forms.

use core::f64::consts::{FRAC_PI_2, PI};

use hockle::Error;
use hockle::Stiffness;
use hockle::error::MAX_POINTS;
use hockle::helix::Helix;

use crate::hostile::{Gen, Report, finite};

/// Well under a second in release.
pub const CI_CALLS: u64 = 500_000;

fn positive(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
        let (a, b, c) = (g.arg(0.0, 1e3), g.arg(0.0, 1e3), g.arg(0.0, 1e3));
        let nu = g.arg(-1.0, 0.5);
        let stiffness = if g.u64() & 1 == 0 {
            let res = r.call(
                || format!("Stiffness::new({a:e}, {b:e}, {c:e})"),
                || Stiffness::new(a, b, c),
            );
            let Some(res) = res else { continue };
            let valid = positive(a) && positive(b) && positive(c);
            r.check(valid == res.is_ok(), || {
                format!("Stiffness::new({a:e}, {b:e}, {c:e}) = {res:?}")
            });
            res
        } else {
            let res = r.call(
                || format!("Stiffness::nikolai({a:e}, {nu:e})"),
                || Stiffness::nikolai(a, nu),
            );
            let Some(res) = res else { continue };
            let valid = positive(a) && nu > -1.0 && nu <= 0.5;
            r.check(valid == res.is_ok(), || {
                format!("Stiffness::nikolai({a:e}, {nu:e}) = {res:?}")
            });
            res
        };
        let Ok(s) = stiffness else { continue };
        let n = g.u32(8);
        let th0 = g.arg(0.0, FRAC_PI_2);
        let Some(h) = r.call(
            || format!("Helix::new({n}, {th0:e}, {s})"),
            || Helix::new(n, th0, s),
        ) else {
            continue;
        };
        let valid = n >= 1 && th0 > 0.0 && th0 <= FRAC_PI_2;
        let h = match h {
            Ok(h) => {
                r.check(valid, || format!("Helix::new({n}, {th0:e}, {s}) accepted"));
                h
            }
            Err(e) => {
                r.check(!valid, || format!("Helix::new({n}, {th0:e}, {s}): {e}"));
                continue;
            }
        };
        for _ in 0..4 {
            angle_entries(g, r, &h);
        }
        if let Some(res) = r.call(|| format!("{h}: spring_constant"), || h.spring_constant()) {
            r.check(
                match &res {
                    Ok(v) => v.is_finite() && *v > 0.0,
                    Err(e) => matches!(e, Error::Overflow { .. }),
                },
                || format!("{h}: spring_constant = {res:?}"),
            );
        }
        if g.u64().is_multiple_of(8) {
            let samples = g.count(20) as usize;
            let samples = if samples > 100 && samples <= MAX_POINTS {
                100
            } else {
                samples
            };
            let zmax = g.arg(th0.cos(), 1.0);
            let what = || format!("{h}: curve_to({samples}, {zmax:e})");
            let Some(res) = r.call(what, || h.curve_to(samples, zmax)) else {
                continue;
            };
            let valid = (2..=MAX_POINTS).contains(&samples) && zmax > th0.cos() && zmax < 1.0;
            match res {
                Ok(c) => r.check(
                    valid
                        && c.len() == samples
                        && c.points()
                            .iter()
                            .all(|p| finite(&[p.force, p.extension, p.parameter])),
                    || format!("{}: bad Ok", what()),
                ),
                Err(e) => r.check(!valid || matches!(e, Error::Overflow { .. }), || {
                    format!("{}: {e}", what())
                }),
            }
        }
    }
}

type AngleEntry = fn(&Helix, f64) -> hockle::Result<f64>;

/// The closed forms at one hostile angle: Ok and finite inside (0, π)
/// unless the value overflows, `InvalidArgument` outside.
fn angle_entries(g: &mut Gen, r: &mut Report, h: &Helix) {
    let theta = g.arg(0.0, PI);
    let inside = theta > 0.0 && theta < PI;
    let entries: [(&str, AngleEntry); 6] = [
        ("force", Helix::force),
        ("force_scaled", Helix::force_scaled),
        ("extension", Helix::extension),
        ("radius", Helix::radius),
        ("twist_rate", Helix::twist_rate),
        ("energy", Helix::energy),
    ];
    for (name, f) in entries {
        let what = || format!("{h}: {name}(θ = {theta:e})");
        let Some(res) = r.call(what, || f(h, theta)) else {
            continue;
        };
        match res {
            Ok(v) => r.check(inside && v.is_finite(), || format!("{} = {v}", what())),
            Err(e) => r.check(
                if inside {
                    matches!(e, Error::Overflow { .. })
                } else {
                    matches!(e, Error::InvalidArgument { name: "theta", .. })
                },
                || format!("{}: {e}", what()),
            ),
        }
    }
}
