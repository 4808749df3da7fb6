//! Reading the mpmath tables and summarising errors in ulps.

use hockle::special::Modulus;

/// One row of a table: the modulus as given ("m" or "c" = m₁), then numbers.
pub struct Row {
    pub modulus: Modulus,
    pub kind: String,
    pub x: f64,
    pub nums: Vec<f64>,
}

pub fn read(name: &str) -> Vec<Row> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .skip(1)
        .map(|line| {
            let mut it = line.split('\t');
            let kind = it.next().expect("kind").to_string();
            let x: f64 = it.next().expect("x").parse().expect("x parses");
            let modulus = match kind.as_str() {
                "m" => Modulus::from_m(x),
                "c" => Modulus::from_complement(x),
                _ => panic!("bad kind {kind}"),
            }
            .expect("table moduli are valid");
            let nums = it.map(|s| s.parse().expect("number parses")).collect();
            Row {
                modulus,
                kind,
                x,
                nums,
            }
        })
        .collect()
}

/// Error of `x` against the reference hi + lo, in ulps of the reference
/// (units of ε·|ref|); exact infinities count as 0.
pub fn ulps_dd(x: f64, hi: f64, lo: f64) -> f64 {
    if x == hi && lo == 0.0 {
        return 0.0;
    }
    if hi.is_infinite() || x.is_nan() {
        return f64::INFINITY;
    }
    if hi == 0.0 {
        return super::common::ulps(x, 0.0);
    }
    (((x - hi) - lo) / hi).abs() / f64::EPSILON
}

/// Median, 99th percentile and maximum of a sample (NaN counts as ∞).
pub struct Stats {
    pub median: f64,
    pub p99: f64,
    pub max: f64,
    pub n: usize,
}

pub fn stats(errs: &[f64]) -> Stats {
    let mut v: Vec<f64> = errs
        .iter()
        .map(|e| if e.is_nan() { f64::INFINITY } else { *e })
        .collect();
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((v.len() - 1) as f64 * q).round() as usize];
    Stats {
        median: at(0.5),
        p99: at(0.99),
        max: *v.last().expect("non-empty"),
        n: v.len(),
    }
}

/// One line of the accuracy table, in the Markdown form of docs/ACCURACY.md.
pub fn line(name: &str, raw: &Stats, norm: Option<&Stats>) -> String {
    match norm {
        Some(n) => format!(
            "| {name} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} |",
            raw.n, raw.median, raw.p99, raw.max, n.median, n.p99, n.max
        ),
        None => format!(
            "| {name} | {} | {:.2} | {:.2} | {:.2} | – | – | – |",
            raw.n, raw.median, raw.p99, raw.max
        ),
    }
}

/// Prints a table of error statistics in the Markdown form of docs/ACCURACY.md.
pub fn report(title: &str, head: &str, lines: &[String]) {
    println!("\n{title}");
    println!("| {head} | n | median | p99 | max | median (norm.) | p99 (norm.) | max (norm.) |");
    println!("|---|---|---|---|---|---|---|---|");
    for l in lines {
        println!("{l}");
    }
}

/// Prints where the largest error of a sample occurred.
pub fn worst(name: &str, errs: &[f64], ctx: &[String]) {
    let (i, e) = errs
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .expect("non-empty");
    println!("  worst {name}: {e:.2} ulp at {}", ctx[i]);
}
