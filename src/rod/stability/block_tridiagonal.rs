//! The discrete rod's Hessian as 3 × 3 blocks ([`BlockTridiagonal`]).

use nalgebra::{DMatrix, Matrix3};

/// A symmetric block-tridiagonal matrix in 3 × 3 blocks, one block row
/// per segment: the discrete rod's Hessian (each node's energy couples two
/// neighbouring segments; the load's, one), in O(N) memory.
pub(super) struct BlockTridiagonal {
    /// H_ii.
    pub(super) diag: Vec<Matrix3<f64>>,
    /// H_{i,i+1} (H_{i+1,i} is its transpose).
    pub(super) upper: Vec<Matrix3<f64>>,
}

impl BlockTridiagonal {
    pub(super) fn zeros(segments: usize) -> Self {
        Self {
            diag: vec![Matrix3::zeros(); segments],
            upper: vec![Matrix3::zeros(); segments.saturating_sub(1)],
        }
    }

    /// The order, 3 per segment.
    pub(super) fn size(&self) -> usize {
        3 * self.diag.len()
    }

    /// The entry (i, j).
    pub(super) fn get(&self, i: usize, j: usize) -> f64 {
        let (bi, bj) = (i / 3, j / 3);
        if bi == bj {
            self.diag[bi][(i % 3, j % 3)]
        } else if bj == bi + 1 {
            self.upper[bi][(i % 3, j % 3)]
        } else if bi == bj + 1 {
            self.upper[bj][(j % 3, i % 3)]
        } else {
            0.0
        }
    }

    /// Adds `v` at (i, j) for j in the same or the next block row (the
    /// upper triangle of the blocks; the lower is its transpose).
    pub(super) fn add_upper(&mut self, i: usize, j: usize, v: f64) {
        let (bi, bj) = (i / 3, j / 3);
        if bi == bj {
            self.diag[bi][(i % 3, j % 3)] += v;
        } else if bj == bi + 1 {
            self.upper[bi][(i % 3, j % 3)] += v;
        }
    }

    /// The dense matrix (for the eigenvalues of `second_variation`).
    pub(super) fn to_dense(&self) -> DMatrix<f64> {
        let n = self.size();
        DMatrix::from_fn(n, n, |i, j| self.get(i, j))
    }
}
