//! `bvp`: the mesh constructors, every `Collocation` setting on the classic
//! problems, hostile parameters and guesses, and user problems whose counts
//! are huge or whose functions return NaN.

use hockle::Error;
use hockle::bvp::classic::{Bratu, Linear};
use hockle::bvp::{Collocation, LinearSolver, Mesh, Problem, Solution};

use crate::hostile::{Gen, Report, finite};

/// Meshes take microseconds, solves on at most 40 intervals tens of
/// microseconds: about a second in release.
pub const CI_CALLS: u64 = 100_000;

/// Solves in the fuzz loop use at most this many intervals (the validation
/// of larger counts is exercised without solving: `settings_only`).
const SOLVE_INTERVALS: usize = 40;

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
        mesh(g, r);
        if g.u64().is_multiple_of(4) {
            collocation(g, r);
        }
        if g.u64().is_multiple_of(16) {
            hostile_problem(g, r);
        }
    }
}

fn mesh(g: &mut Gen, r: &mut Report) {
    // counts that can be allocated only; huge ones: `huge_counts`
    let intervals = (g.count(64) % 10_000) as usize;
    if let Some(res) = r.call(
        || format!("Mesh::uniform({intervals})"),
        || Mesh::uniform(intervals),
    ) {
        match res {
            Ok(m) => r.check(
                intervals >= 1
                    && m.intervals() == intervals
                    && m.points().first() == Some(&0.0)
                    && m.points().last() == Some(&1.0)
                    && m.points().windows(2).all(|w| w[1] > w[0]),
                || format!("Mesh::uniform({intervals}): bad Ok"),
            ),
            Err(e) => r.check(intervals == 0, || {
                format!("Mesh::uniform({intervals}): {e}")
            }),
        }
    }
    let len = (g.u64() % 6) as usize;
    let mut pts: Vec<f64> = (0..len).map(|_| g.arg(0.0, 1.0)).collect();
    if g.u64() & 1 == 0 && len >= 2 {
        // a valid mesh half the time
        pts.sort_by(f64::total_cmp);
        pts[0] = 0.0;
        pts[len - 1] = 1.0;
    }
    let valid =
        len >= 2 && pts[0] == 0.0 && pts[len - 1] == 1.0 && pts.windows(2).all(|w| w[1] > w[0]);
    let shown = format!("{pts:?}");
    if let Some(res) = r.call(
        || format!("Mesh::from_points({shown})"),
        || Mesh::from_points(pts),
    ) {
        r.check(res.is_ok() == valid, || {
            format!("Mesh::from_points({shown}) = {res:?}")
        });
    }
}

/// Every number a solution reports is finite.
pub fn solution_finite(s: &Solution) -> bool {
    let n = s.mesh().intervals();
    finite(s.parameters())
        && (0..=n).all(|j| finite(s.at_mesh(j)))
        && s.residual_norm().is_finite()
        && s.error_estimate().is_finite()
        && finite(s.eval(0.37).as_slice())
}

/// The errors a solve with valid settings may end in: the solver could not
/// do it (or, for a hostile parameter, the problem returned NaN/∞).
fn solver_refusal(e: &Error) -> bool {
    matches!(
        e,
        Error::NonFinite { .. }
            | Error::SingularJacobian { .. }
            | Error::NewtonDiverged { .. }
            | Error::NewtonNotConverged { .. }
            | Error::ToleranceNotMet { .. }
    )
}

/// The settings of one hostile `Collocation` and whether they are valid
/// (`Collocation::new` documents each domain).
struct Settings {
    points: usize,
    intervals: Option<usize>,
    max_intervals: usize,
    tolerance: Option<f64>,
    newton_tolerance: f64,
    max_newton: u32,
    free: Vec<usize>,
    sparse: bool,
}

impl Settings {
    fn draw(g: &mut Gen) -> Self {
        let small = g.u64() & 1 == 0;
        let count = |g: &mut Gen, dflt: u64| {
            if small { dflt } else { g.count(dflt) }
        };
        Settings {
            points: count(g, 4) as usize,
            intervals: (!g.u64().is_multiple_of(3)).then(|| count(g, 12) as usize),
            max_intervals: if g.u64() & 1 == 0 {
                4000
            } else {
                g.count(60) as usize
            },
            tolerance: g.u64().is_multiple_of(4).then(|| g.arg(1e-12, 1.0)),
            newton_tolerance: if small { 1e-10 } else { g.arg(1e-14, 1e-2) },
            max_newton: if small { 30 } else { g.u32(40) },
            free: if g.u64().is_multiple_of(8) {
                vec![(g.count(2)) as usize]
            } else {
                Vec::new()
            },
            sparse: g.u64().is_multiple_of(8),
        }
    }

    fn valid(&self, parameter_count: usize) -> bool {
        let count = |c: usize| (1..=Mesh::MAX_INTERVALS).contains(&c);
        (2..=7).contains(&self.points)
            && self.intervals.is_none_or(count)
            && count(self.max_intervals)
            && self.tolerance.is_none_or(|t| t > 0.0 && t.is_finite())
            && (1e-14..=1e-2).contains(&self.newton_tolerance)
            && (1..=Collocation::MAX_NEWTON).contains(&self.max_newton)
            && self.free.iter().all(|&i| i < parameter_count)
    }

