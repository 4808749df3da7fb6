//! Dense and sparse linear algebra for the solvers: the only module that
//! names faer, which never appears in a public signature.
//!
//! The dense kernels work in place on column-major slices so that the
//! collocation solver can keep every per-interval matrix in one flat buffer
//! and factor it without allocating.

/// Why a dense factorisation stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Breakdown {
    /// An exactly zero pivot in the given column.
    Singular(usize),
    /// A NaN or infinite pivot in the given column.
    NonFinite(usize),
}

/// Sign and log-magnitude of a determinant, accumulated over factorisations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Det {
    /// +1 or −1.
    pub sign: f64,
    /// ln |det|.
    pub log_abs: f64,
}

impl Det {
    pub(crate) const ONE: Det = Det {
        sign: 1.0,
        log_abs: 0.0,
    };

    pub(crate) fn mul(self, other: Det) -> Det {
        Det {
            sign: self.sign * other.sign,
            log_abs: self.log_abs + other.log_abs,
        }
    }
}

/// LU factorisation with partial pivoting of the first `k` columns of the
/// column-major `rows × cols` matrix `a` (`rows ≥ k`), applying every row
/// operation to all `cols` columns.
///
/// On return the top `k × k` block holds U (upper) and the multipliers of L
/// (below the diagonal, also in rows `k..rows`), and `piv[i]` is the row
/// swapped with row `i` at step `i`. Columns `k..cols` hold L⁻¹P applied to
/// them. Returns the determinant of the pivot block including the sign of the
/// row interchanges.
pub(crate) fn lu_panel(
    a: &mut [f64],
    rows: usize,
    cols: usize,
    k: usize,
    piv: &mut [usize],
) -> Result<Det, Breakdown> {
    debug_assert!(rows >= k && cols >= k && a.len() >= rows * cols);
    let mut det = Det::ONE;
    for kk in 0..k {
        let col = &a[kk * rows..kk * rows + rows];
        let mut p = kk;
        let mut best = col[kk].abs();
        for (i, v) in col.iter().enumerate().skip(kk + 1) {
            let v = v.abs();
            if v > best || v.is_nan() {
                best = v;
                p = i;
                if v.is_nan() {
                    break;
                }
            }
        }
        if !best.is_finite() {
            return Err(Breakdown::NonFinite(kk));
        }
        if best == 0.0 {
            return Err(Breakdown::Singular(kk));
        }
        piv[kk] = p;
        if p != kk {
            det.sign = -det.sign;
            for c in 0..cols {
                a.swap(c * rows + kk, c * rows + p);
            }
        }
        let pivot = a[kk * rows + kk];
        if pivot < 0.0 {
            det.sign = -det.sign;
        }
        det.log_abs += pivot.abs().ln();
        let inv = 1.0 / pivot;
        for v in &mut a[kk * rows + kk + 1..kk * rows + rows] {
            *v *= inv;
        }
        let (left, right) = a.split_at_mut((kk + 1) * rows);
        let lcol = &left[kk * rows + kk + 1..kk * rows + rows];
        for c in 0..cols - kk - 1 {
            let cc = &mut right[c * rows..c * rows + rows];
            let f = cc[kk];
            if f != 0.0 {
                for (x, l) in cc[kk + 1..].iter_mut().zip(lcol) {
                    *x -= l * f;
                }
            }
        }
    }
    Ok(det)
}

/// Applies the row interchanges and L⁻¹ of a [`lu_panel`] factorisation to
/// the vector `v` (length `rows`).
pub(crate) fn apply_lower(a: &[f64], rows: usize, k: usize, piv: &[usize], v: &mut [f64]) {
    // The multipliers were swapped along with later pivots (LAPACK
    // convention): apply every interchange first, then L⁻¹.
    for (kk, &p) in piv[..k].iter().enumerate() {
        if p != kk {
            v.swap(kk, p);
        }
    }
    for kk in 0..k {
        let f = v[kk];
        if f != 0.0 {
            let lcol = &a[kk * rows + kk + 1..kk * rows + rows];
            for (x, l) in v[kk + 1..rows].iter_mut().zip(lcol) {
                *x -= l * f;
            }
        }
    }
}

