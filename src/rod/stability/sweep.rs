//! The bordered Hessian of the discrete rod in O(N): a block LDLᵀ sweep
//! along the rod that solves with it ([`Sweep::solve`], the polish's
//! Newton steps) and counts its negative eigenvalues ([`constrained_index`],
//! Sylvester's law).
//!
//! For G of full row rank c, the bordered matrix
//!
//! ```text
//!   B = [[H, Gᵀ], [G, 0]]   has   n₋(B) = n₋(H on ker G) + c
//! ```
//!
//! (Haynsworth's inertia additivity; the bordered-Hessian test of Debreu,
//! Maddocks). H is block tridiagonal (3 × 3 blocks, one per segment: each
//! node's energy couples two neighbours), but the phase row ξ (the
//! rotation about the force axis, a null vector of H on the constraints)
//! and the end-position rows are dense. The phase is therefore taken
//! locally: ℓ = ξ₀ on segment 0 alone. On ker G_end the form has ξ as its
//! one null vector, and its inertia on any complement of ξ there is the
//! same, so ℓ (with ℓᵀξ = |ξ₀|² = 1) slices it as ξ does. Ordered (φ₀, λ_ℓ),
//! φ₁, …, φ_{N−1}, the matrix M = [[H, ℓ], [ℓᵀ, 0]] stays block
//! tridiagonal, and with C_i the coupling of segments i and i + 1 (padded
//! with a zero row at i = 0)
//!
//! ```text
//!   S₀ = [[H₀₀, ξ₀], [ξ₀ᵀ, 0]],   S_i = H_ii − C_{i−1}ᵀ S_{i−1}⁻¹ C_{i−1},
//!   M = L diag(S_i) Lᵀ,   L_{i+1,i} = C_iᵀ S_i⁻¹,   n₋(M) = Σ n₋(S_i).
//! ```
//!
//! The end rows W (x(1), y(1), and z(1) under extension control) enter
//! through the Schur complement T = −W M⁻¹ Wᵀ, and n₋(B) = n₋(M) + n₋(T).
//!
//! The sweep does not pivot between blocks (as the Sturm counts of
//! structural codes do not): where a pivot block or T is nearly singular
//! relative to its own size it gives up (`None`), and the caller takes the
//! sparse LU or the dense eigenvalues instead.

use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// A pivot block (or T) counts as nearly singular when its smallest
/// eigenvalue in modulus is below this fraction of its largest: a count
/// taken through such a pivot could be off by its sign, and a solve
/// through it loses the digits its condition number costs.
const NEARLY_SINGULAR: f64 = 1e-10;

/// The block LDLᵀ of M = [[H, ℓ], [ℓᵀ, 0]] (module docs).
pub(super) struct Sweep {
    /// S_i⁻¹ (4 × 4 at i = 0, else 3 × 3).
    inverses: Vec<DMatrix<f64>>,
    /// C_i (4 × 3 at i = 0, else 3 × 3; none after the last segment).
    couplings: Vec<DMatrix<f64>>,
    /// n₋(M).
    negative: usize,
}

impl Sweep {
    /// The sweep of `hess` (n × n, block tridiagonal in 3 × 3 blocks) with
    /// the local phase `phase` on segment 0; `None` where a pivot is nearly
    /// singular ([`NEARLY_SINGULAR`]).
    pub(super) fn new(hess: &DMatrix<f64>, phase: [f64; 3]) -> Option<Self> {
        let segments = hess.nrows() / 3;
        let block = |i: usize, j: usize, rows: usize| {
            let mut b = DMatrix::<f64>::zeros(rows, 3);
            for a in 0..3 {
                for c in 0..3 {
                    b[(a, c)] = hess[(3 * i + a, 3 * j + c)];
                }
            }
            b
        };
        let mut inverses: Vec<DMatrix<f64>> = Vec::with_capacity(segments);
        let mut couplings: Vec<DMatrix<f64>> = Vec::with_capacity(segments);
        let mut negative = 0;
        for i in 0..segments {
            let size = if i == 0 { 4 } else { 3 };
            let mut s = DMatrix::<f64>::zeros(size, size);
            s.view_mut((0, 0), (3, 3)).copy_from(&block(i, i, 3));
            if i == 0 {
                for a in 0..3 {
                    s[(a, 3)] = phase[a];
                    s[(3, a)] = phase[a];
                }
            } else {
                let (inv, c) = (&inverses[i - 1], &couplings[i - 1]);
                s -= c.transpose() * (inv * c);
            }
            let s = (&s + s.transpose()) * 0.5;
            let eig = SymmetricEigen::new(s);
            if nearly_singular(&eig.eigenvalues) {
                return None;
            }
            negative += eig.eigenvalues.iter().filter(|l| **l < 0.0).count();
            inverses.push(inverse(&eig));
            if i + 1 < segments {
                couplings.push(block(i, i + 1, size));
            }
        }
        Some(Self {
            inverses,
            couplings,
            negative,
        })
    }

