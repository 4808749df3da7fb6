//! Two-parameter continuation of a fold: [`FoldContinuation`], its points
//! ([`FoldPoint`]) and their kinds, cusps among them.
//!
//! ## The formulation, and why
//!
//! The fold is continued as the solution of the *extended* boundary-value
//! problem (AUTO-07p's ISW = 2): the problem in y, its linearisation in a
//! null vector v with the solver's free parameters' variations δq, and the
//! normalisation ∫ v·v ds + δq·δq = 1, with λ (the fold parameter), q and δq
//! free; the run is an ordinary [`Continuation`] of that 2n-dimensional
//! problem in the second parameter μ.
//!
//! - Reuse: every piece of the engine (collocation, condensation, chord
//!   corrector, step control, stop values, events, typed termination)
//!   applies unchanged to the extended problem; the only new code is the
//!   extended problem and the turns of the curve.
//! - Robustness: the extended system is regular at a generic fold and stays
//!   regular through a cusp (there the curve of the extended problem is
//!   smooth; only its projection on the parameter plane has a cusp), so
//!   Newton keeps its quadratic rate and pseudo-arclength goes through
//!   cusps without special care.
//! - Cost: twice the dimension. The condensation's stage blocks are
//!   (2mn)², so one factorisation costs about 8 times the original
//!   problem's; the Jacobian of the v equations needs second derivatives of
//!   f, taken by central differences of the problem's analytic ∂f/∂y, ∂f/∂p
//!   (or, without them, by the solver's differences of the extended
//!   right-hand side, itself a directional difference). A minimally
//!   augmented system (the original n-dimensional system bordered by one
//!   row and column, the fold condition a scalar g = 0 from a bordered solve)
//!   would factorise n-dimensional blocks only, but needs g's derivatives
//!   (an adjoint solve and F_xx products per Newton step) and a corrector of
//!   its own. Measured (docs/PERFORMANCE.md): the Bratu fold curve costs
//!   about 4× a one-parameter step per interval, a fold of the rod (n = 13,
//!   N = 48) 6–7 ms per step, about 4× a step of the pull: affordable for
//!   curves of a few hundred steps,
//!   so the simpler, fully reused formulation was chosen.
//!
//! ## Turns and cusps
//!
//! Along the fold curve, parametrised by arclength s, the parameter plane
//! velocity (dλ/ds, dμ/ds) is tangent to the curve of folds. A zero of one
//! component where the other is not zero is a *turn* of the curve in that
//! parameter ([`FoldPointKind::Turn`]); a *cusp* ([`FoldPointKind::Cusp`]),
//! where two folds of the λ-family meet and vanish, is a common zero of
//! both: the curve's projection stops and reverses. Both are located by the
//! Illinois iteration on arclength (as folds are in a [`Continuation`]) on
//! the sign change of dλ/ds (then of dμ/ds) within a step; a located zero
//! where the other rate is below √(locate tolerance) in the unit tangent,
//! or below a tenth of its larger value at the step's two ends, is a cusp
//! (at a generic cusp both rates are O(distance), so at the located point
//! they are O(tolerance) while the step's ends are a step away; a turn
//! keeps the other rate near its largest). The second test makes the
//! classification independent of the norm's weights: on the rod, whose
//! solution changes fast with θ0, dθ0/ds is below √(tolerance) in the unit
//! tangent along whole stretches of a fold curve.

use super::corrector::Corrected;
use super::fold_extended::Extended;
use super::fold_point::{FoldCurve, FoldObserver, FoldPoint, FoldPointKind};
use super::locate::Watch;
use super::steps::start_fits;
use super::{Continuation, PointKind, Steps, Termination};
use crate::bvp::system::{State, System};
use crate::bvp::{
    Mesh, NewtonOptions, Problem, ROUNDOFF_STALL, Solution, finish, newton, state_on_mesh,
};
use crate::error::{Error, Result};

