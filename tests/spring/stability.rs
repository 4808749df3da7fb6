//! Stability labels of the cheap models, checked against what their one
//! degree of freedom allows.

use hockle::spring::{Control, HelixModel, Model, Spring};

#[test]
fn the_exact_helix_is_unstable_under_dead_load_exactly_where_it_softens() {
    // The exact helix has one degree of freedom, its angle θ, and Δz = cos θ
    // is monotonic in it: a hard device fixes θ, so every point is held,
    // and under a dead load the second variation is U″(θ) − F Δz″(θ), whose
    // sign is that of the stiffness dF/dΔz. The carried labels know
    // neither: they come from the fold list alone.
    let spring = Spring::paper();
    let pull = HelixModel::default().pull(&spring, 3.0).unwrap();
    let pts = pull.curve().points();
    let force = pull.stability(Control::Force);
    let hard = pull.stability(Control::Extension);
    assert!(hard.iter().all(|s| s.is_stable()));
    let mut softening = 0;
    for i in 1..pts.len() - 1 {
        // slope from both neighbours; skip the extreme samples themselves
        let before = (pts[i].force - pts[i - 1].force) / (pts[i].extension - pts[i - 1].extension);
        let after = (pts[i + 1].force - pts[i].force) / (pts[i + 1].extension - pts[i].extension);
        if before.signum() != after.signum() {
            continue;
        }
        assert_eq!(force[i].is_stable(), before > 0.0, "point {i}");
        softening += usize::from(before < 0.0);
    }
    // The paper's helix has a force maximum and a minimum below
    // F/(2πn)² = 3, so both kinds of point are checked.
    assert!(softening > 0 && softening < pts.len() / 2, "{softening}");
}
