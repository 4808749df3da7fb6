//! Pinning near-null modes: where a system is nearly invariant under a
//! motion that is not an exact symmetry (a loop sliding along a rod under
//! tension, held in place only by end effects exponentially small in its
//! distance from the ends), its Jacobian J has a few singular values many
//! orders below the rest. Newton's correction along those modes is rounding
//! amplified by 1/σ, and the iteration stalls far above its tolerance at a
//! point that is converged in every other direction.
//!
//! **Finding the modes.** With J factored, [`SAMPLES`] solves J w = r for
//! fixed pseudo-random right-hand sides r: J⁻¹ r = Σ (uᵢ·r/σᵢ) vᵢ, so the
//! solutions span the right singular vectors of the smallest σ first.
//! Gram–Schmidt with column pivoting (the largest remaining solution next)
//! orders them; the modes are the pivots before the first drop by [`GAP`],
//! if one comes within the first `SAMPLES / 2` (none otherwise). Their span
//! is within σ_{k+1}/σ_k of the near-null subspace, and J v = r e / s for
//! the unit mode v = w e / s: its residual is the right-hand sides' size
//! over the pivot s (≥ 10¹⁰ where the modes stall Newton), so the modes are
//! null to that accuracy whatever the subspace's angle.
//!
//! **Pinning them.** Every solve then removes the components of its
//! solution along the modes: Newton on the system bordered by the phase
//! conditions ⟨vᵢ, · − x⟩ = 0 and unfolded along J vᵢ, whose matrix is as
//! well conditioned as J restricted to the modes' complement. Its
//! solution x* solves G(x*) = Σ μᵢ J vᵢ with the unfoldings μᵢ: the
//! equations hold to what the modes cost, and the point is pinned where the
//! iteration found it along them. Tangents and the mesh check's solves are
//! pinned alike, so a continuation does not follow the slide.
//!
//! A system searches for modes only once pinning is enabled (by
//! [`crate::bvp::newton_pinned`] where a Newton failed, or
//! [`System::enable_pinning`] on a system of the same run); from then on
//! every factorisation searches again. Until then nothing here runs and
//! results are those of the unpinned system.

use super::{State, System};
use crate::bvp::problem::Problem;

/// Right-hand sides drawn to find the near-null modes: up to half as many
/// modes are found.
const SAMPLES: usize = 8;

/// The least ratio between successive pivots of the random solves that
/// separates the near-null modes from the rest (module docs): below it, a
/// system that is merely ill conditioned (a fold nearby) is not pinned.
/// Measured on the rod with loops sliding (ν = −0.5, n = 4,
/// F/((2πn)²B) ≈ 9–14): three modes, 10⁵–10⁸ above the fourth pivot and
/// 10¹–10³ apart; where nothing slides (the same runs before the loops
/// formed) successive pivots differ by less than 10².
const GAP: f64 = 1e4;

/// Euclidean inner product over the unknowns (mesh values, stages and the
/// free parameters).
fn dot(a: &State, b: &State, free: &[usize]) -> f64 {
    let mesh: f64 = a.y.iter().zip(&b.y).map(|(u, v)| u * v).sum();
    let stages: f64 = a.k.iter().zip(&b.k).map(|(u, v)| u * v).sum();
    let params: f64 = free.iter().map(|&i| a.p[i] * b.p[i]).sum();
    mesh + stages + params
}

/// d ← d − ⟨v, d⟩ v for a unit `v`.
fn project_out(d: &mut State, v: &State, free: &[usize]) {
    let c = dot(v, d, free);
    d.axpy(-c, v, free);
}