/// Two-parameter continuation of a fold (the builder; module docs).
///
/// ```
/// use hockle::bvp::Collocation;
/// use hockle::bvp::classic::BratuLength;
/// use hockle::continuation::{Continuation, FoldContinuation};
/// // Bratu on [0, L]: fold at λ*(L) = λ*(1)/L².
/// let p = BratuLength::default();
/// let solver = Collocation::new().intervals(10);
/// let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0, 1.0])?;
/// let run = Continuation::new(0).solver(solver.clone()).step(0.1).max_steps(60).run(&p, &start, ())?;
/// let fold = run.folds().next().expect("a fold");
/// // Continue the fold in L (p[1]) up to L = 2.
/// let curve = FoldContinuation::new(0, Continuation::new(1).solver(solver).step(0.1).stop_at(2.0))
///     .run(&p, fold.solution(), ())?;
/// let end = curve.last().unwrap();
/// assert!((end.fold_parameter() - 3.513830719125162 / 4.0).abs() < 1e-8);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct FoldContinuation {
    fold: usize,
    settings: Continuation,
    cusps: bool,
}

impl FoldContinuation {
    /// Continues a fold in the parameter `fold` (λ) along the second
    /// parameter of `settings` (μ = `settings`' continuation parameter).
    /// Every setting of `settings` applies to the extended problem, with:
    /// its weights (length n) used for both y and v; λ and δq added to the
    /// solver's free parameters; fold and branch-point detection replaced
    /// by the turns and cusps of the module docs; stop values in μ; events
    /// evaluated on the extended solution ([`FoldPoint::extended`]).
    #[must_use]
    pub fn new(fold: usize, settings: Continuation) -> Self {
        FoldContinuation {
            fold,
            settings,
            cusps: true,
        }
    }

    /// Detect and locate turns and cusps (default on).
    #[must_use]
    pub fn detect_cusps(mut self, on: bool) -> Self {
        self.cusps = on;
        self
    }

