//! The picture of `--trade` (`trade.rs`): CPU time against true error,
//! log-log, as SVG.

use std::fmt::Write as _;

use crate::trade::{COLOURS, Row, SERIES, TOLERANCES, median};

/// CPU time against true error, log-log: every spring's point per series
/// (small, pale), the median per series (large) and the lower-left front
/// through the medians.
pub fn plot(rows: &[&Row]) -> String {
    let (w, h) = (860.0, 600.0);
    let (left, right, top, bottom) = (80.0, 200.0, 50.0, 70.0);
    let (pw, ph) = (w - left - right, h - top - bottom);
    let (e_lo, e_hi, t_lo, t_hi) = (-9.0, 0.0, -7.0, 1.0);
    let x = |e: f64| left + (e.clamp(1e-9, 1.0).log10() - e_lo) / (e_hi - e_lo) * pw;
    let y = |t: f64| top + (1.0 - (t.clamp(1e-7, 10.0).log10() - t_lo) / (t_hi - t_lo)) * ph;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="28" font-size="17" text-anchor="middle">spring: what each model costs ({} springs pulled to F/((2πn)²B) = 1)</text>"#,
        left + pw / 2.0,
        rows.len()
    );
    for k in (e_lo as i32)..=(e_hi as i32) {
        let xx = x(10f64.powi(k));
        let _ = writeln!(
            s,
            r##"<line x1="{xx:.2}" y1="{top}" x2="{xx:.2}" y2="{:.2}" stroke="#e6e6e6"/><text x="{xx:.2}" y="{:.2}" font-size="12" text-anchor="middle">1e{k}</text>"##,
            top + ph,
            top + ph + 16.0
        );
    }
    for k in (t_lo as i32)..=(t_hi as i32) {
        let yy = y(10f64.powi(k));
        let _ = writeln!(
            s,
            r##"<line x1="{left}" y1="{yy:.2}" x2="{:.2}" y2="{yy:.2}" stroke="#e6e6e6"/><text x="{:.2}" y="{:.2}" font-size="12" text-anchor="end">{}</text>"##,
            left + pw,
            left - 6.0,
            yy + 4.0,
            seconds_axis(k)
        );
    }
    for tol in TOLERANCES {
        let xx = x(tol);
        let _ = writeln!(
            s,
            r##"<line x1="{xx:.2}" y1="{top}" x2="{xx:.2}" y2="{:.2}" stroke="#999999" stroke-dasharray="4 4"/>"##,
            top + ph
        );
    }
    let _ = writeln!(
        s,
        r#"<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="black"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.2}" y="{:.2}" font-size="13" text-anchor="middle">true error against the converged rod (max norm in Δz, F/((2πn)²B); above 1 drawn at 1; dashed: the tolerances)</text>"#,
        left + pw / 2.0,
        top + ph + 40.0
    );
    let _ = writeln!(
        s,
        r#"<text transform="translate(20 {:.2}) rotate(-90)" font-size="13" text-anchor="middle">CPU time of the model (one thread)</text>"#,
        top + ph / 2.0
    );
    let mut medians = Vec::new();
    for (i, colour) in COLOURS.iter().enumerate() {
        for row in rows {
            let (t, e) = row.cells[i];
            let _ = writeln!(
                s,
                r#"<circle cx="{:.2}" cy="{:.2}" r="2.5" fill="{colour}" fill-opacity="0.35"/>"#,
                x(e),
                y(t)
            );
        }
        let t = median(rows.iter().map(|r| r.cells[i].0).collect());
        let e = median(rows.iter().map(|r| r.cells[i].1).collect());
        medians.push((e, t));
    }
    // the front: medians no other median beats in both time and error
    let mut front: Vec<(f64, f64)> = medians
        .iter()
        .copied()
        .filter(|&(e, t)| !medians.iter().any(|&(e2, t2)| e2 < e && t2 < t))
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut d = String::new();
    for (k, (e, t)) in front.iter().enumerate() {
        if k > 0 {
            // a staircase: the best time for any error at least this one
            let _ = write!(d, "{:.2},{:.2} ", x(*e), y(front[k - 1].1));
        }
        let _ = write!(d, "{:.2},{:.2} ", x(*e), y(*t));
    }
    let _ = writeln!(
        s,
        r##"<polyline points="{d}" fill="none" stroke="#333333" stroke-width="1.2"/>"##
    );
    for (i, ((e, t), colour)) in medians.iter().zip(COLOURS).enumerate() {
        let _ = writeln!(
            s,
            r#"<circle cx="{:.2}" cy="{:.2}" r="7" fill="{colour}" stroke="black" stroke-width="1"/>"#,
            x(*e),
            y(*t)
        );
        let ly = top + 20.0 + 22.0 * i as f64;
        let lx = left + pw + 20.0;
        let _ = writeln!(
            s,
            r#"<circle cx="{lx:.2}" cy="{ly:.2}" r="6" fill="{colour}" stroke="black" stroke-width="1"/><text x="{:.2}" y="{:.2}" font-size="13">{}</text>"#,
            lx + 12.0,
            ly + 4.0,
            SERIES[i]
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{:.2}" y="{:.2}" font-size="11">large: median over the springs</text><text x="{:.2}" y="{:.2}" font-size="11">small: one spring each</text><text x="{:.2}" y="{:.2}" font-size="11">line: front of the medians</text>"#,
        left + pw + 14.0,
        top + 170.0,
        left + pw + 14.0,
        top + 186.0,
        left + pw + 14.0,
        top + 202.0
    );
    s.push_str("</svg>\n");
    s
}

/// The label of 10^k seconds on the time axis.
fn seconds_axis(k: i32) -> String {
    match k {
        -7..=-4 => format!("{} µs", 10f64.powi(k + 6)),
        -3..=-1 => format!("{} ms", 10f64.powi(k + 3)),
        _ => format!("{} s", 10f64.powi(k)),
    }
}
