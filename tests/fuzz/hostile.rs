//! The seeded generator of hostile arguments and the report of oracle
//! failures.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

/// splitmix64: small, fast, and the same sequence on every platform.
pub struct Gen(u64);

/// Values that break numerical code: non-finite, signed zeros, subnormals,
/// the ends of the double range and of the usual domains.
const HOSTILE: [f64; 30] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    5e-324,
    -5e-324,
    1e-310,
    -1e-310,
    f64::MIN_POSITIVE,
    1e-300,
    -1e-300,
    1e-150,
    f64::EPSILON,
    0.5,
    0.999_999_999_999_999_9,
    1.0,
    -1.0,
    1.000_000_000_000_000_2,
    2.0,
    core::f64::consts::FRAC_PI_2,
    core::f64::consts::PI,
    1e6,
    -1e6,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    4.294_967_295e9,
    1e16,
];

impl Gen {
    pub fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ 0x2545_f491_4f6c_dd1d)
    }

    pub fn u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn pick<T: Copy>(&mut self, from: &[T]) -> T {
        from[(self.u64() % from.len() as u64) as usize]
    }

    /// Any double: a hostile value, a log-uniform magnitude over the whole
    /// range with either sign, or a random bit pattern.
    pub fn any_f64(&mut self) -> f64 {
        match self.u64() % 4 {
            0 | 1 => self.pick(&HOSTILE),
            2 => {
                let mag = 10f64.powf(-323.0 + 631.0 * self.unit());
                if self.u64() & 1 == 0 { mag } else { -mag }
            }
            _ => f64::from_bits(self.u64()),
        }
    }

    /// An argument for a parameter documented on [lo, hi]: half the time
    /// inside (uniform, or log-uniform near either end, or the ends
    /// themselves), otherwise one ulp outside or anything at all.
    pub fn arg(&mut self, lo: f64, hi: f64) -> f64 {
        match self.u64() % 8 {
            0 => lo + (hi - lo) * self.unit(),
            1 => {
                let t = 10f64.powf(-320.0 * self.unit());
                lo + (hi - lo) * t
            }
            2 => {
                let t = 10f64.powf(-320.0 * self.unit());
                hi - (hi - lo) * t
            }
            3 => self.pick(&[lo, hi]),
            4 => self.pick(&[ulp_step(lo, false), ulp_step(hi, true)]),
            _ => self.any_f64(),
        }
    }

    /// A count: small, around a limit, or huge.
    pub fn count(&mut self, small: u64) -> u64 {
        match self.u64() % 4 {
            0 | 1 => self.u64() % (small + 1),
            2 => self.pick(&[
                0,
                1,
                2,
                3,
                hockle::error::MAX_POINTS as u64,
                hockle::error::MAX_POINTS as u64 + 1,
                u64::from(u32::MAX),
                u64::MAX,
            ]),
            _ => self.u64() >> (self.u64() % 64),
        }
    }

    /// A u32 (coils, periods): small, or anything.
    pub fn u32(&mut self, small: u32) -> u32 {
        match self.u64() % 4 {
            0 | 1 => (self.u64() % (u64::from(small) + 1)) as u32,
            2 => self.pick(&[0, 1, 2, 50, 221, 222, 1000, 100_000, u32::MAX]),
            _ => self.u64() as u32,
        }
    }
}

/// Calls and oracle failures of one run.
pub struct Report {
    name: &'static str,
    pub calls: u64,
    failures: Vec<String>,
    start: Instant,
    verbose: bool,
}

impl Report {
    pub fn new(name: &str) -> Self {
        Self {
            name: Box::leak(name.to_owned().into_boxed_str()),
            calls: 0,
            failures: Vec::new(),
            start: Instant::now(),
            verbose: std::env::var_os("HOCKLE_FUZZ_VERBOSE").is_some(),
        }
    }

    /// Runs `f` under `catch_unwind`; a panic is a failure and gives `None`.
    /// With `HOCKLE_FUZZ_VERBOSE` set every call is printed first (to find
    /// a hang or an abort).
    pub fn call<R>(&mut self, what: impl Fn() -> String, f: impl FnOnce() -> R) -> Option<R> {
        self.calls += 1;
        if self.verbose {
            eprintln!("{}", what());
        }
        match catch_unwind(AssertUnwindSafe(f)) {
            Ok(v) => Some(v),
            Err(_) => {
                self.fail(format!("PANIC in {}", what()));
                None
            }
        }
    }

    /// Records a failure unless `ok`.
    pub fn check(&mut self, ok: bool, what: impl Fn() -> String) {
        if !ok {
            self.fail(what());
        }
    }

    fn fail(&mut self, msg: String) {
        if self.failures.len() < 50 {
            self.failures.push(msg);
        } else if self.failures.len() == 50 {
            self.failures.push("… (more)".into());
        }
    }

    /// Prints the call count and asserts that nothing failed.
    pub fn finish(&self) {
        eprintln!(
            "fuzz {}: {} calls in {:.1} s, {} failures",
            self.name,
            self.calls,
            self.start.elapsed().as_secs_f64(),
            self.failures.len()
        );
        assert!(
            self.failures.is_empty(),
            "fuzz {}: {} failures:\n{}",
            self.name,
            self.failures.len(),
            self.failures.join("\n")
        );
    }
}

/// All values finite.
pub fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The neighbouring double above (`up`) or below a finite x
/// (`f64::next_up`/`next_down`, which need Rust 1.86).
fn ulp_step(x: f64, up: bool) -> f64 {
    if x == 0.0 {
        return if up { 5e-324 } else { -5e-324 };
    }
    let bits = x.to_bits();
    f64::from_bits(if (x > 0.0) == up { bits + 1 } else { bits - 1 })
}
