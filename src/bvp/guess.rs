//! Starting guesses: what a guess is, and the unknowns built from one.

use super::mesh::Mesh;
use super::solution::Solution;
use super::system::State;
use super::tableau::Tableau;

/// A starting guess for [`Collocation::solve`](super::Collocation::solve): a closure s ↦ y(s) (any
/// `Fn(f64) -> V` with `V: AsRef<[f64]>`, e.g. arrays, `Vec` or `DVector`),
/// or a previous [`Solution`] (copied exactly when the mesh and m agree,
/// otherwise evaluated through its collocation polynomial).
pub trait InitialGuess {
    /// Writes the guess y(s) into `y` (length n).
    fn value(&self, s: f64, y: &mut [f64]);

    /// The solution this guess is, when it is one.
    fn solution(&self) -> Option<&Solution> {
        None
    }
}

impl<F, V> InitialGuess for F
where
    F: Fn(f64) -> V,
    V: AsRef<[f64]>,
{
    fn value(&self, s: f64, y: &mut [f64]) {
        let v = self(s);
        let v = v.as_ref();
        let k = v.len().min(y.len());
        y[..k].copy_from_slice(&v[..k]);
    }
}

impl InitialGuess for Solution {
    fn value(&self, s: f64, y: &mut [f64]) {
        self.eval_into(s, y);
    }

    fn solution(&self) -> Option<&Solution> {
        Some(self)
    }
}

impl InitialGuess for &Solution {
    fn value(&self, s: f64, y: &mut [f64]) {
        self.eval_into(s, y);
    }

    fn solution(&self) -> Option<&Solution> {
        Some(self)
    }
}

/// Builds the unknowns on `mesh` from a guess: Y_j = y(t_j) and K_j such
/// that the collocation polynomial interpolates y at the Gauss points.
pub(crate) fn state_from_guess<G: InitialGuess + ?Sized>(
    guess: &G,
    mesh: &Mesh,
    tab: &Tableau,
    n: usize,
    p: &[f64],
) -> State {
    let m = tab.m;
    let nn = mesh.intervals();
    if let Some(sol) = guess.solution()
        && sol.n == n
        && sol.tab.m == m
        && sol.mesh == *mesh
    {
        return State {
            y: sol.y.clone(),
            k: sol.k.clone(),
            p: p.to_vec(),
        };
    }
    let mut y = vec![0.0; (nn + 1) * n];
    for j in 0..=nn {
        guess.value(mesh.points()[j], &mut y[j * n..(j + 1) * n]);
    }
    let mut k = vec![0.0; nn * m * n];
    let mut v = vec![0.0; m * n];
    for j in 0..nn {
        let h = mesh.width(j);
        for l in 0..m {
            let z = mesh.points()[j] + tab.c[l] * h;
            guess.value(z, &mut v[l * n..(l + 1) * n]);
            for i in 0..n {
                v[l * n + i] -= y[j * n + i];
            }
        }
        for kk in 0..m {
            for l in 0..m {
                let a = tab.a_inv[kk * m + l] / h;
                for i in 0..n {
                    k[(j * m + kk) * n + i] += a * v[l * n + i];
                }
            }
        }
    }
    State {
        y,
        k,
        p: p.to_vec(),
    }
}

/// The unknowns `x` on `from` carried onto `to` through the collocation
/// polynomial (the re-interpolation of a remeshed continuation: of its
/// point and of its tangent alike).
pub(crate) fn state_on_mesh(x: &State, from: &Mesh, tab: &Tableau, n: usize, to: &Mesh) -> State {
    let interpolant = Solution::interpolant(x, from, tab, n);
    state_from_guess(&interpolant, to, tab, n, &x.p)
}
