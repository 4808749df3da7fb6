//! The paper's Fig. spring through the scene: three pop-outs, the stretches
//! between them on the secondary υ elastica branches j = 3, 2, 1.

use hockle::spring::{Control, Direction, ElasticaModel, Model, RodModel, Spring};

#[test]
fn the_paper_spring_sheds_three_loops_onto_the_secondary_upsilon_branches() {
    let spring = Spring::paper();
    let pull = RodModel::default().pull(&spring, 3.0).unwrap();
    assert!(pull.reached_target(), "{pull}");

    let pop_outs = pull.pop_outs();
    assert_eq!(pop_outs.len(), 3, "{pull}");

    let loops: Vec<Option<u32>> = pull.stretches().iter().map(|s| s.loops).collect();
    assert_eq!(loops, [Some(4), Some(3), Some(2), Some(1)]);

    // Each stretch after a pop-out lies nearest the secondary υ-branch with
    // as many loops as the spring has left (the paper's Section 4). The
    // distance bound is the pitch's imperfection: a helix at 0.2° from
    // planar deviates from the elastica by O(cos θ0) ≈ 3.5e-3 in Δz, and the
    // stretch ends near the folds are 3D; 0.05 in (Δz, F/(2πn)²) separates
    // neighbouring branches, which lie ≥ 0.1 apart.
    let scaffold = ElasticaModel::default().scaffold(&spring, 3.0).unwrap();
    let matches = pull.match_branches(&scaffold);
    for (stretch, j) in matches.iter().skip(1).zip([3, 2, 1]) {
        let best = &stretch[0];
        assert!(best.label.contains(&format!("j = {j}")), "{stretch:?}");
        assert!(best.rms_distance < 0.05, "{stretch:?}");
    }

    // Under force control, loading jumps at each maximum-force fold;
    // unloading jumps at minimum-force folds, always at lower forces:
    // hysteresis. (Unloading from the j = 1 branch may drop past the j = 2
    // branch when that branch never comes down to the fold's force.)
    let jumps = pull.jumps(Control::Force);
    let loading: Vec<_> = jumps
        .iter()
        .filter(|j| j.direction == Direction::Loading)
        .collect();
    let unloading: Vec<_> = jumps
        .iter()
        .filter(|j| j.direction == Direction::Unloading)
        .collect();
    assert_eq!(loading.len(), 3, "{jumps:?}");
    assert!(!unloading.is_empty(), "{jumps:?}");
    for down in &unloading {
        assert!(down.to.extension < down.from.extension);
        let up = loading
            .iter()
            .filter(|up| up.to.extension >= down.from.extension);
        for up in up {
            assert!(down.from.force < up.from.force, "{down:?} vs {up:?}");
        }
    }
}
