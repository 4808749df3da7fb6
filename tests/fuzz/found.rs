//! Bugs the fuzz suite found after its first version (issue 10), each with
//! the call that showed it (fixed in src/, see /work/notes/fuzz10.md).

use hockle::spring::{ElasticaModel, Model, Spring};
use hockle::{Error, Stiffness, Target};

/// Found by `spring_entries`: the scaffold of a spring of 4 069 355 578
/// coils searched the fold of every secondary branch j = n − 1, …, 1 (hours,
/// and n branches of `samples` points each); now refused at once, above 221
/// coils (the long run then found that n = 1000 failed in the elastica's
/// fold search, which needs n/j < 222).
#[test]
fn scaffold_of_too_many_coils_is_refused() {
    let s = Stiffness::nikolai(10.0, 0.05).unwrap();
    for n in [
        ElasticaModel::MAX_SCAFFOLD_COILS + 1,
        4_069_355_578,
        u32::MAX,
    ] {
        let spring = Spring::from_degrees(n, 30.0, s).unwrap();
        let res = ElasticaModel::default().scaffold(&spring, 3.0);
        assert!(
            matches!(res, Err(Error::InvalidCount { name: "coils", .. })),
            "n = {n}: {res:?}"
        );
    }
    // 10⁶ samples on each of 200 branches: more than error::MAX_POINTS points
    let spring = Spring::from_degrees(200, 30.0, s).unwrap();
    let res = ElasticaModel::new(1_000_000)
        .unwrap()
        .scaffold(&spring, 3.0);
    assert!(matches!(res, Err(Error::InvalidCount { .. })), "{res:?}");
}

/// Found by `spring_entries`: `ElasticaModel::pull_to(Target::Extension(dz))`
/// found the υ elastica of extension dz by bisection in k, which stops at
/// k = 1 − 2⁻⁵³; for dz beyond the extension there it answered "reached"
/// with a last point far short of dz (Δz = 0.8970 for dz = 1 − 2⁻⁵³ at
/// n = 1 828 996 208; 0.8987 for dz = 0.9 at n = 50). Now the bisection is
/// in q = −ln m₁ up to m₁ = e^−690 (the trace's reach): the last point is
/// on dz, or the target is `UnreachableTarget`.
#[test]
fn elastica_extension_target_is_met_or_refused() {
    let s = Stiffness::nikolai(100.0, 0.05).unwrap();
    for (n, dz) in [(4, 0.9), (50, 0.9), (50, 0.97), (1, 0.95)] {
        let spring = Spring::from_degrees(n, 90.0, s).unwrap();
        let resp = ElasticaModel::default()
            .pull_to(&spring, Target::Extension(dz))
            .unwrap();
        let last = resp.curve().points().last().unwrap().extension;
        // the trace meets its force limit to 1e-9 relative; Δz varies
        // with F far more slowly than F there (dΔz/dF · F ≪ 1)
        assert!(
            resp.reached_target() && (last - dz).abs() < 1e-8,
            "n = {n}, dz = {dz}: {last}"
        );
    }
    let spring = Spring::from_degrees(50, 90.0, s).unwrap();
    let res = ElasticaModel::default().pull_to(&spring, Target::Extension(1.0 - 1e-16));
    assert!(
        matches!(res, Err(Error::UnreachableTarget { .. })),
        "{res:?}"
    );
}