    fn build(&self) -> Collocation {
        let mut c = Collocation::new()
            .points(self.points)
            .max_intervals(self.max_intervals)
            .newton_tolerance(self.newton_tolerance)
            .max_newton(self.max_newton)
            .free_parameters(&self.free);
        if let Some(n) = self.intervals {
            c = c.intervals(n);
        }
        if let Some(t) = self.tolerance {
            c = c.tolerance(t);
        }
        if self.sparse {
            c = c.linear_solver(LinearSolver::SparseLu);
        }
        c
    }
}

/// `Collocation::solve` on y″ = y (closed form) and on Bratu with hostile
/// settings, parameters and guesses.
fn collocation(g: &mut Gen, r: &mut Report) {
    let mut set = Settings::draw(g);
    let bratu = g.u64() & 1 == 0;
    let np = usize::from(bratu);
    let valid = set.valid(np);
    if valid {
        // keep the solve cheap: a valid count is replaced by a small one
        // (the adaptive mesh is bounded by max_intervals)
        if set.intervals.is_some_and(|n| n > SOLVE_INTERVALS) {
            set.intervals = Some(1 + (g.u64() % SOLVE_INTERVALS as u64) as usize);
        }
        if set.tolerance.is_some() || set.max_intervals > 4000 {
            set.max_intervals = set.max_intervals.min(SOLVE_INTERVALS);
        }
    } else if settings_only(g, r, &set, np) {
        return;
    }
    // a free parameter of Bratu (λ) with two boundary conditions is
    // ill-posed: an error, not a solve
    let posed = set.free.is_empty();
    let solver = set.build();
    let what = || format!("{solver:?} on {}", if bratu { "Bratu" } else { "Linear" });
    let res = if bratu {
        let lambda = if g.u64() & 1 == 0 {
            g.unit() * 3.0
        } else {
            g.any_f64()
        };
        let wrong_len = g.u64().is_multiple_of(16);
        let p = if wrong_len {
            vec![lambda, lambda]
        } else {
            vec![lambda]
        };
        let nan_guess = g.u64().is_multiple_of(16);
        let res = r.call(what, || {
            let guess = move |s: f64| {
                if nan_guess && s > 0.5 {
                    [f64::NAN, 0.0]
                } else {
                    [0.0, 0.0]
                }
            };
            solver.solve(&Bratu::default(), guess, &p)
        });
        let Some(res) = res else { return };
        let ok_input = valid && posed && !wrong_len;
        match &res {
            // outside the domain (settings, counts, length): any typed
            // error; inside it, the solver's own refusals only (NaN/∞ in λ
            // or in the guess is the problem's `NonFinite`)
            Err(e) => r.check(!ok_input || solver_refusal(e), || {
                format!("{}: λ = {lambda:e}: {e}", what())
            }),
            Ok(_) => r.check(ok_input && lambda.is_finite() && !nan_guess, || {
                format!("{}: λ = {lambda:e}: accepted", what())
            }),
        }
        res
    } else {
        let Some(res) = r.call(what, || {
            solver.solve(&Linear, |s: f64| Linear::exact(s), &[])
        }) else {
            return;
        };
        match &res {
            Ok(_) => r.check(valid && posed, || format!("{}: accepted", what())),
            Err(e) => r.check(!(valid && posed) || solver_refusal(e), || {
                format!("{}: {e}", what())
            }),
        }
        res
    };
    if let Ok(s) = res {
        r.check(solution_finite(&s), || format!("{}: non-finite Ok", what()));
    }
}

/// Invalid settings must be refused before any work: `solve` with a
/// problem that panics if called. Returns whether it handled `set`.
fn settings_only(g: &mut Gen, r: &mut Report, set: &Settings, np: usize) -> bool {
    if !g.u64().is_multiple_of(2) {
        return false;
    }
    let solver = set.build();
    let problem = Untouchable { np };
    let p = vec![0.0; np];
    let what = || format!("{solver:?} on a problem that must not be called");
    if let Some(res) = r.call(what, || solver.solve(&problem, |_s: f64| [0.0, 0.0], &p)) {
        r.check(
            matches!(
                res,
                Err(Error::InvalidCount { .. } | Error::InvalidArgument { .. })
            ),
            || format!("{}: {res:?}", what()),
        );
    }
    true
}

/// A well-posed problem (two ODEs, two boundary conditions, `np` fixed
/// parameters) that panics when evaluated: settings must be checked first.
struct Untouchable {
    np: usize,
}

impl Problem for Untouchable {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        self.np
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, _y: &[f64], _p: &[f64], _f: &mut [f64]) {
        panic!("rhs called before the settings were checked");
    }
    fn boundary(&self, _y0: &[f64], _y1: &[f64], _p: &[f64], _g: &mut [f64]) {
        panic!("boundary called before the settings were checked");
    }
}

