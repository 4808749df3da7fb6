//! The paper's diamonds: out-of-plane instability points of the planar
//! elastica branches of an n = 4 rod, and how they move with C.
//!
//! ```text
//! cargo run --release --example diamonds
//! cargo run --release --example diamonds -- --nu -0.2 --nu -0.3   # every diamond below F/(2πn)² = 40 at these ν
//! ```
//!
//! Prints every diamond up to F/(2πn)² = 2 for the paper's rod (A/B = 10,
//! C on the Nikolai bound with ν = 0.05), then the primary υ diamond for
//! A/B = 10 and a range of C/B (docs/ACCURACY.md, "elastica: the diamonds").
//! Forces are the physical tension F/(2πn)², half the paper's printed scale.
use hockle::Stiffness;
use hockle::elastica::{Branch, Elastica, OutOfPlane};
use hockle::special::Modulus;

const USAGE: &str = "\
usage: cargo run --release --example diamonds -- [OPTIONS]
  --nu NU        (repeatable) every diamond below F/(2πn)² = 40 at A/B = 10 and C by the
                 Nikolai equality at this Poisson ratio, as CSV (default: the paper's
                 tables at ν = 0.05 and against C/B)
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("diamonds", run())
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut nus = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--nu" => nus.push(
                args.next()
                    .ok_or("--nu needs a Poisson ratio")?
                    .parse::<f64>()?,
            ),
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    if !nus.is_empty() {
        // every branch's diamonds at the Nikolai C of each ν (A/B = 10)
        println!("nu,C/B,branch,force_scaled,extension");
        for nu in nus {
            let s = Stiffness::nikolai(10.0, nu)?;
            for d in OutOfPlane::new(4, s)?.all_diamonds(40.0)? {
                println!(
                    "{nu},{:.4},{},{:.5},{:.5}",
                    s.c(),
                    d.branch(),
                    d.force_scaled(),
                    d.extension()
                );
            }
        }
        return Ok(());
    }
    let paper = Stiffness::nikolai(10.0, 0.05)?;
    println!("# n = 4, A/B = 10, C/B = {:.4} (ν = 0.05)", paper.c());
    println!("branch,k,force_scaled,extension");
    for d in OutOfPlane::new(4, paper)?.all_diamonds(2.0)? {
        println!(
            "{},{:.12},{:.10},{:.10}",
            d.branch(),
            d.modulus(),
            d.force_scaled(),
            d.extension()
        );
    }
    println!("\n# primary υ, n = 4, A/B = 10: its diamonds below F/(2πn)² = 20 against C/B");
    println!("C/B,D/k² at k = 1e-3,force_scaled of each diamond");
    let near_ring = Elastica::upsilon(4, Modulus::from_k(1e-3)?)?;
    for c in [
        0.25,
        0.5,
        1.0,
        1.01,
        1.05,
        1.1,
        1.2,
        1.5,
        paper.c(),
        1.9,
        2.0,
        2.1,
        2.5,
        5.0,
    ] {
        let oop = OutOfPlane::new(4, Stiffness::new(10.0, 1.0, c)?)?.grid(1024)?;
        let d: Vec<String> = oop
            .diamonds(Branch::Upsilon, 20.0)?
            .iter()
            .map(|d| format!("{:.6}", d.force_scaled()))
            .collect();
        let ring = oop.determinant(&near_ring)? / 1e-6;
        println!("{c:.4},{ring:+.4e},{}", d.join(","));
    }
    Ok(())
}
