//! Out-of-plane instability of the planar elastica: the paper's diamonds
//! ([`OutOfPlane`], whose docs carry the derivation).

use core::f64::consts::PI;

use nalgebra::{DMatrix, DVector};

use super::solution::{Arm, Branch, Elastica, check_n};
use super::trace::Path;
use crate::Stiffness;
use crate::error::{Error, Result};
use crate::quadrature::GaussLegendre;
use crate::special::jacobi;

/// Collocation stages (order 2·STAGES).
const STAGES: usize = 6;
/// Unknowns of the out-of-plane system.
const DIM: usize = 5;
/// The diamonds are located to this absolute accuracy in k …
const K_TOLERANCE: f64 = 1e-10;
/// … and this relative accuracy in the force (the bracket's width; the
/// determinant's own resolution may be coarser, see the module docs).
const F_TOLERANCE: f64 = 1e-12;
/// Default relative tolerance of the integration.
const DEFAULT_TOLERANCE: f64 = 1e-13;
/// Default number of grid intervals along a branch.
const DEFAULT_GRID: usize = 256;
/// Most steps one integration may take.
const MAX_STEPS: usize = 100_000;

/// The out-of-plane stability problem of the planar elastica of n coils
/// for given stiffnesses (only A/B and C/B matter: the elastica is in units
/// of B).
///
/// The planar solutions of [`Elastica`] are equilibria of the 3D Kirchhoff
/// rod (the paper's eq. bal, eq. constit with u10 = u30 = 0, u20 = κ0 = 2πn,
/// B = 1) in the plane spanned by d1 and d3, with d2 the constant normal.
/// Where the linearised equations have a nontrivial out-of-plane solution
/// satisfying the zero-moment end conditions (eq. bcs), a branch of 3D
/// solutions crosses the planar branch: the pitchfork the paper marks with a
/// diamond on its Fig. spring ("the location of these diamonds, but not the
/// curves, depends on C").
///
/// # The planar base state
///
/// With u = u1 + Ωs and Jacobi functions of modulus k, the tangent
/// t = d3 = sin φ i + cos φ k makes the angle φ with the force F = F k
/// (F = k²Ω² the tension; the end s = 1 is pulled along +k), and
///
/// ```text
/// κ = φ′ = 2Ω dn u,   cos φ = 2 sn²u − 1,   sin φ = −2 sn u cn u       (eq4)
/// u_base = (0, κ, 0),   m_base = (0, κ − κ0, 0),   f = (f1, 0, f3)
/// f1 = F·d1 = −F sin φ,   f3 = F·d3 = F cos φ,   d1 = cos φ i − sin φ k,  d2 = j
/// ```
///
/// (components in the material frame; φ″ = F sin φ is the moment balance,
/// so the elastica's γ = cos ϑ is −cos φ). The ends have κ = κ0 (eq6), so
/// m_base vanishes there.
///
/// # The linearised out-of-plane equations
///
/// Perturb the frame by a small rotation ψ (δd_i = ψ × d_i, material
/// components ψ1, ψ2, ψ3), the moment by δm, the (constant) force by δF and
/// the centreline by δr. With δu = ψ′ + u × ψ, δm1 = A δu1, δm3 = C δu3,
/// δf = δF·d_i + F·(ψ × d_i), the balance laws m′ + u × m + e3 × f = 0,
/// f′ + u × f = 0 (eq. bal in the material frame) split into an in-plane
/// part (ψ2, δm2, δf1, δf3) and the out-of-plane part, in
/// y = (ψ1, ψ3, m1, m3, w) with m_i = δm_i, w = δr·j and P = δF·j:
///
/// ```text
/// ψ1′ = m1/A − κ ψ3
/// ψ3′ = m3/C + κ ψ1
/// m1′ = −(κ − (κ − κ0)/C) m3 + f3 ψ1 − f1 ψ3 + P        (δf2 = P + f3ψ1 − f1ψ3)
/// m3′ = (κ − (κ − κ0)/A) m1
/// w′  = −ψ1
/// ```
///
/// out-of-plane bending about d1 (A) coupled to twist (C) through the base
/// curvature κ and the prestress κ − κ0. The out-of-plane part of eq. bcs:
/// w = 0 at both ends, δM = 0 at both ends (δM = δm there since m_base = 0),
/// P free (the end's force is a reaction), and the rotation about k is
/// fixed (d1(1)·i = 0 in the paper; any gauge will do).
///
/// # The determinant
///
/// At s = 0 the data are m1 = m3 = w = 0 and three free values: ψ(0) in the
/// plane and P. Two of the three solutions are rigid motions of the whole
/// planar equilibrium, exact solutions of the system above:
///
/// - R_k: the rotation about the force line, ψ = k, m = 0, w = x(s), P = 0.
///   It meets every end condition: the symmetry the gauge removes.
/// - R_i: the rotation about i, ψ = i, m = 0, w = −z(s), P = −F (the force
///   turns with the rod). It meets all end conditions but w(1) = −Δz.
///
/// The third, Y_P, starts from ψ = 0 with P = 1. Along any solution the
/// spatial moment obeys δM′ = −δt × F − t × δF, so k·δM(s) = k·δM(0) − P x(s):
/// k·δM(1) = 0 holds by itself (x(1) = 0), and of δM(1) = 0 only
/// i·δM(1) = m1 cos φ + m3 sin φ is a condition. In the basis {R_i, Y_P} the
/// end conditions (i·δM(1), w(1)) have the determinant Δz · D with
///
/// ```text
/// D(k) = i·δM(1) of Y_P = m1(1) cos φ(1) + m3(1) sin φ(1)
/// ```
///
/// so away from Δz = 0 (the unstressed ring) the planar solution has an
/// out-of-plane neighbour exactly where D = 0. [`OutOfPlane::determinant`]
/// computes D; [`OutOfPlane::diamonds`] locates its sign changes along a
/// branch.
///
/// # Numerics
///
/// The system is integrated from s = 0 to 1 by Gauss–Legendre collocation
/// with six stages (order 12; the stage system of the linear ODE is solved
/// directly), with step-doubling error control to a relative tolerance
/// (default 1e-13 of the largest component). The coefficients come from
/// [`jacobi`] at the collocation nodes: no interpolation, no base-state
/// integration. Along a branch, D is sampled on a grid in the parameter σ of
/// [`Trace`](super::Trace) (q = −ln(1 − k²), σ² on secondary arms) and each
/// sign change is refined by the Illinois variant of regula falsi to
/// |Δk| ≤ 1e-10 and a bracket of 1e-12 relative in F (near k = 1, where
/// F ∝ K², a step of 1e-10 in k is a large step in F). Two sign changes closer than the grid spacing can be missed
/// (then raise [`OutOfPlane::grid`]).
///
/// # Checks
///
/// `tests/elastica/out_of_plane.rs`: the two rigid motions are reproduced by
/// the integrator, the first integrals k·δM = −P x and i·δM = P z − F w
/// (spatial balance, independent of the material-frame linearisation) hold
/// along Y_P, and the diamonds do not move when the tolerance changes.
/// `tests/rod/diamonds.rs`: the 3D rod at θ0 = 90° (quaternion collocation
/// and continuation, an independent model) has its branch points where D
/// vanishes.
///
/// # Example
///
/// ```
/// use hockle::{Stiffness, elastica::{Branch, OutOfPlane}};
/// let oop = OutOfPlane::new(4, Stiffness::nikolai(10.0, 0.05)?)?;
/// let d = oop.diamonds(Branch::Upsilon, 1.2)?;
/// // one diamond on the primary υ-branch below F/(2πn)² = 1.2
/// assert_eq!(d.len(), 1);
/// assert!((d[0].force_scaled() - 0.70456).abs() < 1e-4);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct OutOfPlane {
    n: u32,
    a: f64,
    c: f64,
    tolerance: f64,
    grid: usize,
    rule: Collocation,
}

