//! The two panels as hand-written SVG: the count of pop-outs as filled
//! cells (read off the diagram, [`PhaseDiagram::pop_outs`]) and the cusp
//! lines themselves (points from continuation, joined straight).

use std::fmt::Write as _;

use hockle::rod::{Fixed, PhaseDiagram};

/// Okabe–Ito: fills for 0, 1, 2, 3, … pop-outs and line colours.
/// Okabe–Ito fills for 1–4 pop-outs, then greys; beyond four pop-outs the
/// lines repeat dashed.
const FILL: [&str; 8] = [
    "#ffffff", "#F0E442", "#56B4E9", "#009E73", "#CC79A7", "#bbbbbb", "#888888", "#555555",
];
const LINE: [&str; 4] = ["#E69F00", "#0072B2", "#D55E00", "#000000"];

/// Fill of k pop-outs: white for none, then the four colours in turn.
fn fill(k: usize) -> &'static str {
    if k == 0 {
        FILL[0]
    } else {
        FILL[1 + (k - 1) % (FILL.len() - 1)]
    }
}

/// Stroke colour and dash of pop-out i's line.
fn stroke(i: usize) -> (&'static str, &'static str) {
    let dash = if i >= LINE.len() { "6,4" } else { "none" };
    (LINE[i % LINE.len()], dash)
}
const W: f64 = 420.0;
const H: f64 = 320.0;
const LEFT: f64 = 70.0;
const TOP: f64 = 40.0;

struct Panel {
    x0: f64,
    theta: (f64, f64),
    y: (f64, f64),
    log: bool,
}

impl Panel {
    fn px(&self, theta_deg: f64) -> f64 {
        self.x0 + LEFT + W * (theta_deg - self.theta.0) / (self.theta.1 - self.theta.0)
    }
    fn py(&self, v: f64) -> f64 {
        let (a, b, v) = if self.log {
            (self.y.0.ln(), self.y.1.ln(), v.ln())
        } else {
            (self.y.0, self.y.1, v)
        };
        TOP + H * (1.0 - (v - a) / (b - a))
    }
    fn value(&self, t: f64) -> f64 {
        if self.log {
            (self.y.0.ln() + t * (self.y.1.ln() - self.y.0.ln())).exp()
        } else {
            self.y.0 + t * (self.y.1 - self.y.0)
        }
    }
}

pub fn draw(d: &hockle::rod::PhaseDiagram) -> String {
    let low = |keep: &dyn Fn(Fixed) -> bool| {
        let lo = d
            .lines()
            .iter()
            .filter(|l| keep(l.fixed))
            .flat_map(|l| l.points.iter())
            .map(|p| p.theta0.to_degrees())
            .fold(90.0_f64, f64::min);
        ((lo - 0.5).floor(), 90.0)
    };
    let on_a = |f: Fixed| matches!(f, Fixed::Nu(v) if v == 0.05);
    let on_nu = |f: Fixed| matches!(f, Fixed::AOverB(v) if (v - 10.0).abs() < 1e-9);
    let mut s = String::new();
    let width = 2.0 * (W + LEFT + 40.0);
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{{HEIGHT}}" font-family="sans-serif" font-size="13">"#
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        s,
        r##"<defs><pattern id="unmapped" width="6" height="6" patternUnits="userSpaceOnUse" patternTransform="rotate(45)"><rect width="6" height="6" fill="#eeeeee"/><line x1="0" y1="0" x2="0" y2="6" stroke="#555555" stroke-width="2"/></pattern></defs>"##
    );
    let a = Panel {
        x0: 0.0,
        theta: low(&on_a),
        y: (1.0, 100.0),
        log: true,
    };
    let n = Panel {
        x0: W + LEFT + 40.0,
        theta: low(&on_nu),
        y: (-0.9, 0.49),
        log: false,
    };
    // an incomplete diagram counts the mapped pop-outs: a lower bound
    // (`PhaseDiagram::is_complete`)
    let what = if d.is_complete() {
        "pop-outs"
    } else {
        "at least these pop-outs"
    };
    let mut unmapped = panel(
        &mut s,
        d,
        &a,
        "A/B",
        &format!("n = {}, ν = 0.05: {what} over (θ0, A/B)", d.coils()),
        |t, y| (t, y, 0.05),
        on_a,
        |p| p.a_over_b,
    );
    unmapped |= panel(
        &mut s,
        d,
        &n,
        "ν",
        &format!("n = {}, A/B = 10: {what} over (θ0, ν)", d.coils()),
        |t, y| (t, 10.0, y),
        on_nu,
        |p| p.nu,
    );
    // legend
    let mut y = H + TOP + 60.0;
    let mut x = LEFT;
    for k in 0..=d.pop_out_count() {
        let fill = fill(k);
        if x > width - 120.0 {
            x = LEFT;
            y += 22.0;
        }
        let _ = writeln!(
            s,
            r#"<rect x="{x}" y="{}" width="16" height="12" fill="{fill}" stroke="grey"/><text x="{}" y="{}">{k} pop-outs</text>"#,
            y - 10.0,
            x + 20.0,
            y
        );
        x += 105.0;
    }
    if unmapped {
        let _ = writeln!(
            s,
            r#"<rect x="{x}" y="{}" width="16" height="12" fill="url(#unmapped)" stroke="grey"/><text x="{}" y="{}">not mapped</text>"#,
            y - 10.0,
            x + 20.0,
            y
        );
        x += 105.0;
    }
    for i in 0..d.pop_out_count() {
        let (c, dash) = stroke(i);
        if x > width - 160.0 {
            x = LEFT;
            y += 22.0;
        }
        let _ = writeln!(
            s,
            r#"<line x1="{x}" y1="{}" x2="{}" y2="{}" stroke="{c}" stroke-dasharray="{dash}" stroke-width="2.5"/><text x="{}" y="{}">cusps of pop-out {}</text>"#,
            y - 4.0,
            x + 22.0,
            y - 4.0,
            x + 26.0,
            y,
            i + 1
        );
        x += 150.0;
    }
    s.push_str("</svg>\n");
    // as high as the legend's rows need (seven pop-outs take four)
    let height = (H + TOP + 90.0).max(y + 20.0);
    s.replacen("{HEIGHT}", &height.to_string(), 1)
}

