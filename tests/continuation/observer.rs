//! The observer hooks of a run: order, special points, stopping, and the
//! every-n-th-point adapter.

use std::ops::ControlFlow;

use hockle::bvp::{Collocation, Solution};
use hockle::continuation::{Continuation, Observer, Point, PointKind, Run, Termination};

use super::problems::{Bratu, Euler};

/// What a run told its observer, in order.
#[derive(Debug, Default)]
struct Log {
    calls: Vec<(&'static str, f64)>,
    finish: Option<Termination>,
    stop_at_fold: bool,
    stop_at_start: bool,
}

impl Observer for Log {
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        assert!(settings.to_string().contains("p[0]"), "{settings}");
        self.calls.push(("start", start.parameter()));
        if self.stop_at_start {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    }
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        self.calls.push(("point", point.parameter()));
        ControlFlow::Continue(())
    }
    fn fold(&mut self, fold: &Point) -> ControlFlow<()> {
        self.calls.push(("fold", fold.parameter()));
        if self.stop_at_fold {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    }
    fn branch_point(&mut self, branch_point: &Point) -> ControlFlow<()> {
        self.calls.push(("branch point", branch_point.parameter()));
        ControlFlow::Continue(())
    }
    fn finish(&mut self, termination: &Termination) {
        assert!(self.finish.is_none(), "finish called twice");
        self.finish = Some(termination.clone());
    }
}

fn bratu_start() -> Solution {
    Collocation::new()
        .intervals(10)
        .solve(&Bratu::default(), |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap()
}

/// Around the Bratu fold to y'(0) = 10 on the upper branch.
fn around_the_fold() -> Continuation {
    Continuation::new(0)
        .step(0.1)
        .stop_when(|s| s.at_mesh(0)[1] - 10.0)
}

fn run_logged(log: &mut Log) -> Run {
    around_the_fold()
        .run(&Bratu::default(), &bratu_start(), &mut *log)
        .unwrap()
}

impl Observer for &mut Log {
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        (**self).start(settings, start)
    }
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        (**self).point(point)
    }
    fn fold(&mut self, fold: &Point) -> ControlFlow<()> {
        (**self).fold(fold)
    }
    fn branch_point(&mut self, branch_point: &Point) -> ControlFlow<()> {
        (**self).branch_point(branch_point)
    }
    fn finish(&mut self, termination: &Termination) {
        (**self).finish(termination);
    }
}

#[test]
fn hooks_come_in_order_and_see_every_point_and_the_fold() {
    let mut log = Log::default();
    let run = run_logged(&mut log);
    // start, then point for every point, with fold right after the fold's
    // point; finish with the run's termination.
    assert_eq!(log.calls[0], ("start", 0.0));
    let points: Vec<f64> = log
        .calls
        .iter()
        .filter(|c| c.0 == "point")
        .map(|c| c.1)
        .collect();
    let expected: Vec<f64> = run.points().iter().map(Point::parameter).collect();
    assert_eq!(points, expected);
    let folds: Vec<usize> = (0..log.calls.len())
        .filter(|&i| log.calls[i].0 == "fold")
        .collect();
    assert_eq!(folds.len(), 1, "{:?}", log.calls);
    let fold = run.folds().next().unwrap().parameter();
    assert_eq!(log.calls[folds[0]], ("fold", fold));
    assert_eq!(log.calls[folds[0] - 1], ("point", fold));
    assert_eq!(log.finish.as_ref(), Some(run.termination()));
    assert_eq!(run.termination(), &Termination::Event(0));
}

#[test]
fn a_break_from_the_fold_hook_stops_at_the_fold() {
    let mut log = Log {
        stop_at_fold: true,
        ..Log::default()
    };
    let run = run_logged(&mut log);
    assert_eq!(run.termination(), &Termination::Stopped);
    assert_eq!(run.last().unwrap().kind(), PointKind::Fold);
    assert_eq!(log.calls.last().unwrap().0, "fold");
    assert_eq!(log.finish, Some(Termination::Stopped));
}

#[test]
fn a_break_from_the_start_hook_keeps_the_start_point_only() {
    let mut log = Log {
        stop_at_start: true,
        ..Log::default()
    };
    let run = run_logged(&mut log);
    assert_eq!(run.termination(), &Termination::Stopped);
    assert_eq!(run.points().len(), 1);
    assert_eq!(run.points()[0].kind(), PointKind::Start);
    // No point hook after the Break; finish is still called.
    assert_eq!(log.calls, vec![("start", 0.0)]);
    assert_eq!(log.finish, Some(Termination::Stopped));
}

#[test]
fn the_branch_point_hook_sees_every_buckling_load() {
    let solver = Collocation::new().intervals(40);
    let start = solver.solve(&Euler, |_s: f64| [0.0, 0.0], &[1.0]).unwrap();
    let mut log = Log::default();
    let run = Continuation::new(0)
        .solver(solver)
        .step(0.5)
        .step_bounds(1e-8, 2.0)
        .stop_at(45.0)
        .run(&Euler, &start, &mut log)
        .unwrap();
    let seen: Vec<f64> = log
        .calls
        .iter()
        .filter(|c| c.0 == "branch point")
        .map(|c| c.1)
        .collect();
    let located: Vec<f64> = run.branch_points().map(Point::parameter).collect();
    assert_eq!(located.len(), 2);
    assert_eq!(seen, located);
}

#[test]
fn every_nth_point_keeps_the_start_the_special_points_and_each_nth() {
    let mut all = Vec::new();
    let full = around_the_fold()
        .run(&Bratu::default(), &bratu_start(), |p: &Point| {
            all.push((p.kind(), p.parameter()));
            ControlFlow::Continue(())
        })
        .unwrap();
    let mut some = Vec::new();
    let thinned = around_the_fold()
        .run(
            &Bratu::default(),
            &bratu_start(),
            (|p: &Point| {
                some.push((p.kind(), p.parameter()));
                ControlFlow::Continue(())
            })
            .every(3),
        )
        .unwrap();
    // The run itself is not thinned.
    assert_eq!(thinned.points().len(), full.points().len());
    let expected: Vec<_> = all
        .iter()
        .enumerate()
        .filter(|(i, (k, _))| i % 3 == 0 || *k != PointKind::Regular)
        .map(|(_, p)| *p)
        .collect();
    assert_eq!(some, expected);
    assert!(some.len() < all.len());
    assert!(some.iter().any(|p| p.0 == PointKind::Fold));
    assert!(some.iter().any(|p| p.0 == PointKind::Event(0)));
    // n = 0 is every point.
    let mut n0 = 0;
    around_the_fold()
        .run(
            &Bratu::default(),
            &bratu_start(),
            (|_: &Point| {
                n0 += 1;
                ControlFlow::Continue(())
            })
            .every(0),
        )
        .unwrap();
    assert_eq!(n0, all.len());
}

#[test]
fn settings_results_and_adapters_are_send_and_sync() {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<Continuation>();
    send_sync::<Run>();
    send_sync::<Point>();
    send_sync::<PointKind>();
    send_sync::<Termination>();
    send_sync::<hockle::continuation::BranchSide>();
    send_sync::<hockle::continuation::Every<Log>>();
}