/// One out-of-plane instability point (a diamond) of a planar branch.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Diamond {
    solution: Elastica,
}

impl Diamond {
    /// The planar solution at the diamond.
    #[must_use]
    pub fn solution(&self) -> Elastica {
        self.solution
    }

    /// Its modulus k.
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.solution.modulus()
    }

    /// The tension F (units of B/L²).
    #[must_use]
    pub fn force(&self) -> f64 {
        self.solution.force()
    }

    /// F/(2πn)².
    #[must_use]
    pub fn force_scaled(&self) -> f64 {
        self.solution.force_scaled()
    }

    /// The extension Δz.
    #[must_use]
    pub fn extension(&self) -> f64 {
        self.solution.extension()
    }

    /// The branch it lies on.
    #[must_use]
    pub fn branch(&self) -> Branch {
        self.solution.branch()
    }
}

impl core::fmt::Display for Diamond {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "diamond on {}: k = {}, F/(2πn)² = {}, Δz = {}",
            self.branch(),
            self.modulus(),
            self.force_scaled(),
            self.extension()
        )
    }
}

/// The Gauss collocation tableau for one step of a linear ODE.
#[derive(Debug, Clone, PartialEq)]
struct Collocation {
    c: [f64; STAGES],
    b: [f64; STAGES],
    /// a_ij = ∫0^{c_i} ℓ_j, ℓ_j the Lagrange basis on the nodes.
    a: [[f64; STAGES]; STAGES],
}