    /// Runs from `start`, a solution at (or near) a fold in λ (for instance
    /// a located [`PointKind::Fold`] of a [`Continuation`] run in λ): the
    /// null vector there is found by one solve with the nearly singular
    /// Jacobian, the extended problem is corrected by Newton, and the curve
    /// is continued until the settings' termination.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `fold` is not a parameter index, equals
    /// μ, or is one of the solver's free parameters; bad settings as
    /// [`Continuation::steps`] (checked before the problem is called);
    /// [`Error::LengthMismatch`] / [`Error::InvalidCount`] for a start of
    /// another dimension or m; [`Error::SingularJacobian`] if the start is
    /// exactly singular; a Newton error if the start is not near a fold.
    /// Failures after the start end the run with [`Termination::Failed`].
    pub fn run<P: Problem + ?Sized, O: FoldObserver>(
        &self,
        problem: &P,
        start: &Solution,
        mut observer: O,
    ) -> Result<FoldCurve> {
        let cont = &self.settings;
        let n = problem.dim();
        let ExtendedStart {
            mut sys,
            ext,
            ext_free,
            ext_start,
        } = self.start_on(problem, start, start.mesh())?;
        let weights = cont.weights.clone().unwrap_or_else(|| vec![1.0; n]);
        let weights: Vec<f64> = weights.iter().chain(&weights).copied().collect();
        let ext_cont = cont
            .clone()
            .solver(cont.solver.clone().free_parameters(&ext_free))
            .weights(&weights)
            .detect_folds(false)
            .detect_branch_points(false);
        let mut steps = ext_cont.steps(&ext, &ext_start)?;
        let mut points = Vec::new();
        let mut failure = None;
        let mut stopped = false;
        let mut previous: Option<(f64, f64, f64)> = None;
        while let Some(p) = steps.next() {
            steps.rejections.clear();
            let mut batch = Vec::new();
            let regular = matches!(p.kind(), PointKind::Start | PointKind::Regular);
            let velocity = regular.then(|| (steps.t0.p[self.fold], p.dparameter_ds()));
            if let (Some((s0, l0, m0)), Some((l1, m1)), true) = (previous, velocity, self.cusps) {
                match self.turns(&mut steps, p.arclength() - s0, (l0, m0), (l1, m1)) {
                    Ok(found) => {
                        for (c, s, kind) in found {
                            let at = p.arclength() + s;
                            let vel = (c.tangent.p[self.fold], c.tangent.p[cont.parameter]);
                            match steps.solution(&c.x, Default::default()) {
                                Ok(e) => batch.push((e, at, Some(vel), kind)),
                                Err(e) => failure = Some(e),
                            }
                        }
                    }
                    Err(e) => failure = Some(e),
                }
            }
            if let Some((l1, m1)) = velocity {
                previous = Some((p.arclength(), l1, m1));
            }
            let kind = match p.kind() {
                PointKind::Start => FoldPointKind::Start,
                PointKind::ParameterValue => FoldPointKind::ParameterValue,
                PointKind::Event(i) => FoldPointKind::Event(i),
                _ => FoldPointKind::Regular,
            };
            batch.push((p.solution().clone(), p.arclength(), velocity, kind));
            for (e, arclength, velocity, kind) in batch {
                let solution = match restrict(&mut sys, &e) {
                    Ok(s) => s,
                    Err(err) => {
                        failure = Some(err);
                        break;
                    }
                };
                let fp = FoldPoint {
                    solution,
                    extended: e,
                    fold: self.fold,
                    second: cont.parameter,
                    arclength,
                    velocity,
                    kind,
                    mesh_change: None,
                };
                let mut flow = observer.point(&fp);
                if flow.is_continue() && kind == FoldPointKind::Cusp {
                    flow = observer.cusp(&fp);
                }
                points.push(fp);
                if flow.is_break() {
                    stopped = true;
                    break;
                }
            }
            if stopped || failure.is_some() {
                break;
            }
        }
        let termination = match (failure, stopped) {
            (Some(error), _) => Termination::Failed {
                ds: steps.step_size(),
                error,
            },
            (None, true) => Termination::Stopped,
            (None, false) => steps
                .termination
                .take()
                .unwrap_or(Termination::MaxSteps(steps.accepted())),
        };
        observer.finish(&termination);
        Ok(FoldCurve {
            points,
            termination,
            accepted: steps.accepted(),
            rejected: steps.rejected(),
            newton_iterations: steps.newton_iterations(),
        })
    }

    /// The fold near `start` located on `mesh` (another mesh than the
    /// start's: a finer one to check how far the fold moves with the
    /// discretisation): the fold located on the start's own mesh, exactly
    /// as the first point of [`run`](Self::run) (the null vector there, and
    /// the extended problem of the module docs corrected by Newton with λ,
    /// the free parameters and δq unknown and μ fixed), then carried onto
    /// `mesh` through its collocation polynomial, null vector and all, and
    /// corrected there. (A null vector sought on the new mesh directly,
    /// where the fold has moved, can pick another small mode: measured on
    /// the rod at F/((2πn)²B) ≈ 4.7, whose loops slide at almost no cost,
    /// Newton then failed from 52 intervals on.) The point's kind is
    /// [`FoldPointKind::Start`], its arclength 0, its velocity `None`.
    ///
    /// ```
    /// use hockle::bvp::{Collocation, Mesh};
    /// use hockle::bvp::classic::BratuLength;
    /// use hockle::continuation::{Continuation, FoldContinuation};
    /// let p = BratuLength::default();
    /// let solver = Collocation::new().intervals(4).points(3);
    /// let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0, 1.0])?;
    /// let run = Continuation::new(0).solver(solver.clone()).step(0.1).max_steps(60).run(&p, &start, ())?;
    /// let fold = run.folds().next().expect("a fold");
    /// let fine = FoldContinuation::new(0, Continuation::new(1).solver(solver))
    ///     .locate_on(&p, fold.solution(), &Mesh::uniform(32)?)?;
    /// // λ*(1) = 3.513830719125162 (closed form); 2.9e-5 off on 4 intervals, 1.1e-10 on 32
    /// let (coarse, fine) = (fold.solution().parameters()[0], fine.fold_parameter());
    /// assert!((fine - 3.513830719125162).abs() < 1e-9);
    /// assert!((fine - 3.513830719125162).abs() < (coarse - 3.513830719125162).abs());
    /// # Ok::<(), hockle::Error>(())
    /// ```
    ///
    /// # Errors
    /// As the start of [`run`](Self::run).
    pub fn locate_on<P: Problem + ?Sized>(
        &self,
        problem: &P,
        start: &Solution,
        mesh: &Mesh,
    ) -> Result<FoldPoint> {
        let ExtendedStart {
            mut sys, ext_start, ..
        } = self.start_on(problem, start, mesh)?;
        Ok(FoldPoint {
            solution: restrict(&mut sys, &ext_start)?,
            extended: ext_start,
            fold: self.fold,
            second: self.settings.parameter,
            arclength: 0.0,
            velocity: None,
            kind: FoldPointKind::Start,
            mesh_change: None,
        })
    }