/// Solves U x = v in place with the upper `k × k` block of `a` (leading
/// dimension `rows`).
pub(crate) fn solve_upper(a: &[f64], rows: usize, k: usize, v: &mut [f64]) {
    for kk in (0..k).rev() {
        let x = v[kk] / a[kk * rows + kk];
        v[kk] = x;
        if x != 0.0 {
            let ucol = &a[kk * rows..kk * rows + kk];
            for (y, u) in v[..kk].iter_mut().zip(ucol) {
                *y -= u * x;
            }
        }
    }
}

/// Solves s U = c in place for the row vector `s` (U the upper `k × k`
/// block of `a`, leading dimension `rows`).
pub(crate) fn solve_upper_left(a: &[f64], rows: usize, k: usize, s: &mut [f64]) {
    for kk in 0..k {
        let ucol = &a[kk * rows..kk * rows + kk];
        let mut x = s[kk];
        for (y, u) in s[..kk].iter().zip(ucol) {
            x -= y * u;
        }
        s[kk] = x / a[kk * rows + kk];
    }
}

/// Scratch memory for faer's dense LU (allocated once, reused).
pub(crate) struct DenseWorkspace {
    buf: faer::dyn_stack::MemBuffer,
}

impl DenseWorkspace {
    pub(crate) fn new(n: usize, rhs_cols: usize) -> Self {
        use faer::linalg::lu::partial_pivoting::{factor, solve};
        let req =
            factor::lu_in_place_scratch::<usize, f64>(n, n, faer::Par::Seq, Default::default()).or(
                solve::solve_in_place_scratch::<usize, f64>(n, rhs_cols.max(1), faer::Par::Seq),
            );
        DenseWorkspace {
            buf: faer::dyn_stack::MemBuffer::new(req),
        }
    }
}

/// LU with partial pivoting (faer, SIMD kernels chosen at run time) of the
/// leading `n × n` block of the column-major `n × cols` matrix `a`; the other
/// `cols − n` columns are overwritten with the block's inverse applied to
/// them. `perm`/`perm_inv` (length n) receive the row permutation. Returns
/// the determinant of the block.
pub(crate) fn lu_solve_block(
    a: &mut [f64],
    n: usize,
    cols: usize,
    perm: &mut [usize],
    perm_inv: &mut [usize],
    ws: &mut DenseWorkspace,
) -> Result<Det, Breakdown> {
    use faer::linalg::lu::partial_pivoting::{factor, solve};
    use faer::reborrow::{Reborrow, ReborrowMut};
    let stack = faer::dyn_stack::MemStack::new(&mut ws.buf);
    let (lu_part, rhs_part) = a.split_at_mut(n * n);
    let mut lu = faer::MatMut::from_column_major_slice_mut(lu_part, n, n);
    let (info, pr) = factor::lu_in_place(
        lu.rb_mut(),
        perm,
        perm_inv,
        faer::Par::Seq,
        stack,
        Default::default(),
    );
    let mut det = Det {
        sign: if info.transposition_count % 2 == 0 {
            1.0
        } else {
            -1.0
        },
        log_abs: 0.0,
    };
    for i in 0..n {
        let d = lu[(i, i)];
        if !d.is_finite() {
            return Err(Breakdown::NonFinite(i));
        }
        if d == 0.0 {
            return Err(Breakdown::Singular(i));
        }
        if d < 0.0 {
            det.sign = -det.sign;
        }
        det.log_abs += d.abs().ln();
    }
    if cols > n {
        let rhs =
            faer::MatMut::from_column_major_slice_mut(&mut rhs_part[..n * (cols - n)], n, cols - n);
        let stack = faer::dyn_stack::MemStack::new(&mut ws.buf);
        solve::solve_in_place_with_conj(
            lu.rb(),
            lu.rb(),
            pr,
            faer::Conj::No,
            rhs,
            faer::Par::Seq,
            stack,
        );
    }
    Ok(det)
}

