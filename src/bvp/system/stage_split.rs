//! The interval block's passive components: constants and quadratures.
//!
//! The stage block W_j = I − h_j (a ⊗ I) diag(J_jk) has entries
//! δ_kl δ_ic − h a_kl J_jk[i, c] in row (k, i), column (l, c). Two kinds of
//! components make it simpler than it looks:
//!
//! - a **constant** i, whose row of every J_jk is zero (y_i′ does not depend
//!   on y, only on s and p; the rod's force, F′ = 0), has unit rows:
//!   dK_ki = b_ki;
//! - a **quadrature** c, whose column of every J_jk is zero (no y′ depends
//!   on y_c; the rod's position, r′ = d₃(q)), has unit columns.
//!
//! Ordered core, constants, quadratures (the same order for rows and
//! columns), W_j is block lower triangular with identity blocks on the
//! diagonal but the core's:
//!
//! ```text
//!   ⎡ W_cc  W_cf  0 ⎤
//!   ⎢  0     I    0 ⎥     det W_j = det W_cc,
//!   ⎣ W_rc  W_rf  I ⎦
//! ```
//!
//! so W_j x = b is solved exactly by x_f = b_f, W_cc x_c = b_c − W_cf x_f,
//! x_r = b_r − W_rc x_c − W_rf x_f. Only the (m n_c)² core is factored: on
//! the rod (13 components: 3 quadratures, 3 constants) that is
//! (7/13)³ ≈ 1/6 of the work of W_j. The components are classified per
//! interval by the exact zeros of its Jacobians, so the factorisation is
//! of the same matrix (a zero that is only accidental at this state is
//! still exact); with no passive component the full block is factored as
//! before.
//!
//! The packed form that replaces W_j in the system (column-major blocks,
//! one after the other): the LU of W_cc (m n_c square), W_cf
//! (m n_c × m n_f), and [W_rc W_rf] (m n_r × m (n_c + n_f)); their sizes add
//! up to less than (m n)².

use super::condense::SMALL_BLOCK;
use crate::linalg::{
    Breakdown, DenseWorkspace, Det, apply_lower, lu_panel, lu_solve_block, lu_solve_vec,
    solve_upper,
};

/// The components of one interval in the order core, constants,
/// quadratures, with the two first counts.
#[derive(Debug, Clone, Copy)]
pub(super) struct Split<'a> {
    /// Component indices: `core` core ones, then `constants`, then the
    /// quadratures.
    pub comps: &'a [usize],
    pub core: usize,
    pub constants: usize,
    /// Stages m.
    pub m: usize,
}

impl Split<'_> {
    fn n(&self) -> usize {
        self.comps.len()
    }

    /// Whether the interval has a passive component (else its block is
    /// factored whole).
    pub(super) fn is_reduced(&self) -> bool {
        self.core < self.n()
    }

    fn quadratures(&self) -> usize {
        self.n() - self.core - self.constants
    }

    /// Rows of W_cc (m n_c), of W_cf's columns (m n_f) and of the
    /// quadrature rows (m n_r).
    fn sizes(&self) -> (usize, usize, usize) {
        (
            self.m * self.core,
            self.m * self.constants,
            self.m * self.quadratures(),
        )
    }
}

/// Orders the components of an interval whose Jacobians have a nonzero
/// in row i (`row_nz[i]`) and in column c (`col_nz[c]`): the core, then
/// the constants (zero rows), then the quadratures (zero columns, nonzero
/// rows), into `comps`. Returns the numbers of core components and of
/// constants.
pub(super) fn classify(row_nz: &[bool], col_nz: &[bool], comps: &mut [usize]) -> (usize, usize) {
    let n = row_nz.len();
    let is_core = |i: &usize| row_nz[*i] && col_nz[*i];
    let is_constant = |i: &usize| !row_nz[*i];
    let is_quadrature = |i: &usize| row_nz[*i] && !col_nz[*i];
    let order = (0..n)
        .filter(is_core)
        .chain((0..n).filter(is_constant))
        .chain((0..n).filter(is_quadrature));
    for (slot, i) in comps.iter_mut().zip(order) {
        *slot = i;
    }
    (
        (0..n).filter(is_core).count(),
        (0..n).filter(is_constant).count(),
    )
}

