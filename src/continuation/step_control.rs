//! Step control: halving on rejection, growth by corrector iterations
//! (module docs: AUTO-07p's rule with shifted thresholds).

use super::corrector::Corrected;
use super::{Rejection, Steps};
use crate::bvp::Problem;
use crate::error::Error;

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// Corrects at the current Δs, halving it and retrying while the
    /// corrector fails or the tangent turns by more than the maximum angle;
    /// `None` (with the termination set) when that happens at Δs_min.
    pub(super) fn accepted_step(&mut self) -> Option<Corrected> {
        loop {
            let reuse = self.factored_at_x0;
            let res = self.correct(self.ds, reuse);
            match res {
                Ok(c) => {
                    let cosang = self.inner(&c.tangent, &self.t0.clone());
                    let angle = cosang.clamp(-1.0, 1.0).acos();
                    let max_angle = self.cont.max_angle;
                    if angle <= max_angle {
                        self.angle = angle;
                        return Some(c);
                    }
                    if self.ds <= self.cont.ds_min {
                        self.fail(Error::StepAngleTooLarge { angle, max_angle });
                        return None;
                    }
                    self.reject_step(Rejection::Turn { angle, max_angle });
                }
                Err(e) => {
                    if self.ds <= self.cont.ds_min {
                        self.fail(e);
                        return None;
                    }
                    self.reject_step(Rejection::Corrector(e));
                }
            }
        }
    }

    /// The next Δs after an accepted step whose corrector took
    /// `iterations`, limited so that the next angle between tangents is
    /// about 0.6 of the maximum and by the interpolation's `limit` factor.
    pub(super) fn adapt_step(&mut self, iterations: u32, limit: f64) {
        let by_iterations: f64 = match iterations {
            0..=4 => 2.0,
            5 => 1.5,
            6 => 1.1,
            _ => 0.5,
        };
        let by_angle = if self.angle > 0.0 {
            0.6 * self.cont.max_angle / self.angle
        } else {
            f64::INFINITY
        };
        let factor = by_iterations.min(by_angle).min(limit).max(0.25);
        self.ds = (self.ds * factor).clamp(self.cont.ds_min, self.cont.ds_max);
    }
}
