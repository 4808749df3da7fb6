//! The discrete rod's bordered Hessian in O(N): a block LDLᵀ sweep along
//! the rod that counts its negative eigenvalues ([`constrained_index`],
//! Sylvester's law) and solves with it ([`Sweep::solve_with_phase`]: the
//! end rows' Schur complement, and the polish's Newton steps).
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
//! dense eigenvalues or a sparse LU instead.

use nalgebra::{DMatrix, Matrix4, SymmetricEigen, Vector4};

use super::block_tridiagonal::BlockTridiagonal;

/// A pivot block (or T) counts as nearly singular when its smallest
/// eigenvalue in modulus is below this fraction of its largest: a count
/// taken through such a pivot could be off by its sign, and a solve
/// through it loses the digits its condition number costs.
const NEARLY_SINGULAR: f64 = 1e-10;

/// The block LDLᵀ of M = [[H, ℓ], [ℓᵀ, 0]] (module docs). Every block is
/// 4 × 4 on the stack: segment 0's holds λ_ℓ in its fourth row and
/// column, the others a padding pivot there (a positive multiple of the
/// identity, uncoupled, the size of the block's own diagonal), which adds
/// a positive eigenvalue and no negative one.
pub(super) struct Sweep {
    /// S_i⁻¹.
    inverses: Vec<Matrix4<f64>>,
    /// C_i, the coupling of segment i to i + 1 (fourth row and column
    /// zero, so λ_ℓ and the paddings take no part; none after the last
    /// segment).
    couplings: Vec<Matrix4<f64>>,
    /// n₋(M).
    negative: usize,
}

impl Sweep {
    /// The sweep of `hess` (n × n, block tridiagonal in 3 × 3 blocks) with
    /// the local phase `phase` on segment 0; `None` where a pivot is nearly
    /// singular ([`NEARLY_SINGULAR`]).
    pub(super) fn new(hess: &BlockTridiagonal, phase: [f64; 3]) -> Option<Self> {
        let segments = hess.diag.len();
        let padded = |m: &nalgebra::Matrix3<f64>| {
            let mut b = Matrix4::<f64>::zeros();
            b.fixed_view_mut::<3, 3>(0, 0).copy_from(m);
            b
        };
        let mut inverses = Vec::with_capacity(segments);
        let mut couplings = Vec::with_capacity(segments);
        let mut negative = 0;
        for i in 0..segments {
            let mut s = padded(&hess.diag[i]);
            if i == 0 {
                for a in 0..3 {
                    s[(a, 3)] = phase[a];
                    s[(3, a)] = phase[a];
                }
            } else {
                let c: &Matrix4<f64> = &couplings[i - 1];
                s -= c.transpose() * (inverses[i - 1] * c);
                s[(3, 3)] = (0..3).map(|a| s[(a, a)].abs()).fold(0.0, f64::max);
            }
            let s = (s + s.transpose()) * 0.5;
            let eig = SymmetricEigen::new(s);
            if nearly_singular(eig.eigenvalues.as_slice()) {
                return None;
            }
            negative += eig.eigenvalues.iter().filter(|l| **l < 0.0).count();
            let v = eig.eigenvectors;
            let mut scaled = v;
            for (j, l) in eig.eigenvalues.iter().enumerate() {
                scaled.column_mut(j).scale_mut(1.0 / l);
            }
            inverses.push(scaled * v.transpose());
            if i + 1 < segments {
                couplings.push(padded(&hess.upper[i]));
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
        self.solve_with_phase(r, &vec![0.0; r.ncols()]).0
    }

    /// M⁻¹ [R; r_ℓ]: `r` (n × k, segment order) the φ rows of the
    /// right-hand sides and `r_phase` (k) their λ_ℓ entries; the φ rows of
    /// the solutions and their λ_ℓ entries.
    pub(super) fn solve_with_phase(
        &self,
        r: &DMatrix<f64>,
        r_phase: &[f64],
    ) -> (DMatrix<f64>, Vec<f64>) {
        let segments = self.inverses.len();
        let mut x = DMatrix::<f64>::zeros(3 * segments, r.ncols());
        let mut x_phase = vec![0.0; r.ncols()];
        let mut z = vec![Vector4::<f64>::zeros(); segments];
        for col in 0..r.ncols() {
            // forward: Z_i = R_i − C_{i−1}ᵀ S_{i−1}⁻¹ Z_{i−1}
            for i in 0..segments {
                let mut zi = Vector4::new(
                    r[(3 * i, col)],
                    r[(3 * i + 1, col)],
                    r[(3 * i + 2, col)],
                    if i == 0 { r_phase[col] } else { 0.0 },
                );
                if i > 0 {
                    zi -= self.couplings[i - 1].transpose() * (self.inverses[i - 1] * z[i - 1]);
                }
                z[i] = zi;
            }
            // back: X_i = S_i⁻¹ (Z_i − C_i X_{i+1})
            let mut next = Vector4::<f64>::zeros();
            for i in (0..segments).rev() {
                let mut rhs = z[i];
                if i + 1 < segments {
                    rhs -= self.couplings[i] * next;
                }
                let xi = self.inverses[i] * rhs;
                for a in 0..3 {
                    x[(3 * i + a, col)] = xi[a];
                }
                if i == 0 {
                    x_phase[col] = xi[3];
                }
                next = xi;
            }
        }
        (x, x_phase)
    }
}

/// The number of negative eigenvalues of `hess` (n × n, block tridiagonal
/// in 3 × 3 blocks) restricted to the kernel of the rows `end` (c′ × n) and
/// of the phase row (whose segment-0 entries are `phase`; a null vector
/// of `hess` there), `None` where a pivot or the end rows' Schur
/// complement is nearly singular ([`NEARLY_SINGULAR`]), or where fewer
/// negative pivots than constraints came out (no count to trust).
pub(super) fn constrained_index(
    hess: &BlockTridiagonal,
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
        if nearly_singular(eig.eigenvalues.as_slice()) {
            return None;
        }
        negative += eig.eigenvalues.iter().filter(|l| **l < 0.0).count();
    }
    // n₋(B) = index + c, c = c′ + 1 (the phase)
    negative.checked_sub(c_end + 1)
}

/// Whether the smallest eigenvalue in modulus is below [`NEARLY_SINGULAR`]
/// of the largest (or any is not finite).
fn nearly_singular(eigenvalues: &[f64]) -> bool {
    let (lo, hi) = eigenvalues
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), l| {
            (lo.min(l.abs()), hi.max(l.abs()))
        });
    !(lo.is_finite() && hi.is_finite()) || lo <= NEARLY_SINGULAR * hi
}