impl<P: Problem + ?Sized> System<'_, P> {
    /// From now on every factorisation searches for near-null modes and
    /// every solve drops its components along those found.
    pub(crate) fn enable_pinning(&mut self) {
        self.pinning = true;
    }

    /// Stops searching and forgets the modes.
    pub(crate) fn disable_pinning(&mut self) {
        self.pinning = false;
        self.pinned.clear();
    }

    /// Whether factorisations search for near-null modes.
    pub(crate) fn is_pinning(&self) -> bool {
        self.pinning
    }

    /// How many modes the last factorisation pinned.
    pub(crate) fn pinned_modes(&self) -> usize {
        self.pinned.len()
    }

    /// The part along the pinned modes of the unpinned solution of
    /// J δ = `r`: where pinning leaves the point, to first order, in
    /// the modes' span (module docs; for a Newton residual, how far the
    /// pinned point is from the system's own solution along them).
    pub(crate) fn pinned_part(&mut self, r: &super::Residual) -> crate::error::Result<State> {
        let mut d = self.zero_state();
        self.solve_unpinned(r, &mut d)?;
        let mut part = self.zero_state();
        for v in &self.pinned {
            part.axpy(dot(v, &d, &self.free), v, &self.free);
        }
        Ok(part)
    }

    /// Removes the components of `d` along the pinned modes.
    pub(crate) fn project_pinned(&self, d: &mut State) {
        for v in &self.pinned {
            // twice: the solutions' components along the modes can be
            // 10¹⁰ times the rest
            project_out(d, v, &self.free);
            project_out(d, v, &self.free);
        }
    }

    /// Searches the current factorisation for near-null modes (module
    /// docs); the modes found (none where a solve fails) replace the last
    /// ones, and pinning is enabled.
    pub(crate) fn find_pinned_modes(&mut self) {
        self.pinning = true;
        self.pinned.clear();
        let free = self.free.clone();
        // a fixed xorshift sequence: the search is reproducible bit for bit
        let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            // 53 random bits, in [−1, 1)
            (seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        };
        let mut w: Vec<State> = Vec::with_capacity(SAMPLES);
        for _ in 0..SAMPLES {
            let mut r = self.zero_residual();
            r.rows_mut().for_each(|v| *v = next());
            let mut wi = self.zero_state();
            if self.solve_unpinned(&r, &mut wi).is_err() {
                return;
            }
            w.push(wi);
        }
        let mut modes: Vec<State> = Vec::new();
        let mut last = f64::NAN;
        while modes.len() <= SAMPLES / 2 {
            let Some((i, pivot)) = w
                .iter()
                .map(|wi| dot(wi, wi, &free).sqrt())
                .enumerate()
                .max_by(|a, b| a.1.total_cmp(&b.1))
            else {
                return;
            };
            if !pivot.is_finite() || pivot == 0.0 {
                return;
            }
            if pivot <= last / GAP {
                self.pinned = modes;
                return;
            }
            let mut v = w.swap_remove(i);
            v.scale(1.0 / pivot);
            for wj in &mut w {
                project_out(wj, &v, &free);
                project_out(wj, &v, &free);
            }
            modes.push(v);
            last = pivot;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvp::tableau::Tableau;

    /// y'' = 0 with y'(0) = 0 and y'(1) = δ y(1): the solutions a + b s
    /// need b = 0 and δ a = 0, so the Jacobian's smallest singular value
    /// is about δ, along the constant (y, y') = (1, 0), and the rest are
    /// of order one (a closed form, independent of the search).
    struct NearlyFree(f64);
    impl Problem for NearlyFree {
        fn dim(&self) -> usize {
            2
        }
        fn parameter_count(&self) -> usize {
            0
        }
        fn boundary_count(&self) -> usize {
            2
        }
        fn rhs(&self, _s: f64, y: &[f64], _p: &[f64], f: &mut [f64]) {
            f[0] = y[1];
            f[1] = 0.0;
        }
        fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
            g[0] = y0[1];
            g[1] = y1[1] - self.0 * y1[0];
        }
    }

    fn modes_of(delta: f64) -> (Vec<State>, State) {
        let prob = NearlyFree(delta);
        let t: Vec<f64> = (0..=8).map(|j| f64::from(j) / 8.0).collect();
        let mut sys = System::new(&prob, t, Tableau::new(3), vec![], 0).unwrap();
        let x = sys.zero_state();
        sys.factor(&x).unwrap();
        sys.find_pinned_modes();
        let mut r = sys.zero_residual();
        r.rows_mut()
            .enumerate()
            .for_each(|(i, v)| *v = (i as f64 * 0.37).sin());
        let mut d = sys.zero_state();
        sys.solve(&r, &mut d).unwrap();
        (sys.pinned.clone(), d)
    }

    #[test]
    fn a_nearly_free_constant_is_found_and_pinned() {
        let (modes, d) = modes_of(1e-12);
        assert_eq!(modes.len(), 1);
        let v = &modes[0];
        // the constant mode: y equal at every mesh point, y' zero; the
        // search's subspace is within σ₁/σ₂ ≈ 1e-12 of it plus the solves'
        // rounding (measured: 2.6e-13 off), so 1e-9
        let y0 = v.y[0];
        for (j, pair) in v.y.chunks(2).enumerate() {
            assert!((pair[0] - y0).abs() < 1e-9, "y at mesh point {j}");
            assert!(pair[1].abs() < 1e-9, "y' at mesh point {j}");
        }
        // a pinned solve has no component along it: unpinned it would be
        // of order 1/δ = 1e12; what the projection leaves is rounding
        // (measured: 7e-13), so 1e-6
        let along: f64 = v.y.iter().zip(&d.y).map(|(a, b)| a * b).sum();
        assert!(along.abs() < 1e-6, "{along}");
    }

    #[test]
    fn a_well_posed_system_has_no_mode_to_pin() {
        // δ = 0.1: σ₁ of order 0.1, no gap of 10⁴ below the rest
        let (modes, _) = modes_of(0.1);
        assert!(modes.is_empty());
    }
}