/// The eigenvalues, ascending, of the symmetric column-major `n × n` matrix
/// `a` (faer's self-adjoint eigensolver, reading the lower triangle);
/// `None` if it does not converge.
pub(crate) fn symmetric_eigenvalues(a: &[f64], n: usize) -> Option<Vec<f64>> {
    let m = faer::MatRef::from_column_major_slice(a, n, n);
    m.self_adjoint_eigenvalues(faer::Side::Lower).ok()
}

/// Solves with a [`lu_solve_block`] factorisation for one vector `v`
/// (`tmp` is scratch of length n).
pub(crate) fn lu_solve_vec(a: &[f64], n: usize, perm: &[usize], v: &mut [f64], tmp: &mut [f64]) {
    for i in 0..n {
        tmp[i] = v[perm[i]];
    }
    for k in 0..n {
        let x = tmp[k];
        if x != 0.0 {
            let col = &a[k * n + k + 1..k * n + n];
            for (t, l) in tmp[k + 1..n].iter_mut().zip(col) {
                *t -= l * x;
            }
        }
    }
    solve_upper(a, n, n, tmp);
    v[..n].copy_from_slice(&tmp[..n]);
}

/// The sparsity pattern of a square sparse matrix with its symbolic LU
/// (column ordering and elimination structure): computed once per pattern,
/// then [`factor`](Self::factor) costs one numeric factorisation per matrix
/// with that pattern (faer's symbolic/numeric split).
pub(crate) struct SparsePattern {
    n: usize,
    entries: Vec<(usize, usize)>,
    symbolic: faer::sparse::SymbolicSparseColMat<usize>,
    argsort: faer::sparse::Argsort<usize>,
    lu: faer::sparse::linalg::solvers::SymbolicLu<usize>,
}

impl SparsePattern {
    /// The pattern of the `n × n` matrix whose entries (row, column) are
    /// listed (duplicates are summed by [`factor`](Self::factor)). `None`
    /// if an index is out of range or faer cannot analyse it.
    pub(crate) fn new(n: usize, entries: &[(usize, usize)]) -> Option<SparsePattern> {
        use faer::sparse::{Pair, SymbolicSparseColMat};
        let idx: Vec<Pair<usize, usize>> = entries
            .iter()
            .map(|&(row, col)| Pair { row, col })
            .collect();
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(n, n, &idx).ok()?;
        let lu = faer::sparse::linalg::solvers::SymbolicLu::try_new(symbolic.as_ref()).ok()?;
        Some(SparsePattern {
            n,
            entries: entries.to_vec(),
            symbolic,
            argsort,
            lu,
        })
    }

    /// Whether this is the pattern of `n` and `entries`.
    pub(crate) fn is(&self, n: usize, entries: &[(usize, usize)]) -> bool {
        self.n == n && self.entries == entries
    }

    /// The numeric LU with partial pivoting of the matrix with this pattern
    /// and `values` (one per entry, in the order the entries were given).
    pub(crate) fn factor(&self, values: &[f64]) -> Option<SparseLu> {
        use faer::sparse::SparseColMat;
        use faer::sparse::linalg::solvers::Lu;
        if values.len() != self.entries.len() {
            return None;
        }
        let mat =
            SparseColMat::new_from_argsort(self.symbolic.clone(), &self.argsort, values).ok()?;
        let lu = Lu::try_new_with_symbolic(self.lu.clone(), mat.as_ref()).ok()?;
        Some(SparseLu { mat, lu })
    }
}

/// A numeric sparse LU and the matrix it factors.
pub(crate) struct SparseLu {
    mat: faer::sparse::SparseColMat<usize, f64>,
    lu: faer::sparse::linalg::solvers::Lu<usize, f64>,
}