/// Found by `rod_entries`: a force target f whose physical value
/// f·(2πn)²B overflows passed `Pull::check` and then failed in `run` with
/// "stop_at = inf is not allowed", a setting the user never gave. Now
/// `check` (and so `run`, `start`, `RodModel`) refuses it as
/// `UnreachableTarget`.
#[test]
fn force_target_beyond_the_double_range_is_unreachable() {
    use hockle::rod::{Pull, Rod};
    let rod = Rod::new(
        8,
        89.8_f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    for f in [f64::MAX, -f64::MAX, 1e306] {
        let pull = Pull::new(rod, Target::Force(f)).intervals(8).max_steps(5);
        assert!(
            matches!(pull.check(), Err(Error::UnreachableTarget { .. })),
            "f = {f:e}: {:?}",
            pull.check()
        );
        assert!(matches!(pull.run(()), Err(Error::UnreachableTarget { .. })));
    }
    // the largest representable one is still a target (not run here)
    let f = 1e300;
    assert!(Pull::new(rod, Target::Force(f)).check().is_ok());
}

/// Found by the long run (`helix_entries`, 30× budget, at main 3a870ea):
/// `Helix::curve_to` for a stiffness B whose force scale (2πn)²B overflows
/// (B = f64::MAX, or n = 2³² − 1 with B = 1e290) failed with
/// "bending stiffness B is not allowed" from the curve's `ForceScale`,
/// although `Helix::new` accepted B (the helix's closed forms are scaled);
/// now `Error::Overflow` naming B, as the helix documents for values beyond
/// the largest double.
#[test]
fn helix_curve_whose_force_scale_overflows_is_overflow() {
    use hockle::helix::Helix;
    for (n, b) in [(221, f64::MAX), (u32::MAX, 1e290)] {
        let h = Helix::new(n, 1.0, Stiffness::new(1.0, b, 1.0).unwrap()).unwrap();
        let res = h.curve_to(5, 0.9);
        assert!(
            matches!(res, Err(Error::Overflow { name: "B", .. })),
            "n = {n}, B = {b:e}: {res:?}"
        );
    }
}

/// Found by the long run (`rod_entries`): a rod whose force scale
/// (2πn)²B is beyond 1e154 or below 1e-154 passed `Pull::check` and failed
/// in `run` with "parameter_weight = 0" or "weight = inf" (the pull's norm
/// weighs forces by 1/((2πn)²B)²), settings the user never gave. Now
/// `check` refuses it naming B.
#[test]
fn pull_refuses_a_force_scale_its_norm_cannot_square() {
    use hockle::rod::{Pull, Rod};
    for b in [1e160, 1e-160] {
        let rod = Rod::new(4, 1.0, Stiffness::new(1.0, b, 1.0).unwrap()).unwrap();
        let pull = Pull::new(rod, Target::Force(0.5)).intervals(8).max_steps(5);
        let res = pull.run(());
        assert!(
            matches!(
                res,
                Err(Error::InvalidArgument {
                    name: "bending stiffness B",
                    ..
                })
            ),
            "B = {b:e}: {res:?}"
        );
    }
}

use hockle::nalgebra::DMatrixViewMut;

/// y′ = 0, y(0) = λ: the solution is y ≡ λ, so two solutions at λ = a and
/// λ = b are |a − b| apart in y and in λ, and their distance in a norm with
/// weight 1 and parameter weight θ is |a − b| √(1 + θ).
struct Constant;

impl hockle::bvp::Problem for Constant {
    fn dim(&self) -> usize {
        1
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        1
    }
    fn rhs(&self, _s: f64, _y: &[f64], _p: &[f64], f: &mut [f64]) {
        f[0] = 0.0;
    }
    fn rhs_jacobian(
        &self,
        _s: f64,
        _y: &[f64],
        _p: &[f64],
        _dfdy: DMatrixViewMut<'_, f64>,
        _dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        // both zero (the solver zeroes them): differences of y = 1e300
        // would overflow
        true
    }
    fn boundary(&self, y0: &[f64], _y1: &[f64], p: &[f64], g: &mut [f64]) {
        g[0] = y0[0] - p[0];
    }
    fn boundary_jacobian(
        &self,
        _y0: &[f64],
        _y1: &[f64],
        _p: &[f64],
        mut dg0: DMatrixViewMut<'_, f64>,
        _dg1: DMatrixViewMut<'_, f64>,
        mut dgp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        dg0[(0, 0)] = 1.0;
        dgp[(0, 0)] = -1.0;
        true
    }
}

/// Found by the long run (`continuation_entries`): `Continuation::distance`
/// of two finite solutions returned `Ok(∞)` when their difference was
/// beyond ~1e154 (the squared norm overflowed; the run had reached them
/// after steps of Δs ≈ 1e194), and 0 for differences below ~1e-162 (the
/// squares underflowed). Now the sum is scaled: exact to rounding at every
/// size, and `Error::Overflow` only where the distance itself is beyond
/// the largest double.
#[test]
fn continuation_distance_is_scaled() {
    use hockle::bvp::Collocation;
    use hockle::continuation::Continuation;
    let solve = |l: f64| {
        // the guess is the solution: no Newton step changes it
        Collocation::new()
            .intervals(4)
            .solve(&Constant, move |_s: f64| [l], &[l])
            .expect("y ≡ λ")
    };
    let theta = 3.0;
    let cont = Continuation::new(0).parameter_weight(theta);
    for (a, b) in [
        (1.0, -1.0),
        (1e200, -1e200),
        (1e300, 3e300),
        (0.25 * f64::MAX, -0.2 * f64::MAX),
        (1e-200, -1e-200),
        (1e-320, 0.0),
    ] {
        let d = cont.distance(&solve(a), &solve(b)).unwrap();
        let exact = (a - b).abs() * (1.0 + theta).sqrt();
        // a sum of 4 × 4 equal terms and a square root: a few ulps, 1e-14
        // relative (the subnormal difference is exact to its 2⁻¹⁰⁷⁴ grain)
        assert!(
            (d - exact).abs() <= 1e-14 * exact + 1e-323,
            "a = {a:e}, b = {b:e}: {d:e} vs {exact:e}"
        );
    }
    // a difference beyond the largest double, a distance below it: weight
    // 0 on y, θ = 1/4 on λ, so the distance is |a − b|/2
    let half = Continuation::new(0).weights(&[0.0]).parameter_weight(0.25);
    let d = half
        .distance(&solve(f64::MAX), &solve(-0.5 * f64::MAX))
        .unwrap();
    // one exact halving, one square root of an exact square: 1e-15
    assert!((d / (0.75 * f64::MAX) - 1.0).abs() < 1e-15, "{d:e}");
    // the distance itself beyond the largest double
    let res = cont.distance(&solve(f64::MAX), &solve(-f64::MAX));
    assert!(matches!(res, Err(Error::Overflow { .. })), "{res:?}");
}

/// A helix-model pull to a force target: `Ok` only if it reached the
/// target with its last point on it to `HelixModel::FORCE_ACCURACY`,
/// otherwise the model's typed refusal; `true` if it was met.
fn helix_force_met_or_refused(spring: &Spring, f: f64) -> bool {
    use hockle::spring::HelixModel;
    let res = HelixModel::new(20)
        .unwrap()
        .pull_to(spring, Target::Force(f));
    match res {
        Ok(resp) => {
            let c = resp.curve();
            let last = c.force_scaled(c.len() - 1).unwrap();
            assert!(
                resp.reached_target()
                    && (last - f).abs() <= HelixModel::FORCE_ACCURACY * f.max(1.0)
                    && c.points().iter().all(|p| p.extension.abs() <= 1.0),
                "{spring}, f = {f:e}: reached = {}, last F/((2πn)²B) = {last:e}",
                resp.reached_target()
            );
            true
        }
        Err(Error::OutsideModel { model: "helix", .. }) => false,
        Err(e) => panic!("{spring}, f = {f:e}: {e}"),
    }
}

/// Found by `spring_entries`: `HelixModel::pull_to` on a spring with
/// θ0 < 1e-7 rad failed with `InvalidArgument { name: "theta" }`, a name
/// the user never gave (cos θ0 rounds to 1, and the curve, sampled
/// uniformly in Δz = cos θ, asked for θ = acos(1) = 0). Now sampled in
/// w = 1 − Δz = 2 sin²(θ/2): the pull is answered.
#[test]
fn helix_model_of_an_almost_straight_spring() {
    let s = Stiffness::nikolai(10.0, 0.05).unwrap();
    for th in [1e-8, 1e-12, 1e-100, 1e-300] {
        let spring = Spring::new(4, th, s).unwrap();
        for f in [1e-9, 1e-3, 0.5, 3.0] {
            assert!(helix_force_met_or_refused(&spring, f), "θ0 = {th:e}");
        }
    }
    // the helix angle at f ≈ θ0/(1 + f) is subnormal: refused
    let spring = Spring::new(4, 1e-320, s).unwrap();
    assert!(!helix_force_met_or_refused(&spring, 0.5));
}

/// Found by `spring_entries` and the long run (seed 1006):
/// `HelixModel::pull_to(Target::Force(f))` said "reached" with a last
/// point off the target where the force has fewer than 53 bits: the helix
/// angle at f subnormal (f ≳ 1e300 at small θ0), or the physical force
/// (2πn)²B·f subnormal (B ≲ 1e-300; 3.7e-6 off at θ0 = 89.99977°, n = 1).
/// Now the target is met to `FORCE_ACCURACY` or refused as `OutsideModel`.
#[test]
fn helix_model_meets_a_force_or_says_it_cannot() {
    // subnormal physical forces (2πn)²B·f: met while their grain allows
    let th = 89.99977_f64.to_radians();
    for (b, met) in [(1e-300, Some(true)), (1e-310, None), (1e-318, Some(false))] {
        let s = Stiffness::new(1e-3 * b, b, b).unwrap();
        let spring = Spring::new(1, th, s).unwrap();
        let got = helix_force_met_or_refused(&spring, 3.0);
        assert!(met.is_none_or(|m| m == got), "B = {b:e}: {got}");
    }
    let paper = Stiffness::nikolai(10.0, 0.05).unwrap();
    // the helix angle at f is ≈ sin θ0 cos θ0/f: normal, met
    for (th, f) in [(1.0, 1e300), (1e-5, 1e290), (89.8_f64.to_radians(), 1e300)] {
        let spring = Spring::new(4, th, paper).unwrap();
        assert!(
            helix_force_met_or_refused(&spring, f),
            "θ0 = {th}, f = {f:e}"
        );
    }
    // subnormal: refused
    for (th, f) in [(1e-15, 1e305), (1e-18, 1e300), (1e-30, 1e290)] {
        let spring = Spring::new(4, th, paper).unwrap();
        assert!(
            !helix_force_met_or_refused(&spring, f),
            "θ0 = {th}, f = {f:e}"
        );
    }
    // a physical force beyond the largest double is an unreachable target
    let spring = Spring::new(4, 1.0, Stiffness::new(1e300, 1e300, 1e300).unwrap()).unwrap();
    let res = hockle::spring::HelixModel::default().pull_to(&spring, Target::Force(1e300));
    assert!(
        matches!(res, Err(Error::UnreachableTarget { .. })),
        "{res:?}"
    );
}

/// Found by the long run (`continuation_entries`, seed 1004): a run on
/// Bratu with stops [4, 5e-324], a location tolerance of 1 in arclength
/// (valid: finite, > 0) and two Newton iterations ended with
/// `ParameterValue(0.0239…)`, a value it was not asked to stop at: the stop
/// was located only to the arclength tolerance, and when the Newton solve
/// with λ fixed at the stop failed, the located point was kept as the stop
/// (a fallback meant for a stop at a fold). Now a located stop is on its
/// value, or the run fails with the typed Newton error (points kept).
#[test]
fn a_stop_that_cannot_be_pinned_is_a_failure() {
    use hockle::bvp::Solution;
    use hockle::bvp::classic::Bratu;
    use hockle::continuation::{Continuation, PointKind, Termination};
    let start = crate::continuation::bratu_start();
    let stops = [4.0, 5e-324];
    let mut cont = Continuation::new(0)
        .step(0.1)
        .step_bounds(1e-8, core::f64::consts::FRAC_PI_2)
        .parameter_weight(1.0)
        .max_angle(0.35)
        .locate_tolerance(0.999_999_999_158_882_7)
        .max_newton(2)
        .max_steps(1);
    for v in stops {
        cont = cont.stop_at(v);
    }
    for (i, level) in [2.953_994_530_000_934_5, -4.358_893_596_804_443_5e-212]
        .into_iter()
        .enumerate()
    {
        cont = cont.stop_when(move |sol: &Solution| sol.at_mesh(0)[1] - level - i as f64);
    }
    let run = cont.run(&Bratu::default(), &start, ()).unwrap();
    let last = run.points().last().unwrap();
    match run.termination() {
        Termination::ParameterValue(v) => assert!(
            stops.contains(v) && last.kind() == PointKind::ParameterValue && last.parameter() == *v,
            "ParameterValue({v}) with the last point at λ = {}",
            last.parameter()
        ),
        Termination::Failed { error, .. } => assert!(
            matches!(
                error,
                Error::NewtonNotConverged { .. } | Error::NewtonDiverged { .. }
            ),
            "{error}"
        ),
        t => panic!("{t:?}"),
    }
}

/// Reported by the long run before the tolerance engine (`rod_entries`,
/// seed 1005): pulls on coarse fixed meshes returned `Ok` curves with
/// |Δz| = 2.4 and 6.3, which no inextensible rod of unit length has. With
/// the tolerance engine the same draws end in typed errors, and fixed
/// meshes of 2–4 intervals keep |Δz| ≤ 1; where such a pull "reaches" its
/// target far from the right answer, its error estimate says so. The
/// reference is the adaptive default pull (its own estimate ~1e-6, checked
/// against converged meshes in tests/rod/tolerance.rs); "far" is 0.01 in
/// Δz, 10⁴ times that.
#[test]
fn coarse_fixed_meshes_stay_rods_and_say_they_are_not_accurate() {
    use hockle::rod::{Pull, Rod};
    let rod = Rod::new(
        4,
        89.8_f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let target = Target::Force(100.0);
    let reference = Pull::new(rod, target).run(()).unwrap();
    assert!(reference.reached_target());
    let dz_ref = reference.curve().points().last().unwrap().extension;
    let mut far = 0;
    for intervals in 2..=4 {
        for m in [2, 3, 4] {
            let pull = Pull::new(rod, target).intervals(intervals).points(m);
            let run = match pull.run(()) {
                Ok(run) => run,
                // a typed solver error at the start is an answer too
                Err(Error::NewtonNotConverged { .. } | Error::NewtonDiverged { .. }) => continue,
                Err(e) => panic!("{intervals} intervals, m = {m}: {e}"),
            };
            let c = run.curve();
            assert!(
                c.points().iter().all(|p| p.extension.abs() <= 1.0),
                "{intervals} intervals, m = {m}: |Δz| > 1"
            );
            let end = c.points().last().unwrap().extension;
            if run.reached_target() && (end - dz_ref).abs() > 0.01 {
                far += 1;
                assert!(
                    run.estimate().curve() > run.tolerance(),
                    "{intervals} intervals, m = {m}: Δz = {end} vs {dz_ref}, estimate {}",
                    run.estimate()
                );
            }
        }
    }
    // the check is not empty: 2 intervals at m = 4 end at Δz ≈ 0.40
    assert!(far >= 1);
}

/// Found by the long run (`rod_entries`, seed 1005), still failing with
/// the tolerance engine: an almost straight rod (θ0 = 3.2e-23, A/B = 100)
/// pushed to Δz = −0.5 under extension control on a fixed mesh of 11
/// intervals with m = 2 returned `Ok` with points at Δz = 1.27, 2.42, 2.29
/// (no inextensible rod of unit length has |Δz| > 1; its estimate said
/// 5.1), and with more steps even "reached" −0.5 along that path. Then the
/// run ended `Failed` with `NotARod` at the first such point. Now its start
/// keeps the exact rest where re-solving it under extension control is
/// singular (a straight rod: ∂Δz/∂F = 0; that Newton converged or not
/// with the rounding), and the pull buckles the rod at its Euler load
/// (a fold at Δz = 0.99995) and goes on as a rod: whatever the path, no
/// kept point has |Δz| > 1, and a run that ends early says why in a type.
#[test]
fn a_straight_rod_pushed_on_a_coarse_mesh_stays_a_rod() {
    use hockle::continuation::Termination;
    use hockle::rod::{Pull, Rod};
    let s = Stiffness::new(100.0, 1.0, 1.885_902_876_001_885_9).unwrap();
    let rod = Rod::new(1, 3.171_855_365_100_386_6e-23, s).unwrap();
    for steps in [5, 50] {
        let run = Pull::new(rod, Target::Extension(-0.5))
            .intervals(11)
            .points(2)
            .max_steps(steps)
            .max_angle(0.3)
            .locate_folds(false)
            .run(())
            .unwrap();
        let c = run.curve();
        assert!(
            !c.is_empty() && c.points().iter().all(|p| p.extension.abs() <= 1.0),
            "steps {steps}: {c}"
        );
        assert!(
            matches!(
                run.termination(),
                Termination::MaxSteps(_)
                    | Termination::ParameterValue(_)
                    | Termination::Failed {
                        error: Error::NotARod { .. },
                        ..
                    }
            ),
            "steps {steps}: {}",
            run.termination()
        );
    }
}