    /// Checks `start`, corrects the extended problem from it on its own
    /// mesh and, if `mesh` is another, carries that onto `mesh` and
    /// corrects it again there.
    fn start_on<'a, P: Problem + ?Sized>(
        &self,
        problem: &'a P,
        start: &Solution,
        mesh: &Mesh,
    ) -> Result<ExtendedStart<'a, P>> {
        let (n, np) = (problem.dim(), problem.parameter_count());
        let cont = &self.settings;
        cont.validate(n, np)?;
        let free = cont.solver.free().to_vec();
        if self.fold >= np || self.fold == cont.parameter || free.contains(&self.fold) {
            return Err(Error::InvalidCount {
                name: "fold parameter",
                value: self.fold as u64,
                allowed: "a parameter index below parameter_count(), not the continuation parameter, not a free parameter of the solver",
            });
        }
        if free.contains(&cont.parameter) {
            return Err(Error::InvalidCount {
                name: "continuation parameter",
                value: cont.parameter as u64,
                allowed: "a parameter that is not already one of the solver's free parameters",
            });
        }
        let tab = cont.solver.validate()?;
        start_fits(start, n, np, tab.m)?;
        let on = |mesh: &Mesh| -> Result<System<'a, P>> {
            let mut sys = System::new(
                problem,
                mesh.points().to_vec(),
                tab.clone(),
                free.clone(),
                0,
            )?;
            sys.linear = cont.solver.linear();
            Ok(sys)
        };
        let mut sys = on(start.mesh())?;
        let x = State {
            y: start.y.clone(),
            k: start.k.clone(),
            p: start.p.clone(),
        };
        let v = null_vector(&mut sys, &x)?;
        let ext = Extended {
            problem,
            free: free.clone(),
        };
        let mut ext_free = free.clone();
        ext_free.push(self.fold);
        ext_free.extend(np..np + free.len());
        let ext_start = extended_start(&ext, &sys, &x, &v, &ext_free, cont, start.mesh(), mesh)?;
        if mesh != start.mesh() {
            sys = on(mesh)?;
        }
        Ok(ExtendedStart {
            sys,
            ext,
            ext_free,
            ext_start,
        })
    }

    /// The turns and cusps in the step of arclength `ds` that ended at the
    /// current point, given (dλ/ds, dμ/ds) at its ends; arclengths relative
    /// to the current point (≤ 0).
    fn turns<P: Problem + ?Sized>(
        &self,
        steps: &mut Steps<'_, P>,
        ds: f64,
        (l0, m0): (f64, f64),
        (l1, m1): (f64, f64),
    ) -> Result<Vec<(Corrected, f64, FoldPointKind)>> {
        let mu = self.settings.parameter;
        let small = self.settings.locate_tolerance.sqrt();
        // A cusp: the other rate is at the tolerance's level in the unit
        // tangent, or small against its values at the step's ends (the
        // rates' sizes depend on the norm's weights; at a turn the other
        // rate is near its largest, at a cusp it vanishes with the first).
        let vanishes = |r: f64, ends: (f64, f64)| {
            r.abs() <= small || r.abs() <= CUSP_RATIO * ends.0.abs().max(ends.1.abs())
        };
        let mut found = Vec::new();
        if l0 * l1 < 0.0 {
            let (c, s) = steps.locate(Watch::Tangent(self.fold), (-ds, l0), (0.0, l1), 0.0)?;
            let kind = if vanishes(c.tangent.p[mu], (m0, m1)) {
                FoldPointKind::Cusp
            } else {
                FoldPointKind::Turn(self.fold)
            };
            found.push((c, s, kind));
        }
        let cusp = found.iter().any(|f| f.2 == FoldPointKind::Cusp);
        if m0 * m1 < 0.0 && !cusp {
            let (c, s) = steps.locate(Watch::Tangent(mu), (-ds, m0), (0.0, m1), 0.0)?;
            let kind = if vanishes(c.tangent.p[self.fold], (l0, l1)) {
                FoldPointKind::Cusp
            } else {
                FoldPointKind::Turn(mu)
            };
            found.push((c, s, kind));
        }
        // Both rates changed sign in one step and the curve's direction in
        // the plane reversed: one cusp whose two zeros the location found
        // a short arclength apart (the discretisation's error), reported
        // once, at the zero of dμ/ds (where μ turns back).
        let reversed = l0 * l1 + m0 * m1 < -REVERSED * l0.hypot(m0) * l1.hypot(m1);
        if found.len() == 2 && reversed {
            found.retain(|f| f.2 != FoldPointKind::Turn(self.fold));
            if let Some(f) = found.first_mut() {
                f.2 = FoldPointKind::Cusp;
            }
        }
        found.sort_by(|a, b| a.1.total_cmp(&b.1));
        Ok(found)
    }
}

