//! Extreme and hostile input (issue 10): secondary folds far from the ring,
//! subnormal complementary parameters, forces beyond reach, huge counts.

use core::f64::consts::PI;

use hockle::Error;
use hockle::elastica::{Arm, Branch, Elastica, Trace, bifurcation, secondary_fold};
use hockle::error::MAX_POINTS;
use hockle::special::Modulus;

use crate::common::rel_err;

/// The end curvature is 2Ω dn(u) at u = u1 + Ω: rounding u (|u| ≈ Ω) moves
/// it by |u|ε·|d ln dn/du| ≤ Ωε relative (|d ln dn/du| = m|sn cd| ≤ 1 at the
/// ends, where dn ≥ k'), and the root t carries as much again; 4Ωε covers
/// both with the O(1) rounding of dn itself.
fn end_curvature_tol(e: &Elastica) -> f64 {
    4.0 * e.omega() * f64::EPSILON
}

fn assert_ends_on_the_ring_curvature(e: &Elastica) {
    let k0 = 2.0 * PI * f64::from(e.coils());
    for kappa in e.end_curvatures() {
        let err = rel_err(kappa, k0);
        assert!(
            err <= end_curvature_tol(e),
            "{e}: end curvature off by {err:e}"
        );
    }
}

/// Before: `secondary` and the fold search called each other without end
/// (a stack overflow, which aborts the process) when the fold was not found.
#[test]
fn secondary_far_below_its_fold_is_a_typed_error() {
    match Elastica::secondary(8, 273_537, 0.5) {
        Err(Error::BelowFold {
            n: 8,
            j: 273_537,
            k,
            fold,
        }) => {
            assert_eq!(k, 0.5);
            // k rounds to the same double at the fold and the bifurcation here
            assert!(fold > 0.5 && fold <= bifurcation(8, 273_537).unwrap().modulus());
        }
        other => panic!("{other:?}"),
    }
}

/// Folds of branches with j ≫ n, which were lost to rounding at the
/// bifurcation point (and then overflowed the stack): the fold solution
/// keeps the ring curvature at both ends, lies below the bifurcation point,
/// both arms exist just above it and neither just below it.
#[test]
fn folds_with_many_more_periods_than_coils() {
    for (n, j) in [
        (8, 36_960),
        (1, 100_000),
        (8, 273_537),
        (8, u32::MAX),
        (50, 2),
    ] {
        let f = secondary_fold(n, j).unwrap_or_else(|e| panic!("({n}, {j}): {e}"));
        let e = f.solution();
        assert_ends_on_the_ring_curvature(&e);
        let b = bifurcation(n, j).unwrap();
        assert!(f.modulus() <= b.modulus(), "({n}, {j})");
        let mc = e.elliptic_modulus().complement();
        // 1e-3 in m₁ is far above the bisection's resolution in ln m₁
        let above = Modulus::from_complement(mc * (1.0 - 1e-3)).unwrap();
        let below = Modulus::from_complement(mc * (1.0 + 1e-3)).unwrap();
        for arm in [Arm::Lower, Arm::Upper] {
            let a = Elastica::secondary_arm(n, j, arm, above)
                .unwrap_or_else(|e| panic!("({n}, {j}) {arm} above the fold: {e}"));
            assert_ends_on_the_ring_curvature(&a);
            assert!(matches!(
                Elastica::secondary_arm(n, j, arm, below),
                Err(Error::BelowFold { .. })
            ));
        }
    }
}

/// m₁ ≤ 1e-310: the α end equation multiplied two O(k′) numbers whose
/// product was subnormal (end curvature off by 8e-4 at m₁ = 5e-324).
#[test]
fn subnormal_complementary_parameters_keep_the_end_curvature() {
    for mc in [1e-300, 1e-308, 1e-310, 1e-315, 1e-320, 5e-324] {
        let modulus = Modulus::from_complement(mc).unwrap();
        for n in [1, 2, 3, 8, 50] {
            let s = Elastica::symmetric_with(n, modulus).unwrap();
            for e in [s.upsilon, s.alpha] {
                assert_ends_on_the_ring_curvature(&e);
                assert!(e.extension().is_finite() && e.force().is_finite(), "{e}");
            }
        }
    }
}

/// Before: a trace asked for F/(2πn)² = 1e5 returned Ok with a curve ending
/// at 1.2e4. Now the limit is reached exactly or refused with the reach.
#[test]
fn forces_beyond_the_branch_are_refused_with_its_reach() {
    for f in [1e5, 1e6, 1e300] {
        match Trace::new()
            .points(10)
            .max_force_scaled(f)
            .run(4, Branch::Upsilon)
        {
            Err(Error::ForceOutOfReach {
                requested,
                reachable,
            }) => {
                assert_eq!(requested, f);
                assert!(reachable > 1e4 && reachable < 1.3e4, "{reachable}");
            }
            other => panic!("{f}: {other:?}"),
        }
    }
    let Err(Error::ForceOutOfReach { reachable, .. }) = Trace::new()
        .points(10)
        .max_force_scaled(1e5)
        .run(4, Branch::Upsilon)
    else {
        unreachable!()
    };
    // just inside the reach the curve ends at the limit (bisection to 2^-60 in q)
    let target = 0.999 * reachable;
    let c = Trace::new()
        .points(10)
        .max_force_scaled(target)
        .run(4, Branch::Upsilon)
        .unwrap();
    assert!(rel_err(c.force_scaled(9).unwrap(), target) < 1e-9);
}

