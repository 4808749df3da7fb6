//! How close each stretch of a [`Response`] lies to reference branches
//! (the elastica's), in the plane of the paper's plots.

use super::Response;
use crate::curve::{ForceExtension, ForcePoint};

/// How close a stretch lies to a reference branch (an elastica branch):
/// distances in the (Δz, F/(2πn)²) plane of the paper's plots.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BranchMatch {
    /// The branch's label.
    pub label: String,
    /// Root-mean-square distance of the stretch's points from the branch.
    pub rms_distance: f64,
    /// Largest distance of a stretch point from the branch.
    pub max_distance: f64,
}

impl Response {
    /// How close each stretch lies to each of `branches`, nearest first.
    ///
    /// Distances are measured in the (Δz, F/(2πn)²) plane with the curve's
    /// own force scale, from each stretch point to the branch polyline.
    #[must_use]
    pub fn match_branches(&self, branches: &[ForceExtension]) -> Vec<Vec<BranchMatch>> {
        let scale = self.curve().force_scale();
        let pts = self.curve().points();
        self.stretches()
            .iter()
            .map(|stretch| {
                let mut matches: Vec<BranchMatch> = branches
                    .iter()
                    .filter(|b| b.len() >= 2)
                    .map(|b| {
                        let (mut sum, mut max) = (0.0, 0.0_f64);
                        for p in &pts[stretch.range.clone()] {
                            let d = distance_to_polyline(p, b.points(), scale);
                            sum += d * d;
                            max = max.max(d);
                        }
                        BranchMatch {
                            label: b.label().to_owned(),
                            rms_distance: (sum / stretch.range.len() as f64).sqrt(),
                            max_distance: max,
                        }
                    })
                    .collect();
                matches.sort_by(|a, b| a.rms_distance.total_cmp(&b.rms_distance));
                matches
            })
            .collect()
    }
}

fn distance_to_polyline(p: &ForcePoint, line: &[ForcePoint], scale: f64) -> f64 {
    let (px, py) = (p.extension, p.force / scale);
    line.windows(2)
        .map(|w| {
            let (ax, ay) = (w[0].extension, w[0].force / scale);
            let (bx, by) = (w[1].extension, w[1].force / scale);
            let (dx, dy) = (bx - ax, by - ay);
            let len2 = dx * dx + dy * dy;
            let t = if len2 > 0.0 {
                (((px - ax) * dx + (py - ay) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (px - ax - t * dx).hypot(py - ay - t * dy)
        })
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::super::response::test_curves::s_curve;

    #[test]
    fn a_stretch_on_a_branch_is_at_distance_zero_from_it() {
        let pull = s_curve(61);
        let near = pull.match_branches(&[pull.curve().clone()]);
        assert!(near.iter().all(|m| m[0].max_distance == 0.0));
    }
}
