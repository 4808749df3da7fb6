//! `spring::sweep`: every scene answered as alone, bit for bit, in input
//! order, whatever the number of threads.

use std::sync::atomic::{AtomicUsize, Ordering};

use hockle::spring::{HelixModel, Model, RodModel, Spring, Target, sweep, sweep_serial};
use hockle::{Error, Stiffness};

fn scenes() -> Vec<(Spring, Target)> {
    // Different helix angles and anisotropies, one target the helix cannot
    // reach at rest (an error must come back in its place).
    let mut s: Vec<(Spring, Target)> = [(89.8, 10.0), (88.0, 4.0), (80.0, 1.0)]
        .into_iter()
        .map(|(t, a)| {
            (
                Spring::from_degrees(4, t, Stiffness::nikolai(a, 0.05).unwrap()).unwrap(),
                Target::Force(0.3),
            )
        })
        .collect();
    s.push((s[0].0, Target::Extension(1.5)));
    s
}

#[test]
fn sweep_equals_serial_runs_and_single_pulls() {
    let scenes = scenes();
    // A coarse rod (16 intervals) keeps the test short; bit-identity does
    // not depend on the mesh.
    let rod = RodModel::default().intervals(16);
    let models: [&(dyn Model + Sync); 2] = [&HelixModel::default(), &rod];
    for model in models {
        let calls = AtomicUsize::new(0);
        let parallel = sweep(model, &scenes, |done, total| {
            assert!(done >= 1 && done <= total && total == scenes.len());
            calls.fetch_add(1, Ordering::Relaxed);
        });
        assert_eq!(calls.load(Ordering::Relaxed), scenes.len());
        let serial = sweep_serial(model, &scenes, |_, _| {});
        assert_eq!(parallel.len(), scenes.len());
        for (k, ((p, s), (spring, target))) in parallel.iter().zip(&serial).zip(&scenes).enumerate()
        {
            let alone = model.pull_to(spring, *target);
            match (p, s, alone) {
                // PartialEq on Response compares every f64 exactly
                (Ok(p), Ok(s), Ok(a)) => {
                    assert_eq!(p, s, "{}: scene {k}", model.name());
                    assert_eq!(p, &a, "{}: scene {k}", model.name());
                }
                (Err(p), Err(s), Err(a)) => {
                    assert_eq!(p.to_string(), s.to_string());
                    assert_eq!(p.to_string(), a.to_string());
                    assert!(matches!(p, Error::UnreachableTarget { .. }), "{p}");
                }
                other => panic!("{}: scene {k}: {other:?}", model.name()),
            }
        }
    }
}

#[cfg(feature = "rayon")]
#[test]
fn sweep_on_one_and_three_threads_is_bit_identical() {
    let scenes = scenes();
    let rod = RodModel::default().intervals(16);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| sweep(&rod, &scenes, |_, _| {}))
    };
    let (one, three) = (run(1), run(3));
    for (a, b) in one.iter().zip(&three) {
        match (a, b) {
            (Ok(a), Ok(b)) => assert_eq!(a, b),
            (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
            other => panic!("{other:?}"),
        }
    }
}