impl SparseLu {
    /// Solves A x = b. `None` when the solution is not finite or its
    /// residual is not small (faer can return `inf` silently on singular
    /// matrices).
    pub(crate) fn solve(&self, b: &[f64]) -> Option<Vec<f64>> {
        use faer::linalg::solvers::SolveCore;
        let n = b.len();
        let mut rhs = faer::Mat::<f64>::from_fn(n, 1, |i, _| b[i]);
        self.lu
            .solve_in_place_with_conj(faer::Conj::No, rhs.as_mut());
        let x: Vec<f64> = (0..n).map(|i| rhs[(i, 0)]).collect();
        if x.iter().any(|v| !v.is_finite()) {
            return None;
        }
        // Residual check: ‖Ax − b‖∞ ≤ 1e-8 (‖A‖∞‖x‖∞ + ‖b‖∞).
        let mut r: Vec<f64> = b.iter().map(|v| -v).collect();
        let mut row_norm = vec![0.0_f64; n];
        let a = self.mat.as_ref();
        let (col_ptr, row_idx, val) = (a.symbolic().col_ptr(), a.symbolic().row_idx(), a.val());
        for (j, xj) in x.iter().enumerate() {
            for p in col_ptr[j]..col_ptr[j + 1] {
                let i = row_idx[p];
                r[i] += val[p] * xj;
                row_norm[i] += val[p].abs();
            }
        }
        let an = row_norm.iter().fold(0.0_f64, |m, v| m.max(*v));
        let xn = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let bn = b.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let rn = r.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        (rn <= 1e-8 * (an * xn + bn)).then_some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_lu_solves_and_determinant() {
        // A = [[0, 2, 1], [1, 1, 0], [3, 0, 1]] (column-major below), det = -5.
        let mut a = vec![0.0, 1.0, 3.0, 2.0, 1.0, 0.0, 1.0, 0.0, 1.0];
        let mut piv = [0usize; 3];
        let det = lu_panel(&mut a, 3, 3, 3, &mut piv).unwrap();
        assert_eq!(det.sign, -1.0);
        assert!((det.log_abs - 5.0_f64.ln()).abs() < 1e-14);
        // b = A (1, 2, 3)ᵀ = (7, 3, 6)
        let mut v = [7.0, 3.0, 6.0];
        apply_lower(&a, 3, 3, &piv, &mut v);
        solve_upper(&a, 3, 3, &mut v);
        for (x, e) in v.iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - e).abs() < 1e-14);
        }
    }

    #[test]
    fn singular_is_reported() {
        let mut a = vec![1.0, 2.0, 2.0, 4.0];
        let mut piv = [0usize; 2];
        assert!(matches!(
            lu_panel(&mut a, 2, 2, 2, &mut piv),
            Err(Breakdown::Singular(1))
        ));
    }

    #[test]
    fn sparse_matches_dense() {
        let e = [
            (0, 1, 2.0),
            (0, 2, 1.0),
            (1, 0, 1.0),
            (1, 1, 1.0),
            (2, 0, 3.0),
            (2, 2, 1.0),
        ];
        let solve = |n: usize, e: &[(usize, usize, f64)], b: &[f64]| {
            let idx: Vec<(usize, usize)> = e.iter().map(|&(i, j, _)| (i, j)).collect();
            let val: Vec<f64> = e.iter().map(|t| t.2).collect();
            SparsePattern::new(n, &idx)?.factor(&val)?.solve(b)
        };
        let x = solve(3, &e, &[7.0, 3.0, 6.0]).unwrap();
        for (x, e) in x.iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - e).abs() < 1e-13);
        }
        let singular = [(0, 0, 1.0), (0, 1, 2.0), (1, 0, 2.0), (1, 1, 4.0)];
        assert!(solve(2, &singular, &[1.0, 1.0]).is_none());
        // One pattern, two matrices: duplicates are summed, values follow
        // the entry order. A = [[2, 1], [1, 3]] then [[4, 0], [1, 1]].
        let idx = [(0, 0), (1, 0), (0, 1), (1, 1), (0, 0)];
        let pattern = SparsePattern::new(2, &idx).unwrap();
        let x = pattern
            .factor(&[1.0, 1.0, 1.0, 3.0, 1.0])
            .unwrap()
            .solve(&[3.0, 4.0])
            .unwrap();
        assert!((x[0] - 1.0).abs() < 1e-14 && (x[1] - 1.0).abs() < 1e-14);
        let x = pattern
            .factor(&[3.0, 1.0, 0.0, 1.0, 1.0])
            .unwrap()
            .solve(&[4.0, 3.0])
            .unwrap();
        assert!((x[0] - 1.0).abs() < 1e-14 && (x[1] - 2.0).abs() < 1e-14);
    }
}