/// The start of a fold curve ([`FoldContinuation::start_on`]).
struct ExtendedStart<'a, P: Problem + ?Sized> {
    /// The problem's own system on the mesh of the corrected start.
    sys: System<'a, P>,
    /// The extended problem (module docs).
    ext: Extended<'a, P>,
    /// Its free parameters: the solver's, λ, and the δq.
    ext_free: Vec<usize>,
    /// Its solution at the start, corrected.
    ext_start: Solution,
}

/// The cosine below which the plane direction (dλ/ds, dμ/ds) at a step's
/// two ends counts as reversed (a turn of more than 154°).
const REVERSED: f64 = 0.9;

/// At a located zero of one rate, the other rate below this fraction of
/// its larger value at the step's ends marks a cusp (module docs).
const CUSP_RATIO: f64 = 0.1;

/// The null vector (v, δq) of the collocation Jacobian at `x` (λ fixed):
/// one solve with the nearly singular factorisation, scaled to
/// ∫ v·v ds + δq·δq = 1 (Gauss rule of the collocation).
fn null_vector<P: Problem + ?Sized>(sys: &mut System<'_, P>, x: &State) -> Result<State> {
    let mut y_ref = std::mem::take(&mut sys.y_ref);
    sys.collocation_values(x, &mut y_ref);
    sys.y_ref = y_ref;
    sys.factor(x)?;
    let mut r = sys.zero_residual();
    for (i, v) in r
        .stage
        .iter_mut()
        .chain(r.cont.iter_mut())
        .chain(r.bc.iter_mut())
        .chain(r.dense.iter_mut())
        .enumerate()
    {
        *v = 1.0 + 0.5 * (i as f64).sin();
    }
    let mut v = sys.zero_state();
    sys.solve(&r, &mut v)?;
    let mut values = vec![0.0; sys.y_ref.len()];
    sys.collocation_values(&v, &mut values);
    let (n, m) = (sys.n, sys.m);
    let mut sq = 0.0;
    for j in 0..sys.nn {
        for k in 0..m {
            let w = sys.h(j) * sys.tab.b[k];
            let o = (j * m + k) * n;
            sq += w * values[o..o + n].iter().map(|a| a * a).sum::<f64>();
        }
    }
    sq += sys.free.iter().map(|&q| v.p[q] * v.p[q]).sum::<f64>();
    if !(sq.is_finite() && sq > 0.0) {
        return Err(Error::NonFinite {
            what: "fold null vector",
            s: f64::NAN,
        });
    }
    v.scale(1.0 / sq.sqrt());
    Ok(v)
}