/// Packs the raw W_j (the first (m n)² values of `wa`, column-major) into
/// the packed form (module docs) at the front of `wa`, factoring W_cc, and
/// overwrites the right-hand sides that follow it in `wa` (columns of
/// length m n) with W_j⁻¹ times them; the core's columns are solved
/// together, on W_cc's factorisation (faer's blocked solve). `scratch`
/// holds at least m n (1 + the columns of `wa`), `piv` and `pinv` m n.
/// Returns det W_j.
pub(super) fn pack_and_solve(
    wa: &mut [f64],
    split: Split<'_>,
    piv: &mut [usize],
    pinv: &mut [usize],
    dense: &mut DenseWorkspace,
    scratch: &mut [f64],
) -> Result<Det, Breakdown> {
    let (n, m) = (split.n(), split.m);
    let mn = m * n;
    let (mc, mf, mr) = split.sizes();
    let (core, rest) = split.comps.split_at(split.core);
    let (constants, quadratures) = rest.split_at(split.constants);
    let nr = quadratures.len();
    let ncols = wa.len() / mn - mn;
    let (w, rhs) = wa.split_at_mut(mn * mn);
    let raw = |k: usize, i: usize, l: usize, c: usize| w[(l * n + c) * mn + k * n + i];
    // scratch: [W_cc | core rows of the right-hand sides] (mc rows), then
    // W_cf and [W_rc W_rf]
    let (block, rest) = scratch.split_at_mut(mc * (mc + ncols));
    let (wcf, rest) = rest.split_at_mut(mc * mf);
    let (wr, rest) = rest.split_at_mut(mr * (mc + mf));
    for l in 0..m {
        for (b, &c) in core.iter().enumerate() {
            let col = l * split.core + b;
            for k in 0..m {
                for (a, &i) in core.iter().enumerate() {
                    block[col * mc + k * split.core + a] = raw(k, i, l, c);
                }
                for (a, &i) in quadratures.iter().enumerate() {
                    wr[col * mr + k * nr + a] = raw(k, i, l, c);
                }
            }
        }
        for (b, &c) in constants.iter().enumerate() {
            let col = l * split.constants + b;
            for k in 0..m {
                for (a, &i) in core.iter().enumerate() {
                    wcf[col * mc + k * split.core + a] = raw(k, i, l, c);
                }
                for (a, &i) in quadratures.iter().enumerate() {
                    wr[(mc + col) * mr + k * nr + a] = raw(k, i, l, c);
                }
            }
        }
    }
    // b_c − W_cf b_f for every right-hand side
    for (col, b) in rhs.chunks_exact(mn).enumerate() {
        let out = &mut block[(mc + col) * mc..(mc + col + 1) * mc];
        gather_core(b, split, out);
        subtract_constants(b, split, wcf, out);
    }
    let det = if mc <= SMALL_BLOCK {
        lu_panel(block, mc, mc + ncols, mc, piv).inspect(|_| {
            let (lu, extra) = block.split_at_mut(mc * mc);
            for col in extra.chunks_exact_mut(mc.max(1)) {
                solve_upper(lu, mc, mc, col);
            }
        })
    } else {
        lu_solve_block(
            block,
            mc,
            mc + ncols,
            &mut piv[..mc],
            &mut pinv[..mc],
            dense,
        )
    }?;
    let (lu, solved) = block.split_at(mc * mc);
    let xr = &mut rest[..mr];
    for (col, b) in rhs.chunks_exact_mut(mn).enumerate() {
        scatter_core(&solved[col * mc..(col + 1) * mc], split, b);
        solve_quadratures(b, split, wr, xr);
    }
    let packed = [lu, &*wcf, &*wr];
    let mut at = 0;
    for part in packed {
        w[at..at + part.len()].copy_from_slice(part);
        at += part.len();
    }
    Ok(det)
}