/// Before: `usize::MAX` points or samples overflowed the capacity (a panic)
/// or asked for terabytes (an abort).
#[test]
fn huge_counts_are_refused_before_any_work() {
    let e = Elastica::symmetric(4, 0.5).unwrap().upsilon;
    for count in [MAX_POINTS + 1, u32::MAX as usize, usize::MAX] {
        assert!(matches!(
            e.centreline(count),
            Err(Error::InvalidCount {
                name: "samples",
                ..
            })
        ));
        let t = Trace::new().points(count);
        assert!(matches!(
            t.run(4, Branch::Upsilon),
            Err(Error::InvalidCount { name: "points", .. })
        ));
        assert!(matches!(
            t.secondary(4, 3),
            Err(Error::InvalidCount { name: "points", .. })
        ));
    }
}

/// Before: the bisection stopped at 2⁻⁶⁰ in q and m = 1 − e^−q rounded to 0
/// below q ≈ 1e-16, so a limit of 1e-100 returned Ok with a last point at
/// F/(2πn)² ≈ 3e-17. Now every limit down to 1e-300 is met (to the trace's
/// 1e-9) and a limit below the double range of m is refused.
#[test]
fn tiny_force_limits_are_met_or_refused() {
    for limit in [1e-10, 1e-100, 1e-280, 1e-300] {
        for branch in [Branch::Upsilon, Branch::Alpha, Branch::Theta { j: 4 }] {
            let c = Trace::new()
                .points(10)
                .max_force_scaled(limit)
                .run(4, branch)
                .unwrap();
            let last = c.force_scaled(9).unwrap();
            assert!(
                rel_err(last, limit) < 1e-9,
                "{branch}: {last:e} for {limit:e}"
            );
        }
    }
    assert!(matches!(
        Trace::new()
            .points(10)
            .max_force_scaled(1e-320)
            .run(4, Branch::Upsilon),
        Err(Error::InvalidArgument {
            name: "max_force_scaled",
            ..
        })
    ));
}

/// Before: the centreline integrated z over every one of the Ω/(2K) periods
/// (capped at 2²⁰ pieces per sample: minutes for n = 2³⁰, and the cap left
/// the end 2e-8 off). Now whole periods are one period's integral times
/// their number. Reference: the closed-form extension (eq5, evaluated
/// without quadrature): the end of the centreline is (0, Δz). Each of the
/// 99 segments and the period integral are accurate to a few ε absolute
/// (|z′| ≤ 1), measured ≤ 1.3e-15; 1e-14 allows for them.
#[test]
fn centrelines_of_rods_with_a_billion_coils() {
    const END_TOL: f64 = 1e-14;
    for n in [1 << 20, 1 << 30, u32::MAX] {
        for k in [1e-3, 0.5, 0.99] {
            let s = Elastica::symmetric(n, k).unwrap();
            for e in [s.upsilon, s.alpha] {
                let c = e.centreline(100).unwrap();
                let end = c[99];
                assert!(end.x.abs() < END_TOL, "{e}: x = {:e}", end.x);
                assert!(
                    (end.y - e.extension()).abs() < END_TOL,
                    "{e}: {:e}",
                    end.y - e.extension()
                );
                assert!(e.energy().is_finite());
            }
        }
    }
}

/// Found by the fuzz suite: branches that start at m₁ below e^−690 (ϑ_j and
/// secondary branches with n/j near 222) doubled q past the double range
/// and failed with "k = 1 is not allowed". Now they are traced or refused
/// with their reach.
#[test]
fn branches_starting_near_the_end_of_the_double_range() {
    for (n, branch) in [
        (1000, Branch::Theta { j: 5 }),
        (222, Branch::Theta { j: 1 }),
        (
            221,
            Branch::Secondary {
                j: 1,
                arm: Arm::Upper,
            },
        ),
        (
            1000,
            Branch::Secondary {
                j: 5,
                arm: Arm::Lower,
            },
        ),
    ] {
        match Trace::new()
            .points(10)
            .max_force_scaled(20.0)
            .run(n, branch)
        {
            Ok(c) => assert!(rel_err(c.force_scaled(9).unwrap(), 20.0) < 1e-9),
            Err(Error::ForceOutOfReach { reachable, .. }) => assert!(reachable < 20.0),
            Err(e) => panic!("{n} {branch}: {e}"),
        }
    }
}

/// Found while writing the fuzz oracle: `Trace::secondary` returned one point
/// fewer than asked (the fold was counted on both arms), and 3 for 2.
#[test]
fn a_whole_secondary_branch_has_the_points_asked_for() {
    for points in [3, 4, 5, 10, 101] {
        let c = Trace::new()
            .points(points)
            .max_force_scaled(2.0)
            .secondary(4, 3)
            .unwrap();
        assert_eq!(c.len(), points);
    }
    assert!(matches!(
        Trace::new().points(2).secondary(4, 3),
        Err(Error::InvalidCount {
            name: "points",
            value: 2,
            ..
        })
    ));
}
