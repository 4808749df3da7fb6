//! `bvp`: the mesh constructors (the solver's entries are the lead's to add).

use hockle::bvp::Mesh;

use crate::hostile::{Gen, Report};

pub const CI_CALLS: u64 = 100_000;

pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
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
}

/// Counts beyond what can be allocated must be refused.
pub fn huge_counts(_g: &mut Gen, r: &mut Report, _calls: u64) {
    for intervals in [hockle::error::MAX_POINTS + 1, u32::MAX as usize, usize::MAX] {
        if let Some(res) = r.call(
            || format!("Mesh::uniform({intervals})"),
            || Mesh::uniform(intervals),
        ) {
            r.check(res.is_err(), || {
                format!("Mesh::uniform({intervals}) accepted")
            });
        }
    }
}
