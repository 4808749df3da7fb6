//! `rod::PhaseDiagram` (issue 13): `from_csv` of hostile files (rows of
//! the committed n = 4 and n = 8 diagrams cut, shuffled and mutated:
//! hostile numbers, junk fields, missing or extra commas, other headers,
//! huge pop-out indices), then every reading at hostile scenes (audit15).
//!
//! Oracles: no panic; a diagram read is written back by `to_csv` to the
//! same diagram; `pop_outs` is `InvalidArgument` exactly outside θ0 ∈ (0,
//! π/2), A/B > 0 finite, ν ∈ (−1, ½), otherwise a count of at most the
//! mapped pop-outs or `NotMapped` over a range inside [0, 90°];
//! `cusp_theta0` likewise, a range inside [0, π/2].

use core::f64::consts::FRAC_PI_2;

use hockle::Error;
use hockle::rod::PhaseDiagram;

use crate::hostile::{Gen, Report};

/// A file is a few dozen rows, a reading a few lines: about a second in
/// release.
pub const CI_CALLS: u64 = 100_000;

const N4: &str = include_str!("../../docs/data/phase_diagram_n4.csv");
const N8: &str = include_str!("../../docs/data/phase_diagram_n8.csv");

/// A field replaced by something hostile.
fn hostile_field(g: &mut Gen) -> String {
    match g.u64() % 6 {
        0 => format!("{:e}", g.any_f64()),
        1 => format!("{}", g.any_f64()),
        2 => g.count(8).to_string(),
        3 => g
            .pick(&[
                "",
                " ",
                "nan",
                "-inf",
                "1e999",
                "tip",
                "nu",
                "a_over_b",
                "x/y",
                "tip/",
                "/range",
                "range/tip/tip",
                "0x10",
                "1_0",
            ])
            .to_owned(),
        4 => g
            .pick(&[
                "tip/tip",
                "range/range",
                "unfinished-steps/tip",
                "tip/unfinished-other",
            ])
            .to_owned(),
        _ => format!("{}", -(g.count(4) as i64)),
    }
}

/// Rows of a committed diagram, cut and mutated, under a header.
fn hostile_csv(g: &mut Gen) -> String {
    let source = if g.u64() & 1 == 0 { N4 } else { N8 };
    let mut lines = source.lines();
    let header = lines.next().unwrap_or_default();
    let rows: Vec<&str> = lines.collect();
    let mut out = String::new();
    match g.u64() % 8 {
        0 => {}                                              // no header
        1 => out.push_str("pop_out,fixed,theta0_deg\n"),     // another one
        2 => out.push_str(&format!("\u{feff}{header}\r\n")), // BOM, CRLF
        _ => out.push_str(&format!("{header}\n")),
    }
    if rows.is_empty() {
        return out;
    }
    // a run of consecutive rows (whole lines or their pieces), or a few
    // picked anywhere
    let take = (g.u64() % 60) as usize;
    let start = (g.u64() % rows.len() as u64) as usize;
    for k in 0..take {
        let row = if g.u64().is_multiple_of(8) {
            rows[(g.u64() % rows.len() as u64) as usize]
        } else {
            rows[(start + k) % rows.len()]
        };
        let mut fields: Vec<String> = row.split(',').map(str::to_owned).collect();
        if g.u64().is_multiple_of(6) {
            let i = (g.u64() % fields.len() as u64) as usize;
            fields[i] = hostile_field(g);
        }
        match g.u64() % 16 {
            0 => {
                fields.pop();
            }
            1 => fields.push(hostile_field(g)),
            _ => {}
        }
        out.push_str(&fields.join(","));
        out.push_str(if g.u64().is_multiple_of(16) {
            "\r\n"
        } else {
            "\n"
        });
    }
    out
}

fn scene_ok(theta0: f64, a_over_b: f64, nu: f64) -> bool {
    theta0 > 0.0 && theta0 < FRAC_PI_2 && material_ok(a_over_b, nu)
}

fn material_ok(a_over_b: f64, nu: f64) -> bool {
    a_over_b > 0.0 && a_over_b.is_finite() && nu > -1.0 && nu < 0.5
}

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
        let csv = hostile_csv(g);
        let coils = if g.u64() & 1 == 0 { 4 } else { g.u32(9) };
        let what = || format!("PhaseDiagram::from_csv({coils}, {csv:?})");
        let Some(res) = r.call(what, || PhaseDiagram::from_csv(coils, &csv)) else {
            continue;
        };
        let d = match res {
            Ok(d) => d,
            Err(e) => {
                r.check(matches!(e, Error::InvalidArgument { .. }), || {
                    format!("{}: {e}", what())
                });
                continue;
            }
        };
        let what = || format!("PhaseDiagram::from_csv({coils}, {csv:?}): to_csv, from_csv");
        if let Some(back) = r.call(what, || PhaseDiagram::from_csv(coils, &d.to_csv())) {
            // (compared as text: NaN forces are not equal to themselves)
            r.check(
                back.as_ref().is_ok_and(|b| b.to_csv() == d.to_csv()),
                || format!("{}: {back:?}", what()),
            );
        }
        let mapped = d.pop_out_count();
        for _ in 0..4 {
            let theta0 = if g.u64() & 1 == 0 {
                g.arg(80.0, 90.0).to_radians()
            } else {
                g.arg(0.0, FRAC_PI_2)
            };
            let (a_over_b, nu) = (g.arg(0.01, 100.0), g.arg(-1.0, 0.5));
            let i = g.count(4) as usize;
            let what = || {
                format!(
                    "diagram of {coils} coils ({csv:?}): pop_outs({theta0:e}, {a_over_b:e}, {nu:e}), cusp_theta0({i}, …)"
                )
            };
            let Some((count, cusp)) = r.call(what, || {
                (
                    d.pop_outs(theta0, a_over_b, nu),
                    d.cusp_theta0(i, a_over_b, nu),
                )
            }) else {
                continue;
            };
            let ok = match count {
                Ok(n) => scene_ok(theta0, a_over_b, nu) && n <= mapped,
                Err(Error::InvalidArgument { .. }) => !scene_ok(theta0, a_over_b, nu),
                Err(Error::NotMapped {
                    from_deg, to_deg, ..
                }) => {
                    scene_ok(theta0, a_over_b, nu)
                        && from_deg >= 0.0
                        && from_deg <= to_deg
                        && to_deg <= 90.0 + 1e-9
                }
                Err(_) => false,
            };
            r.check(ok, || format!("{}: {count:?}", what()));
            let ok = match &cusp {
                Ok(range) => {
                    material_ok(a_over_b, nu)
                        && *range.start() >= 0.0
                        && range.start() <= range.end()
                        && *range.end() <= FRAC_PI_2 + 1e-12
                }
                Err(Error::InvalidArgument { .. }) => !material_ok(a_over_b, nu),
                Err(_) => false,
            };
            r.check(ok, || format!("{}: {cusp:?}", what()));
        }
    }
}
