//! The integral inner product of the continuation (module docs).

use super::{Continuation, Steps};
use crate::bvp::system::State;
use crate::bvp::{Problem, Solution};
use crate::error::{Error, Result};

impl Continuation {
    /// The distance ‖a − b‖ of two solutions in this continuation's norm
    /// (module docs: weights w_i, θ on the solver's free parameters and λ),
    /// integrals by the Gauss rule of the solver, so that it measures
    /// arclength the way [`Point::arclength`] does (e.g. to join a point
    /// computed before the run to the branch).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] or [`Error::InvalidCount`] unless both
    /// solutions have the dimension of the weights, the solver's points per
    /// interval, and the same mesh; bad settings as [`Continuation::steps`].
    pub fn distance(&self, a: &Solution, b: &Solution) -> Result<f64> {
        let n = a.dim();
        self.validate(n, a.parameters().len())?;
        let tab = self.solver.validate()?;
        if b.dim() != n || b.parameters().len() != a.parameters().len() {
            return Err(Error::LengthMismatch {
                name: "solution dimension",
                found: b.dim() as u64,
                expected: n as u64,
            });
        }
        for s in [a, b] {
            if s.points_per_interval() != tab.m || s.mesh() != a.mesh() {
                return Err(Error::InvalidCount {
                    name: "points per interval",
                    value: s.points_per_interval() as u64,
                    allowed: "the solver's m, on the same mesh for both solutions",
                });
            }
        }
        let (ya, yb) = (a.collocation_values(), b.collocation_values());
        let mesh = a.mesh();
        let mut sum = 0.0;
        for j in 0..mesh.intervals() {
            let h = mesh.width(j);
            for (k, bk) in tab.b.iter().enumerate() {
                for i in 0..n {
                    let w = self.weights.as_ref().map_or(1.0, |w| w[i]);
                    sum += h * bk * w * (ya[(i, j * tab.m + k)] - yb[(i, j * tab.m + k)]).powi(2);
                }
            }
        }
        for &q in self.solver.free().iter().chain([&self.parameter]) {
            sum += self.parameter_weight * (a.parameters()[q] - b.parameters()[q]).powi(2);
        }
        Ok(sum.sqrt())
    }
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    pub(super) fn inner(&mut self, a: &State, b: &State) -> f64 {
        let (n, m) = (self.sys.n, self.sys.m);
        self.sys.collocation_values(a, &mut self.ycol_a);
        self.sys.collocation_values(b, &mut self.ycol_b);
        let mut s = 0.0;
        for j in 0..self.sys.nn {
            let h = self.sys.h(j);
            for k in 0..m {
                let w = h * self.sys.tab.b[k];
                let o = (j * m + k) * n;
                for i in 0..n {
                    s += w * self.weights[i] * self.ycol_a[o + i] * self.ycol_b[o + i];
                }
            }
        }
        for &q in &self.sys.free {
            s += self.cont.parameter_weight * a.p[q] * b.p[q];
        }
        s
    }

    pub(super) fn norm(&mut self, a: &State) -> f64 {
        self.inner(a, a).sqrt()
    }
}