impl Collocation {
    fn new() -> Self {
        let rule = GaussLegendre::new(STAGES);
        let mut c = [0.0; STAGES];
        let mut b = [0.0; STAGES];
        c.copy_from_slice(&rule.nodes);
        b.copy_from_slice(&rule.weights);
        let lagrange = |j: usize, x: f64| -> f64 {
            (0..STAGES)
                .filter(|&l| l != j)
                .map(|l| (x - c[l]) / (c[j] - c[l]))
                .product()
        };
        // the same rule on [0, c_i] is exact for the degree STAGES − 1 basis
        let mut a = [[0.0; STAGES]; STAGES];
        for (i, row) in a.iter_mut().enumerate() {
            for (j, aij) in row.iter_mut().enumerate() {
                *aij = c[i]
                    * (0..STAGES)
                        .map(|l| b[l] * lagrange(j, c[i] * c[l]))
                        .sum::<f64>();
            }
        }
        Self { c, b, a }
    }
}

/// y′ = M(s) y + P g at one s.
struct Coefficients {
    m: [[f64; DIM]; DIM],
}

impl OutOfPlane {
    /// The problem for n coils with stiffnesses A, B, C (only A/B and C/B
    /// enter).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if n = 0.
    pub fn new(n: u32, stiffness: Stiffness) -> Result<Self> {
        check_n(n)?;
        Ok(Self {
            n,
            a: stiffness.a() / stiffness.b(),
            c: stiffness.c() / stiffness.b(),
            tolerance: DEFAULT_TOLERANCE,
            grid: DEFAULT_GRID,
            rule: Collocation::new(),
        })
    }