    /// X = M⁻¹ [R; 0] restricted to the φ rows: `r` is n × k in segment
    /// order (no row for λ_ℓ, whose right-hand side is 0).
    pub(super) fn solve(&self, r: &DMatrix<f64>) -> DMatrix<f64> {
        let segments = self.inverses.len();
        let k = r.ncols();
        let rows = |i: usize| if i == 0 { 4 } else { 3 };
        // forward: Z_i = R_i − C_{i−1}ᵀ S_{i−1}⁻¹ Z_{i−1}
        let mut z: Vec<DMatrix<f64>> = Vec::with_capacity(segments);
        for i in 0..segments {
            let mut zi = DMatrix::<f64>::zeros(rows(i), k);
            zi.view_mut((0, 0), (3, k)).copy_from(&r.rows(3 * i, 3));
            if i > 0 {
                let c = &self.couplings[i - 1];
                zi -= c.transpose() * (&self.inverses[i - 1] * &z[i - 1]);
            }
            z.push(zi);
        }
        // back: X_i = S_i⁻¹ (Z_i − C_i X_{i+1})
        let mut x = DMatrix::<f64>::zeros(3 * segments, k);
        let mut next: Option<DMatrix<f64>> = None;
        for i in (0..segments).rev() {
            let mut rhs = z[i].clone();
            if let Some(xn) = &next {
                rhs -= &self.couplings[i] * xn;
            }
            let xi = &self.inverses[i] * rhs;
            x.view_mut((3 * i, 0), (3, k)).copy_from(&xi.rows(0, 3));
            next = Some(xi.rows(0, 3).into_owned());
        }
        x
    }
}

/// The number of negative eigenvalues of `hess` (n × n, block tridiagonal
/// in 3 × 3 blocks) restricted to the kernel of the rows `end` (c′ × n) and
/// of the phase row (whose segment-0 entries are `phase`; a null vector
/// of `hess` there), `None` where a pivot or the end rows' Schur
/// complement is nearly singular ([`NEARLY_SINGULAR`]).
pub(super) fn constrained_index(
    hess: &DMatrix<f64>,
    end: &DMatrix<f64>,
    phase: [f64; 3],
) -> Option<usize> {
    let sweep = Sweep::new(hess, phase)?;
    let mut negative = sweep.negative;
    let c_end = end.nrows();
    if c_end > 0 {
        let t = -(end * sweep.solve(&end.transpose()));
        let t = (&t + t.transpose()) * 0.5;
        let eig = SymmetricEigen::new(t);
        if nearly_singular(&eig.eigenvalues) {
            return None;
        }
        negative += eig.eigenvalues.iter().filter(|l| **l < 0.0).count();
    }
    // n₋(B) = index + c, c = c′ + 1 (the phase)
    negative.checked_sub(c_end + 1)
}

/// S⁻¹ = V Λ⁻¹ Vᵀ from the eigen-decomposition.
fn inverse(eig: &SymmetricEigen<f64, nalgebra::Dyn>) -> DMatrix<f64> {
    let v = &eig.eigenvectors;
    let mut scaled = v.clone();
    for (j, l) in eig.eigenvalues.iter().enumerate() {
        scaled.column_mut(j).scale_mut(1.0 / l);
    }
    scaled * v.transpose()
}

/// Whether the smallest eigenvalue in modulus is below [`NEARLY_SINGULAR`]
/// of the largest (or any is not finite).
fn nearly_singular(eigenvalues: &DVector<f64>) -> bool {
    let (lo, hi) = eigenvalues
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), l| {
            (lo.min(l.abs()), hi.max(l.abs()))
        });
    !(lo.is_finite() && hi.is_finite()) || lo <= NEARLY_SINGULAR * hi
}