#[cfg(test)]
mod random_tests {
    use super::*;

    #[test]
    fn faer_block_matches_panel() {
        let n = 12;
        let cols = 15;
        let a0: Vec<f64> = (0..n * cols)
            .map(|i| ((i * i) as f64 * 0.37 + 1.3).sin())
            .collect();
        let mut a = a0.clone();
        let mut b = a0.clone();
        let mut piv = vec![0; n];
        let d1 = lu_panel(&mut a, n, cols, n, &mut piv).unwrap();
        let (lu, extra) = a.split_at_mut(n * n);
        for col in extra.chunks_exact_mut(n) {
            solve_upper(lu, n, n, col);
        }
        let mut perm = vec![0; n];
        let mut perm_inv = vec![0; n];
        let mut ws = DenseWorkspace::new(n, cols - n);
        let d2 = lu_solve_block(&mut b, n, cols, &mut perm, &mut perm_inv, &mut ws).unwrap();
        assert_eq!(d1.sign, d2.sign);
        assert!((d1.log_abs - d2.log_abs).abs() < 1e-12);
        for i in n * n..n * cols {
            assert!((a[i] - b[i]).abs() < 1e-10, "{i}: {} vs {}", a[i], b[i]);
        }
        // Vector solve: A x = e_0 against the panel path.
        let mut v = vec![0.0; n];
        v[0] = 1.0;
        let mut w = v.clone();
        apply_lower(&a, n, n, &piv, &mut v);
        solve_upper(&a, n, n, &mut v);
        let mut tmp = vec![0.0; n];
        lu_solve_vec(&b, n, &perm, &mut w, &mut tmp);
        for i in 0..n {
            assert!((v[i] - w[i]).abs() < 1e-10);
        }
    }

    #[test]
    fn random_10() {
        let n = 10;
        let mut a: Vec<f64> = (0..n * n)
            .map(|i| ((i * i) as f64 * 0.37 + 1.3).sin())
            .collect();
        let a0 = a.clone();
        let b: Vec<f64> = (0..n).map(|i| i as f64 - 3.0).collect();
        let mut piv = vec![0; n];
        lu_panel(&mut a, n, n, n, &mut piv).unwrap();
        let mut x = b.clone();
        apply_lower(&a, n, n, &piv, &mut x);
        solve_upper(&a, n, n, &mut x);
        for i in 0..n {
            let s: f64 = (0..n).map(|j| a0[j * n + i] * x[j]).sum();
            assert!((s - b[i]).abs() < 1e-10, "row {i}: {s} vs {}", b[i]);
        }
    }
}

#[cfg(test)]
mod timing {
    use super::*;

    #[test]
    #[ignore = "timing probe: cargo test --release --lib timing -- --ignored --nocapture"]
    fn lu_52() {
        let (n, cols) = (52, 66);
        let a0: Vec<f64> = (0..n * cols)
            .map(|i| ((i * i) as f64 * 0.37 + 1.3).sin() + if i % (n + 1) == 0 { 5.0 } else { 0.0 })
            .collect();
        let mut piv = vec![0; n];
        let mut perm_inv = vec![0; n];
        let mut ws = DenseWorkspace::new(n, cols - n);
        let reps = 2000;
        let mut a = a0.clone();
        let t = std::time::Instant::now();
        for _ in 0..reps {
            a.copy_from_slice(&a0);
            lu_panel(&mut a, n, cols, n, &mut piv).unwrap();
            let (lu, extra) = a.split_at_mut(n * n);
            for col in extra.chunks_exact_mut(n) {
                solve_upper(lu, n, n, col);
            }
        }
        let t1 = t.elapsed().as_secs_f64() / reps as f64;
        let t = std::time::Instant::now();
        for _ in 0..reps {
            a.copy_from_slice(&a0);
            lu_solve_block(&mut a, n, cols, &mut piv, &mut perm_inv, &mut ws).unwrap();
        }
        let t2 = t.elapsed().as_secs_f64() / reps as f64;
        eprintln!("own {:.1} µs, faer {:.1} µs", t1 * 1e6, t2 * 1e6);
    }
}
