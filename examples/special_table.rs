//! K, E, sn, cn, dn at the moduli of the paper's elastica (n = 4).
//!
//! `cargo run --release --example special_table`
//!
//! Rows: the moduli at which the non-symmetric ϑ-branches of Starostin &
//! van der Heijden (2009) gain a root of eq81 at s₁ = 0, i.e. where
//! 2K(k) j = πn (the dn maximum meets the end-curvature condition), for
//! n = 4 and j = 1, 2, 3; then moduli towards k = 1 given by m₁ = 1 − k².
//! Columns sn, cn, dn are at u = K/2, where DLMF 22.5.2 gives closed
//! forms: sn = 1/√(1 + k′), cn = √(k′/(1 + k′)), dn = √k′; the last column
//! is the largest relative deviation from them.

use hockle::special::{Modulus, ellip_e, ellip_k, jacobi};
use std::f64::consts::PI;

/// The modulus with K(k) = target, by bisection on log m₁ (K decreases in m₁).
fn modulus_with_k(target: f64) -> Modulus {
    let (mut lo, mut hi) = (-700.0f64, 0.0f64); // log m₁
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let md = Modulus::from_complement(mid.exp()).expect("m1 in (0, 1]");
        if ellip_k(md) > target {
            lo = mid
        } else {
            hi = mid
        }
    }
    Modulus::from_complement((0.5 * (lo + hi)).exp()).expect("m1 in (0, 1]")
}

const USAGE: &str = "\
usage: cargo run --release --example special_table -- [OPTIONS]
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("special_table", run())
}

fn run() -> Result<(), String> {
    if cli::help(USAGE) {
        return Ok(());
    }
    cli::only_flags(&[], USAGE)?;
    let n = 4.0;
    let mut rows: Vec<(String, Modulus)> = (1..4)
        .map(|j| {
            (
                format!("2Kj = 4π, j = {j}"),
                modulus_with_k(PI * n / (2.0 * f64::from(j))),
            )
        })
        .collect();
    for mc in [0.75, 0.19, 1e-2, 1e-6, 1e-12, 1e-300] {
        rows.push((
            format!("m1 = {mc:e}"),
            Modulus::from_complement(mc).expect("valid"),
        ));
    }
    println!(
        "{:<18} {:>22} {:>10} {:>20} {:>20} {:>20} {:>12} {:>12} {:>9}",
        "row", "k", "m1", "K", "E", "sn(K/2)", "cn(K/2)", "dn(K/2)", "max rel"
    );
    for (label, md) in rows {
        let (k, e) = (ellip_k(md), ellip_e(md));
        let j = jacobi(0.5 * k, md);
        let kp = md.k_prime();
        let exact = [1.0 / (1.0 + kp).sqrt(), (kp / (1.0 + kp)).sqrt(), kp.sqrt()];
        let dev = [j.sn, j.cn, j.dn]
            .iter()
            .zip(exact)
            .map(|(x, r)| ((x - r) / r).abs())
            .fold(0.0, f64::max);
        println!(
            "{label:<18} {:>22.17} {:>10.3e} {:>20.16} {:>20.17} {:>20.17} {:>12.5e} {:>12.5e} {:>9.1e}",
            md.k(),
            md.complement(),
            k,
            e,
            j.sn,
            j.cn,
            j.dn,
            dev
        );
    }
    Ok(())
}