/// A user problem with arbitrary counts whose functions write `value`
/// (NaN, ∞ or a number) everywhere.
pub struct Counts {
    pub dim: usize,
    pub parameters: usize,
    pub boundary: usize,
    pub integral: usize,
    pub value: f64,
}

impl Problem for Counts {
    fn dim(&self) -> usize {
        self.dim
    }
    fn parameter_count(&self) -> usize {
        self.parameters
    }
    fn boundary_count(&self) -> usize {
        self.boundary
    }
    fn integral_count(&self) -> usize {
        self.integral
    }
    fn rhs(&self, _s: f64, _y: &[f64], _p: &[f64], f: &mut [f64]) {
        f.fill(self.value);
    }
    fn boundary(&self, _y0: &[f64], _y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g.fill(self.value);
    }
    fn integrand(&self, _s: f64, _y: &[f64], _y_ref: &[f64], _p: &[f64], h: &mut [f64]) {
        h.fill(self.value);
    }
}

/// User problems with hostile counts (ill-posed, wrapping sums, systems too
/// large to allocate) and non-finite functions.
fn hostile_problem(g: &mut Gen, r: &mut Report) {
    let huge = |g: &mut Gen| -> usize {
        g.pick(&[
            0,
            1,
            2,
            3,
            usize::MAX,
            usize::MAX - 1,
            usize::MAX / 2,
            u32::MAX as usize,
            1 << 40,
        ])
    };
    let dim = huge(g);
    let np = (g.u64() % 3) as usize;
    let (boundary, integral) = match g.u64() % 3 {
        // well-posed on the counts (maybe too large to allocate)
        0 => (dim, 0),
        1 => (dim.saturating_sub(1), usize::from(dim > 0)),
        _ => (huge(g), huge(g)),
    };
    let value = g.pick(&[f64::NAN, f64::INFINITY, 1.0, 0.0]);
    let problem = Counts {
        dim,
        parameters: np,
        boundary,
        integral,
        value,
    };
    let intervals = 1 + (g.u64() % 8) as usize;
    let posed = integral.checked_add(boundary) == Some(dim) && dim >= 1;
    let small = dim <= 3;
    let what = || {
        format!(
            "solve of a problem with dim {dim}, {np} parameters, {boundary} + {integral} conditions, \
             value {value} on {intervals} intervals"
        )
    };
    let p = vec![0.5; np];
    let Some(res) = r.call(what, || {
        // a guess of the problem's dimension only if it can be allocated
        let guess = move |_s: f64| vec![0.25; if small { dim } else { 0 }];
        Collocation::new()
            .intervals(intervals)
            .solve(&problem, guess, &p)
    }) else {
        return;
    };
    match res {
        Ok(s) => r.check(
            posed && small && value.is_finite() && solution_finite(&s),
            || format!("{}: accepted", what()),
        ),
        Err(e) => r.check(
            match e {
                Error::IllPosed { .. } => !posed,
                Error::InvalidCount { name: "dim", .. } => dim == 0,
                Error::SystemTooLarge { .. } => !small,
                Error::NonFinite { .. } => !value.is_finite(),
                // a constant right-hand side with constant boundary rows:
                // the Jacobian in y is singular
                ref e => solver_refusal(e) && posed && small,
            },
            || format!("{}: {e}", what()),
        ),
    }
}

/// Counts beyond what can be allocated must be refused, before the
/// problem is called.
pub fn huge_counts(_g: &mut Gen, r: &mut Report, _calls: u64) {
    for intervals in [
        Mesh::MAX_INTERVALS + 1,
        hockle::error::MAX_POINTS + 1,
        u32::MAX as usize,
        usize::MAX,
    ] {
        if let Some(res) = r.call(
            || format!("Mesh::uniform({intervals})"),
            || Mesh::uniform(intervals),
        ) {
            r.check(res.is_err(), || {
                format!("Mesh::uniform({intervals}) accepted")
            });
        }
        for max in [false, true] {
            let solver = if max {
                Collocation::new().tolerance(1e-6).max_intervals(intervals)
            } else {
                Collocation::new().intervals(intervals)
            };
            let what = || format!("{solver:?}: solve");
            let problem = Untouchable { np: 0 };
            if let Some(res) = r.call(what, || solver.solve(&problem, |_s: f64| [0.0, 0.0], &[])) {
                r.check(matches!(res, Err(Error::InvalidCount { .. })), || {
                    format!("{}: {res:?}", what())
                });
            }
        }
    }
    // the largest mesh allowed, on a problem too large for it: refused
    // before the workspace is allocated
    let problem = Counts {
        dim: 13,
        parameters: 0,
        boundary: 13,
        integral: 0,
        value: 0.0,
    };
    let solver = Collocation::new().points(7).intervals(Mesh::MAX_INTERVALS);
    let what = || "13 ODEs on 10⁶ intervals, m = 7".to_string();
    if let Some(res) = r.call(what, || solver.solve(&problem, |_s: f64| [0.0; 13], &[])) {
        r.check(matches!(res, Err(Error::SystemTooLarge { .. })), || {
            format!("{}: {res:?}", what())
        });
    }
}
