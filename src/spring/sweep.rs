//! Many scenes, one model: [`sweep`], in parallel with the `rayon` feature.

use std::sync::atomic::{AtomicUsize, Ordering};

use super::{Model, Response, Spring};
use crate::error::Result;
use crate::load::Target;

/// Pulls every `(spring, target)` of `scenes` with `model` and returns the
/// answers in input order. With the `rayon` feature the scenes run on
/// rayon's pool (one scene per task, the slowest scenes decide the wall
/// time); without it, one after the other. `progress(done, total)` is
/// called after each scene finishes, from the thread that ran it, in
/// completion order.
///
/// Each scene is computed exactly as [`Model::pull_to`] computes it alone:
/// the answers are the same bit for bit as [`sweep_serial`]'s, whatever
/// the number of threads (`tests/spring` checks it).
///
/// ```
/// use hockle::spring::{sweep, HelixModel, Spring, Target};
/// let mut scenes = Vec::new();
/// for theta0 in [60.0, 80.0, 89.0] {
///     let spring = Spring::from_degrees(4, theta0, hockle::Stiffness::nikolai(10.0, 0.05)?)?;
///     scenes.push((spring, Target::Force(0.5)));
/// }
/// let answers = sweep(&HelixModel::default(), &scenes, |done, total| eprintln!("{done}/{total}"));
/// assert_eq!(answers.len(), 3);
/// assert!(answers.iter().all(|a| a.is_ok()));
/// # Ok::<(), hockle::Error>(())
/// ```
pub fn sweep<M, F>(model: &M, scenes: &[(Spring, Target)], progress: F) -> Vec<Result<Response>>
where
    M: Model + Sync + ?Sized,
    F: Fn(usize, usize) + Sync,
{
    let done = AtomicUsize::new(0);
    let total = scenes.len();
    let one = |(spring, target): &(Spring, Target)| {
        let r = model.pull_to(spring, *target);
        progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
        r
    };
    #[cfg(feature = "rayon")]
    {
        use rayon::prelude::*;
        scenes.par_iter().with_max_len(1).map(one).collect()
    }
    #[cfg(not(feature = "rayon"))]
    {
        scenes.iter().map(one).collect()
    }
}

/// [`sweep`] on this thread only, in input order (the reference for the
/// parallel run and its speed-up).
pub fn sweep_serial<M, F>(
    model: &M,
    scenes: &[(Spring, Target)],
    progress: F,
) -> Vec<Result<Response>>
where
    M: Model + ?Sized,
    F: Fn(usize, usize),
{
    let total = scenes.len();
    scenes
        .iter()
        .enumerate()
        .map(|(i, (spring, target))| {
            let r = model.pull_to(spring, *target);
            progress(i + 1, total);
            r
        })
        .collect()
}
