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