/// The core rows of `x` (stage-major) into `out` (m n_c).
fn gather_core(x: &[f64], split: Split<'_>, out: &mut [f64]) {
    let n = split.n();
    for k in 0..split.m {
        for (a, &i) in split.comps[..split.core].iter().enumerate() {
            out[k * split.core + a] = x[k * n + i];
        }
    }
}

/// The core rows `xc` (m n_c) into `x` (stage-major).
fn scatter_core(xc: &[f64], split: Split<'_>, x: &mut [f64]) {
    let n = split.n();
    for k in 0..split.m {
        for (a, &i) in split.comps[..split.core].iter().enumerate() {
            x[k * n + i] = xc[k * split.core + a];
        }
    }
}

/// `out` −= W_cf x_f.
fn subtract_constants(x: &[f64], split: Split<'_>, wcf: &[f64], out: &mut [f64]) {
    let n = split.n();
    let mc = split.m * split.core;
    let constants = &split.comps[split.core..split.core + split.constants];
    for l in 0..split.m {
        for (b, &c) in constants.iter().enumerate() {
            let v = x[l * n + c];
            if v != 0.0 {
                let col = &wcf[(l * split.constants + b) * mc..][..mc];
                for (o, wv) in out.iter_mut().zip(col) {
                    *o -= wv * v;
                }
            }
        }
    }
}

/// x_r = b_r − W_rc x_c − W_rf x_f in place in `x` (whose core and
/// constant rows are solved); `xr` is scratch of length m n_r.
fn solve_quadratures(x: &mut [f64], split: Split<'_>, wr: &[f64], xr: &mut [f64]) {
    let n = split.n();
    let (_, _, mr) = split.sizes();
    if mr == 0 {
        return;
    }
    let core = &split.comps[..split.core];
    let constants = &split.comps[split.core..split.core + split.constants];
    let quadratures = &split.comps[split.core + split.constants..];
    let nr = quadratures.len();
    let xr = &mut xr[..mr];
    for k in 0..split.m {
        for (a, &i) in quadratures.iter().enumerate() {
            xr[k * nr + a] = x[k * n + i];
        }
    }
    let mut col = 0;
    for part in [core, constants] {
        for l in 0..split.m {
            for &c in part {
                let v = x[l * n + c];
                if v != 0.0 {
                    for (xv, wv) in xr.iter_mut().zip(&wr[col * mr..(col + 1) * mr]) {
                        *xv -= wv * v;
                    }
                }
                col += 1;
            }
        }
    }
    for k in 0..split.m {
        for (a, &i) in quadratures.iter().enumerate() {
            x[k * n + i] = xr[k * nr + a];
        }
    }
}

/// Solves W_j x = b in place (`x` holds b, length m n) with the packed form
/// `packed` of [`pack_and_solve`]; `tmp` is scratch of length 2 m n.
pub(super) fn solve(
    packed: &[f64],
    piv: &[usize],
    split: Split<'_>,
    x: &mut [f64],
    tmp: &mut [f64],
) {
    let (mc, mf, mr) = split.sizes();
    let (lu, rest) = packed.split_at(mc * mc);
    let (wcf, rest) = rest.split_at(mc * mf);
    let wr = &rest[..mr * (mc + mf)];
    let (xc, rest) = tmp.split_at_mut(mc);
    let (work, xr) = rest.split_at_mut(mc);
    gather_core(x, split, xc);
    subtract_constants(x, split, wcf, xc);
    if mc <= SMALL_BLOCK {
        apply_lower(lu, mc, mc, piv, xc);
        solve_upper(lu, mc, mc, xc);
    } else {
        lu_solve_vec(lu, mc, piv, xc, work);
    }
    scatter_core(xc, split, x);
    solve_quadratures(x, split, wr, xr);
}