/// The extended start: (y, v) interleaved per mesh point and stage, (p, δq),
/// corrected by Newton with λ, q and δq free and μ fixed, on the mesh of
/// `sys`, then (if `to` is another mesh) carried onto `to` through its
/// collocation polynomial and corrected there.
#[allow(clippy::too_many_arguments)]
fn extended_start<P: Problem + ?Sized>(
    ext: &Extended<'_, P>,
    sys: &System<'_, P>,
    x: &State,
    v: &State,
    ext_free: &[usize],
    cont: &Continuation,
    mesh: &crate::bvp::Mesh,
    to: &crate::bvp::Mesh,
) -> Result<Solution> {
    let n = sys.n;
    let interleave = |a: &[f64], b: &[f64]| -> Vec<f64> {
        a.chunks(n)
            .zip(b.chunks(n))
            .flat_map(|(u, w)| u.iter().chain(w).copied())
            .collect()
    };
    let mut p = x.p.clone();
    p.extend(sys.free.iter().map(|&q| v.p[q]));
    let mut xe = State {
        y: interleave(&x.y, &v.y),
        k: interleave(&x.k, &v.k),
        p,
    };
    let mut stats = correct_extended(ext, &sys.t, sys, &mut xe, ext_free, cont)?;
    if to != mesh {
        xe = state_on_mesh(&xe, mesh, &sys.tab, 2 * n, to);
        stats = correct_extended(ext, to.points(), sys, &mut xe, ext_free, cont)?;
    }
    let mut esys = System::new(
        ext,
        to.points().to_vec(),
        sys.tab.clone(),
        ext_free.to_vec(),
        0,
    )?;
    finish(&mut esys, xe, to.clone(), stats)
}

/// Newton on the extended problem on the mesh `t`, from `xe`.
fn correct_extended<P: Problem + ?Sized>(
    ext: &Extended<'_, P>,
    t: &[f64],
    sys: &System<'_, P>,
    xe: &mut State,
    ext_free: &[usize],
    cont: &Continuation,
) -> Result<crate::bvp::NewtonStats> {
    let mut esys = System::new(ext, t.to_vec(), sys.tab.clone(), ext_free.to_vec(), 0)?;
    esys.linear = cont.solver.linear();
    let mut y_ref = std::mem::take(&mut esys.y_ref);
    esys.collocation_values(xe, &mut y_ref);
    esys.y_ref = y_ref;
    let opts = NewtonOptions {
        stall: ROUNDOFF_STALL,
        ..cont.solver.newton_options()
    };
    newton(&mut esys, xe, opts, false)
}

/// `problem`'s solution (components 0..n, parameters 0..n_p) of a solution
/// `e` of its fold problem ([`super::FoldProblem`] with the solver's free
/// parameters `free`), on `e`'s mesh.
pub(crate) fn restricted<P: Problem + ?Sized>(
    problem: &P,
    free: &[usize],
    e: &Solution,
) -> Result<Solution> {
    let mut sys = System::new(
        problem,
        e.mesh.points().to_vec(),
        e.tab.clone(),
        free.to_vec(),
        0,
    )?;
    restrict(&mut sys, e)
}

/// The problem's solution (components 0..n, parameters 0..n_p) of an
/// extended solution.
fn restrict<P: Problem + ?Sized>(sys: &mut System<'_, P>, e: &Solution) -> Result<Solution> {
    let n = sys.n;
    let pick = |a: &[f64]| -> Vec<f64> { a.chunks(2 * n).flat_map(|c| c[..n].to_vec()).collect() };
    let x = State {
        y: pick(&e.y),
        k: pick(&e.k),
        p: e.p[..sys.np].to_vec(),
    };
    finish(sys, x, e.mesh.clone(), e.newton)
}