#[allow(clippy::too_many_arguments)]
fn panel(
    s: &mut String,
    d: &PhaseDiagram,
    p: &Panel,
    ylabel: &str,
    title: &str,
    scene: impl Fn(f64, f64) -> (f64, f64, f64),
    line: impl Fn(Fixed) -> bool,
    coord: impl Fn(&hockle::rod::CuspAt) -> f64,
) -> bool {
    let mut unmapped = false;
    // cells of one count merged along each row
    let (nx, ny) = (240, 160);
    let (cw, ch) = (W / f64::from(nx), H / f64::from(ny));
    for j in 0..ny {
        let y = p.value((f64::from(j) + 0.5) / f64::from(ny));
        let count = |i: u32| {
            let t = p.theta.0 + (f64::from(i) + 0.5) / f64::from(nx) * (p.theta.1 - p.theta.0);
            let (th, ab, nu) = scene(t, y);
            // None: not mapped (a swallowtail's fold-back, or beyond an
            // unfinished line), drawn hatched
            d.pop_outs(th.to_radians(), ab, nu).ok()
        };
        let mut i = 0;
        while i < nx {
            let k = count(i);
            let mut e = i + 1;
            while e < nx && count(e) == k {
                e += 1;
            }
            unmapped |= k.is_none();
            if k != Some(0) {
                let _ = writeln!(
                    s,
                    r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{}"/>"#,
                    p.x0 + LEFT + f64::from(i) * cw,
                    TOP + H - f64::from(j + 1) * ch,
                    f64::from(e - i) * cw + 0.3,
                    ch + 0.3,
                    k.map_or("url(#unmapped)", fill)
                );
            }
            i = e;
        }
    }
    for l in d.lines().iter().filter(|l| line(l.fixed)) {
        let pts: Vec<String> = l
            .points
            .iter()
            .filter(|q| {
                let v = coord(q);
                v >= p.y.0.min(p.y.1) && v <= p.y.1.max(p.y.0)
            })
            .map(|q| format!("{:.2},{:.2}", p.px(q.theta0.to_degrees()), p.py(coord(q))))
            .collect();
        let _ = writeln!(
            s,
            r#"<polyline points="{}" fill="none" stroke="{}" stroke-dasharray="{}" stroke-width="2.5"/>"#,
            pts.join(" "),
            stroke(l.pop_out).0,
            stroke(l.pop_out).1
        );
    }
    let (x0, x1) = (p.x0 + LEFT, p.x0 + LEFT + W);
    let _ = writeln!(
        s,
        r#"<rect x="{x0}" y="{TOP}" width="{W}" height="{H}" fill="none" stroke="black"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle" font-size="14">{title}</text>"#,
        (x0 + x1) / 2.0,
        TOP - 14.0
    );
    let step = if p.theta.1 - p.theta.0 > 10.0 {
        2.0
    } else {
        1.0
    };
    let mut t = (p.theta.0 / step).ceil() * step;
    while t <= p.theta.1 + 1e-9 {
        let x = p.px(t);
        let _ = writeln!(
            s,
            r#"<line x1="{x:.2}" y1="{}" x2="{x:.2}" y2="{}" stroke="black"/><text x="{x:.2}" y="{}" text-anchor="middle">{t}</text>"#,
            TOP + H,
            TOP + H + 5.0,
            TOP + H + 20.0
        );
        t += step;
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle">helix angle θ0 (degrees)</text>"#,
        (x0 + x1) / 2.0,
        TOP + H + 38.0
    );
    let ticks: Vec<f64> = if p.log {
        vec![1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0]
    } else {
        vec![-0.8, -0.6, -0.4, -0.2, 0.0, 0.2, 0.4]
    };
    for v in ticks {
        let y = p.py(v);
        let _ = writeln!(
            s,
            r#"<line x1="{}" y1="{y:.2}" x2="{x0}" y2="{y:.2}" stroke="black"/><text x="{}" y="{:.2}" text-anchor="end">{v}</text>"#,
            x0 - 5.0,
            x0 - 8.0,
            y + 4.0
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle" transform="rotate(-90 {} {})">{ylabel}</text>"#,
        x0 - 45.0,
        TOP + H / 2.0,
        x0 - 45.0,
        TOP + H / 2.0
    );
    unmapped
}