    /// The relative tolerance of the integration (default 1e-13).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless 1e-15 ≤ `tolerance` ≤ 1e-3.
    pub fn tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(1e-15..=1e-3).contains(&tolerance) {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                allowed: "a relative tolerance from 1e-15 to 1e-3",
            });
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// The number of grid intervals along a branch on which sign changes of
    /// D are sought (default 256).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] unless 2 ≤ `grid` ≤ 2²⁰.
    pub fn grid(mut self, grid: usize) -> Result<Self> {
        if !(2..=1 << 20).contains(&grid) {
            return Err(Error::InvalidCount {
                name: "grid",
                value: grid as u64,
                allowed: "from 2 to 2^20 grid intervals",
            });
        }
        self.grid = grid;
        Ok(self)
    }

    fn check_solution(&self, e: &Elastica) -> Result<()> {
        if e.coils() != self.n {
            return Err(Error::InvalidCount {
                name: "coils",
                value: u64::from(e.coils()),
                allowed: "a solution with the n coils this OutOfPlane was made for",
            });
        }
        Ok(())
    }

    fn coefficients(&self, e: &Elastica, s: f64) -> (Coefficients, f64, f64) {
        let j = jacobi(e.u1 + e.omega * s, e.modulus);
        let kappa = 2.0 * e.omega * j.dn;
        let kappa0 = 2.0 * PI * f64::from(self.n);
        let mu = kappa - kappa0;
        let cos_phi = 2.0 * j.sn * j.sn - 1.0;
        let sin_phi = -2.0 * j.sn * j.cn;
        let force = e.force();
        let (f1, f3) = (-force * sin_phi, force * cos_phi);
        let mut m = [[0.0; DIM]; DIM];
        m[0][1] = -kappa;
        m[0][2] = 1.0 / self.a;
        m[1][0] = kappa;
        m[1][3] = 1.0 / self.c;
        m[2][0] = f3;
        m[2][1] = -f1;
        m[2][3] = -(kappa - mu / self.c);
        m[3][2] = kappa - mu / self.a;
        m[4][0] = -1.0;
        (Coefficients { m }, cos_phi, sin_phi)
    }

    /// One collocation step of length h from (s, y).
    fn step(&self, e: &Elastica, s: f64, h: f64, y: &[f64; DIM], p: f64) -> Result<[f64; DIM]> {
        let n = STAGES * DIM;
        let coef: Vec<Coefficients> = self
            .rule
            .c
            .iter()
            .map(|&ci| self.coefficients(e, s + ci * h).0)
            .collect();
        // stage slopes K_i = M_i (y + h Σ_j a_ij K_j) + P g
        let mut mat = DMatrix::<f64>::identity(n, n);
        let mut rhs = DVector::<f64>::zeros(n);
        for i in 0..STAGES {
            let mi = &coef[i].m;
            for r in 0..DIM {
                rhs[i * DIM + r] = (0..DIM).map(|q| mi[r][q] * y[q]).sum::<f64>();
                if r == 2 {
                    rhs[i * DIM + r] += p;
                }
                for jst in 0..STAGES {
                    let aij = h * self.rule.a[i][jst];
                    for q in 0..DIM {
                        mat[(i * DIM + r, jst * DIM + q)] -= aij * mi[r][q];
                    }
                }
            }
        }
        let k = mat.lu().solve(&rhs).ok_or(Error::NonFinite {
            what: "out-of-plane collocation step",
            s,
        })?;
        let mut out = *y;
        for (i, bi) in self.rule.b.iter().enumerate() {
            for (r, o) in out.iter_mut().enumerate() {
                *o += h * bi * k[i * DIM + r];
            }
        }
        Ok(out)
    }

    /// Integrates the out-of-plane system along the solution `e` from s = 0
    /// with the data `start` = (ψ1, ψ3, m1, m3, w) (material components, see
    /// the [type docs](OutOfPlane)) and out-of-plane force P = `p` up to
    /// s = `end` ∈ [0, 1], and returns y(end).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `e` has another number of coils;
    /// [`Error::InvalidArgument`] for `end` outside [0, 1] or non-finite
    /// data; [`Error::NonFinite`] if the integration breaks down (or needs
    /// more than 10⁵ steps).
    pub fn integrate(&self, e: &Elastica, start: [f64; 5], p: f64, end: f64) -> Result<[f64; 5]> {
        self.check_solution(e)?;
        if !(0.0..=1.0).contains(&end) {
            return Err(Error::InvalidArgument {
                name: "end",
                value: end,
                allowed: "an arclength in [0, 1]",
            });
        }
        if let Some(bad) = start.iter().chain([&p]).find(|v| !v.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "start",
                value: *bad,
                allowed: "finite initial data and force",
            });
        }
        let mut y = start;
        let mut s = 0.0;
        // a first step resolving the curvature scale 1/(2Ω)
        let mut h = (0.5 / e.omega.max(1.0)).min(end.max(f64::MIN_POSITIVE));
        let order = (2 * STAGES + 1) as f64;
        for _ in 0..MAX_STEPS {
            if s >= end {
                return Ok(y);
            }
            h = h.min(end - s);
            let full = self.step(e, s, h, &y, p)?;
            let half = self.step(e, s, 0.5 * h, &y, p)?;
            let half = self.step(e, s + 0.5 * h, 0.5 * h, &half, p)?;
            let scale = half
                .iter()
                .chain(y.iter())
                .fold(1.0_f64, |a, v| a.max(v.abs()));
            let err = full
                .iter()
                .zip(&half)
                .fold(0.0_f64, |a, (x, z)| a.max((x - z).abs()))
                / scale;
            if !err.is_finite() {
                break;
            }
            let grow = if err == 0.0 {
                4.0
            } else {
                (0.8 * (self.tolerance / err).powf(1.0 / order)).clamp(0.2, 4.0)
            };
            if err <= self.tolerance {
                s = if end - s <= h { end } else { s + h };
                y = half;
            }
            h *= grow;
        }
        Err(Error::NonFinite {
            what: "out-of-plane integration",
            s,
        })
    }

    /// D at the planar solution `e`: the out-of-plane moment i·δM(1) left at
    /// the far end by the solution that starts with no rotation, moment or
    /// displacement under a unit out-of-plane force (see the
    /// [type docs](OutOfPlane)). D = 0 where `e` has an out-of-plane neighbour;
    /// D = O(k²) at the unstressed ring (k = 0), where Δz = 0 and the rigid
    /// rotation about i no longer turns the force.
    ///
    /// # Errors
    /// As [`OutOfPlane::integrate`].
    pub fn determinant(&self, e: &Elastica) -> Result<f64> {
        let y = self.integrate(e, [0.0; 5], 1.0, 1.0)?;
        let (_, cos_phi, sin_phi) = self.coefficients(e, 1.0);
        Ok(y[2] * cos_phi + y[3] * sin_phi)
    }

    /// The diamonds on `branch` (primary υ or α, a secondary arm, or ϑ_j —
    /// its first root of eq81, as in [`Trace`](super::Trace)) with
    /// F/(2πn)² ≤ `max_force_scaled`, in order along the branch from where
    /// it starts, each located to ≤ 1e-10 in k and a bracket of 1e-12
    /// relative in F.
    ///
    /// # Errors
    /// As [`Trace::run`](super::Trace::run) for the branch and the force
    /// limit; as [`OutOfPlane::integrate`].
    pub fn diamonds(&self, branch: Branch, max_force_scaled: f64) -> Result<Vec<Diamond>> {
        let path = Path::new(self.n, branch)?;
        let scale = (2.0 * PI * f64::from(self.n)).powi(2);
        let q_end = path.q_end(max_force_scaled, scale)?;
        let at = |sigma: f64| path.at_q(path.q_of(sigma, q_end));
        let eval = |sigma: f64| -> Result<(Elastica, f64)> {
            let e = at(sigma)?;
            Ok((e, self.determinant(&e)?))
        };
        let mut out = Vec::new();
        // At σ = 0 a secondary arm sits on its fold, where rounding may put
        // the modulus just below it: start at the first grid point that
        // solves. The unstressed ring (k = 0, where D = O(k²) vanishes with
        // Δz) is no diamond: skip it.
        let mut prev: Option<(f64, Elastica, f64)> = None;
        for i in 0..=self.grid {
            let sigma = i as f64 / self.grid as f64;
            let (e, d) = match eval(sigma) {
                Ok((e, _)) if e.modulus() == 0.0 => continue,
                Ok(v) => v,
                Err(_) if i == 0 => continue,
                Err(err) => return Err(err),
            };
            if let Some((s0, e0, d0)) = prev {
                if d == 0.0 {
                    out.push(Diamond { solution: e });
                } else if d0 != 0.0 && (d0 < 0.0) != (d < 0.0) {
                    out.push(self.refine(&at, (s0, e0, d0), (sigma, e, d))?);
                }
            } else if d == 0.0 {
                out.push(Diamond { solution: e });
            }
            prev = Some((sigma, e, d));
        }
        Ok(out
            .into_iter()
            .filter(|d| d.force_scaled() <= max_force_scaled * (1.0 + 1e-12))
            .collect())
    }

    /// Every diamond of the n-coil rod's planar branches up to
    /// `max_force_scaled`: primary υ and α, then secondary j = 1..n−1 (υ)
    /// on both arms.
    ///
    /// # Errors
    /// As [`OutOfPlane::diamonds`] (a branch that starts above the force
    /// limit is skipped).
    pub fn all_diamonds(&self, max_force_scaled: f64) -> Result<Vec<Diamond>> {
        let mut branches = vec![Branch::Upsilon, Branch::Alpha];
        for j in 1..self.n {
            for arm in [Arm::Lower, Arm::Upper] {
                branches.push(Branch::Secondary { j, arm });
            }
        }
        let mut out = Vec::new();
        for b in branches {
            match self.diamonds(b, max_force_scaled) {
                Ok(d) => out.extend(d),
                Err(Error::InvalidArgument {
                    name: "max_force_scaled",
                    ..
                }) => {}
                Err(e) => return Err(e),
            }
        }
        Ok(out)
    }

    /// Illinois regula falsi on σ until the bracket spans ≤ 1e-10 in k and
    /// ≤ 1e-12 relative in F (or σ's rounding).
    fn refine(
        &self,
        at: &impl Fn(f64) -> Result<Elastica>,
        lo: (f64, Elastica, f64),
        hi: (f64, Elastica, f64),
    ) -> Result<Diamond> {
        let (mut a, mut ea, mut fa) = lo;
        let (mut b, mut eb, mut fb) = hi;
        for _ in 0..200 {
            // near k = 1 a step of 1e-10 in k is a large step in F ∝ K²:
            // also close the bracket in the force
            if (eb.modulus() - ea.modulus()).abs() <= 0.5 * K_TOLERANCE
                && (eb.force() - ea.force()).abs() <= F_TOLERANCE * eb.force()
            {
                break;
            }
            let mut c = b - fb * (b - a) / (fb - fa);
            if !(c > a.min(b) && c < a.max(b)) {
                c = 0.5 * (a + b);
            }
            if c == a || c == b {
                break;
            }
            let ec = at(c)?;
            let fc = self.determinant(&ec)?;
            if fc == 0.0 {
                return Ok(Diamond { solution: ec });
            }
            if (fc < 0.0) != (fb < 0.0) {
                (a, ea, fa) = (b, eb, fb);
            } else {
                fa *= 0.5;
            }
            (b, eb, fb) = (c, ec, fc);
        }
        Ok(Diamond { solution: eb })
    }
}
