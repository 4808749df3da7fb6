//! [`Elastica`]: one solution, its force, extension, energy and shape.

use core::f64::consts::PI;

use nalgebra::Point2;

use super::integrals::{SMALL_M, i_between, i_period};
use crate::error::{Error, Result, check_points};
use crate::quadrature::gauss_legendre;
use crate::special::{FixedModulus, Jacobi, Modulus, ellip_e, ellip_e_inc, jacobi, jacobi_epsilon};

/// The shape class of a solution (the paper's Greek letters).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Shape {
    /// υ: an opened coil, ends near curvature maxima.
    Upsilon,
    /// α: a tightened coil, ends near curvature minima.
    Alpha,
    /// ϑ: non-symmetric, a whole number j of periods.
    Theta,
}

impl core::fmt::Display for Shape {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::Upsilon => "υ",
            Self::Alpha => "α",
            Self::Theta => "ϑ",
        })
    }
}

/// One of the two arms of a secondary symmetric branch, which meet at its
/// fold (the smallest k on the branch).
///
/// At equal k the `Lower` arm has the smaller Ω (fewer curvature periods).
/// The bifurcation point with ϑ_j lies on the `Lower` arm for j < n (υ) and
/// on the `Upper` arm for j > n (α): see [`Arm::bifurcating`]. As k → 1 the
/// υ arms approach ϑ_(j−1) (`Lower`, a coil lost) and ϑ_(j+1) (`Upper`, a
/// coil gained); both α arms approach ϑ_j.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Arm {
    /// Smaller Ω at equal k.
    Lower,
    /// Larger Ω at equal k.
    Upper,
}

impl Arm {
    /// The arm that carries the bifurcation point with ϑ_j: `Lower` for
    /// j < n, `Upper` for j > n (for j = n there is no secondary branch;
    /// `Lower` is returned).
    #[must_use]
    pub fn bifurcating(n: u32, j: u32) -> Self {
        if j > n { Self::Upper } else { Self::Lower }
    }

    /// The other arm.
    #[must_use]
    pub fn other(self) -> Self {
        match self {
            Self::Lower => Self::Upper,
            Self::Upper => Self::Lower,
        }
    }
}

impl core::fmt::Display for Arm {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::Lower => "lower arm",
            Self::Upper => "upper arm",
        })
    }
}

/// Which branch a solution lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Branch {
    /// The primary symmetric υ-branch through the unstressed ring.
    Upsilon,
    /// The primary symmetric α-branch through the unstressed ring.
    Alpha,
    /// The non-symmetric ϑ-branch with j periods (Ω = 2jK).
    Theta {
        /// Number of periods on the rod.
        j: u32,
    },
    /// The secondary symmetric branch born at ϑ_j (υ for j < n, α for j > n).
    Secondary {
        /// The ϑ-branch it bifurcates from.
        j: u32,
        /// Which arm.
        arm: Arm,
    },
}

impl core::fmt::Display for Branch {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Upsilon => f.write_str("primary υ"),
            Self::Alpha => f.write_str("primary α"),
            Self::Theta { j } => write!(f, "ϑ j={j}"),
            Self::Secondary { j, arm } => write!(f, "secondary j={j} ({arm})"),
        }
    }
}

/// One equilibrium of the planar elastica with intrinsic curvature 2πn,
/// unit length, zero end moments, pulled by a force along the end-to-end
/// line (see the [module docs](super)).
///
/// The curvature along the rod is κ(s) = 2Ω dn(u1 + Ωs, k), s ∈ [0, 1].
/// All quantities are computed once; accessors are free.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Elastica {
    pub(crate) n: u32,
    pub(crate) modulus: Modulus,
    pub(crate) big_k: f64,
    pub(crate) omega: f64,
    /// Ω − πn, computed without cancellation.
    pub(crate) excess: f64,
    pub(crate) u1: f64,
    pub(crate) extension: f64,
    pub(crate) branch: Branch,
}

/// Validates n (≥ 1).
pub(crate) fn check_n(n: u32) -> Result<()> {
    if n == 0 {
        return Err(Error::InvalidCount {
            name: "n",
            value: 0,
            allowed: "at least one coil",
        });
    }
    Ok(())
}

/// Validates j (≥ 1).
pub(crate) fn check_j(j: u32) -> Result<()> {
    if j == 0 {
        return Err(Error::InvalidCount {
            name: "j",
            value: 0,
            allowed: "at least one period",
        });
    }
    Ok(())
}

/// A modulus usable by the elastica: k ∈ [0, 1).
pub(crate) fn check_modulus(modulus: Modulus) -> Result<Modulus> {
    if modulus.complement() > 0.0 {
        Ok(modulus)
    } else {
        Err(Error::ModulusNotBelowOne {
            k: modulus.k(),
            complement: modulus.complement(),
        })
    }
}

/// From k ∈ [0, 1).
pub(crate) fn modulus_from_k(k: f64) -> Result<Modulus> {
    check_modulus(Modulus::from_k(k)?)
}

impl Elastica {
    /// `excess` is Ω − πn computed without cancellation; `ends` says where
    /// the ends sit (for the cancellation-free extension).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_parts(
        n: u32,
        modulus: Modulus,
        big_k: f64,
        omega: f64,
        excess: f64,
        u1: f64,
        ends: Ends,
        branch: Branch,
    ) -> Self {
        let extension = extension(modulus, omega, u1, ends);
        Self {
            n,
            modulus,
            big_k,
            omega,
            excess,
            u1,
            extension,
            branch,
        }
    }

    /// Number of coils n of the unstressed ring (κ0 = 2πn).
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.n
    }

    /// The elliptic modulus k.
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.modulus.k()
    }

    /// The modulus with its exact complement (k → 1 without loss).
    #[must_use]
    pub fn elliptic_modulus(&self) -> Modulus {
        self.modulus
    }

    /// Ω: the curvature is 2Ω dn(Ωs, k) (eq4, eq5); Ω = πn at k = 0.
    #[must_use]
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// Ω − πn, computed without cancellation (O(k⁶) on the υ-branch, O(k²)
    /// on α and ϑ_n): what the small-k series of Ω describe.
    #[must_use]
    pub fn omega_excess(&self) -> f64 {
        self.excess
    }

    /// The physical tension F = k²Ω² = dU/dΔz (the paper's F = 2k²Ω² is
    /// twice it; see the [module docs](super)).
    #[must_use]
    pub fn force(&self) -> f64 {
        self.modulus.m() * self.omega * self.omega
    }

    /// F/(2πn)², the scale of the paper's plots (with this solution's n).
    #[must_use]
    pub fn force_scaled(&self) -> f64 {
        let s = 2.0 * PI * f64::from(self.n);
        self.force() / (s * s)
    }

    /// End-to-end distance along the force, Δz ∈ (−1, 1), eq8 / eq82
    /// (positive in tension; 0 for the ring).
    #[must_use]
    pub fn extension(&self) -> f64 {
        self.extension
    }

    /// The shape class: υ, α or ϑ.
    #[must_use]
    pub fn shape(&self) -> Shape {
        match self.branch {
            Branch::Upsilon => Shape::Upsilon,
            Branch::Alpha => Shape::Alpha,
            Branch::Theta { .. } => Shape::Theta,
            Branch::Secondary { j, .. } => {
                if j < self.n {
                    Shape::Upsilon
                } else {
                    Shape::Alpha
                }
            }
        }
    }

    /// The branch this solution lies on.
    #[must_use]
    pub fn branch(&self) -> Branch {
        self.branch
    }

    /// The start of the rod in the paper's arclength coordinate, s1 = u1/Ω
    /// (the rod is s ∈ [s1, s1 + 1]; for ϑ-shapes a root of eq81).
    #[must_use]
    pub fn start(&self) -> f64 {
        self.u1 / self.omega
    }

    /// K(k), the quarter period.
    #[must_use]
    pub fn quarter_period(&self) -> f64 {
        self.big_k
    }

    /// Curvature κ(s) = 2Ω dn(u1 + Ωs, k) at s ∈ [0, 1] measured from the
    /// rod's start (any real s is evaluated on the periodic extension; NaN
    /// for a non-finite s or one where Ωs overflows, as in
    /// [`jacobi`](crate::special::jacobi)).
    ///
    /// ```
    /// let e = hockle::elastica::Elastica::symmetric(1, 0.9)?.upsilon;
    /// // the opened coil straightens in the middle: its curvature is below κ0
    /// assert!(e.curvature(0.5) < 2.0 * std::f64::consts::PI);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn curvature(&self, s: f64) -> f64 {
        2.0 * self.omega * jacobi(self.u1 + self.omega * s, self.modulus).dn
    }

    /// The curvatures at both ends, [κ(0), κ(1)]; both equal 2πn (eq6) to
    /// rounding.
    #[must_use]
    pub fn end_curvatures(&self) -> [f64; 2] {
        [self.curvature(0.0), self.curvature(1.0)]
    }

    /// Elastic energy U = ½∫(κ − 2πn)² ds in units of B/L:
    ///
    /// ```text
    /// U = 2Ω Δε − 4πn Δam + 2π²n²,   Δε = ε(u2) − ε(u1),  Δam = am u2 − am u1      (m ≥ ½)
    /// U = (2/Ω) ∫ (Ω(Δ − 1) + (Ω − πn))² / Δ dφ  over [am u1, am u2]           (m < ½)
    /// ```
    ///
    /// The closed form cancels where U is small (U = O(k⁴) as k → 0), so
    /// below m = ½ the integral (φ = am u, Δ = dn) is evaluated by composite
    /// Gauss–Legendre quadrature (pieces of π/16) with Δ − 1 = −m sin²φ/(1 + Δ) and Ω − πn
    /// carried without cancellation: ≤ 1e-14 relative for every k
    /// (`tests/elastica`).
    ///
    /// ```
    /// use hockle::elastica::Elastica;
    /// // F = dU/dΔz along the branch (central difference in k)
    /// let (k, h) = (0.6, 1e-6);
    /// let a = Elastica::symmetric(2, k + h)?.upsilon;
    /// let b = Elastica::symmetric(2, k - h)?.upsilon;
    /// let fd = (a.energy() - b.energy()) / (a.extension() - b.extension());
    /// let f = Elastica::symmetric(2, k)?.upsilon.force();
    /// assert!((fd / f - 1.0).abs() < 1e-7);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn energy(&self) -> f64 {
        let m = self.modulus.m();
        if m == 0.0 {
            return 0.0;
        }
        // the closed form loses ~(πn)²ε/U: keep the quadrature up to m = ½
        if m < 0.5 {
            let phi1 = jacobi(self.u1, self.modulus).am;
            let phi2 = jacobi(self.u1 + self.omega, self.modulus).am;
            let (om, ex) = (self.omega, self.excess);
            let f = |phi: f64| {
                let s = phi.sin();
                let d = (1.0 - m * s * s).sqrt();
                let v = ex - om * m * s * s / (1.0 + d);
                v * v / d
            };
            return 2.0 / om * periodic_integral(f, phi1, phi2, PI, PI / 16.0);
        }
        let u2 = self.u1 + self.omega;
        let de = jacobi_epsilon(u2, self.modulus) - jacobi_epsilon(self.u1, self.modulus);
        let da = jacobi(u2, self.modulus).am - jacobi(self.u1, self.modulus).am;
        let pn = PI * f64::from(self.n);
        2.0 * self.omega * de - 4.0 * pn * da + 2.0 * pn * pn
    }

    /// The centreline at `samples` equally spaced s ∈ [0, 1], from eq5, as
    /// points (x, z) with z along the force: the rod starts at the origin and
    /// ends at (0, Δz) (the paper's figures draw the force horizontally).
    ///
    /// ```text
    /// x(s) = −(2/Ω) (sn² u1 − sn² u) / (dn u + dn u1),    u = u1 + Ωs
    /// z(s) = ∫0^s (2 sn² u − 1) ds
    /// ```
    ///
    /// This is eq5 shifted to the start and turned by π so that Δz > 0, with
    /// x written without the 1/k² cancellation; z is evaluated by 8-point
    /// Gauss–Legendre quadrature on sub-steps of at most min(K/4, ½) in u,
    /// which stays accurate as k → 0 where eq5 cancels.
    ///
    /// ```
    /// let e = hockle::elastica::Elastica::symmetric(2, 0.7)?.alpha;
    /// let c = e.centreline(101)?;
    /// assert_eq!(c[0], hockle::nalgebra::Point2::new(0.0, 0.0));
    /// assert!((c[100].y - e.extension()).abs() < 1e-12 && c[100].x.abs() < 1e-12);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `samples` < 2 or > [`MAX_POINTS`](crate::error::MAX_POINTS).
    pub fn centreline(&self, samples: usize) -> Result<Vec<Point2<f64>>> {
        check_points("samples", samples)?;
        // Every value here is at one modulus: K, the reduction constants and
        // the series are formed once (`FixedModulus`), not at each of the
        // ~10 Jacobi evaluations per sample.
        let fixed = FixedModulus::new(self.modulus);
        let j1 = fixed.jacobi(self.u1);
        let mut out = Vec::with_capacity(samples);
        let mut z = 0.0;
        let mut s_prev = 0.0;
        let zprime = |u: f64| {
            let sn = fixed.jacobi(u).sn;
            2.0 * sn * sn - 1.0
        };
        let h = (0.25 * self.big_k).min(0.5);
        for i in 0..samples {
            let s = i as f64 / (samples - 1) as f64;
            if i > 0 {
                let (a, b) = (self.u1 + self.omega * s_prev, self.u1 + self.omega * s);
                z += periodic_integral(zprime, a, b, 2.0 * self.big_k, h) / self.omega;
            }
            let j = fixed.jacobi(self.u1 + self.omega * s);
            let x = -(2.0 / self.omega) * (j1.sn * j1.sn - j.sn * j.sn) / (j.dn + j1.dn);
            out.push(Point2::new(x, z));
            s_prev = s;
        }
        Ok(out)
    }
}

/// Δz at the ends u1, u2 = u1 + Ω (the paper's sign: positive in tension).
///
/// For m ≥ ¼ eq5 directly: Δz = 2/m − 1 − 2(ε(u2) − ε(u1))/(mΩ). Below, that
/// cancels (Δz = O(k²) from terms of size 2/m), so z′ = 1 − 2sn² = cos 2φ
/// is integrated by parts in φ = am u (du = dφ/Δ):
///
/// ```text
/// Δz = −(1/Ω) [sn cn/dn]_{u1}^{u2} + (m/(4Ω)) ∫_{φ1}^{φ2} sin²2φ / Δ³ dφ
/// ```
///
/// Both terms are positive on the primary branches (the boundary term is
/// 2 sn cn/dn (t) / Ω at the end distance t ≥ 0, zero for ϑ where the ends
/// are a whole number of periods apart and the integral is j I_π), so the
/// sum keeps relative accuracy as k → 0.
pub(crate) fn extension(modulus: Modulus, omega: f64, u1: f64, ends: Ends) -> f64 {
    let m = modulus.m();
    if m == 0.0 {
        return 0.0;
    }
    if m >= SMALL_M {
        // Δε = ε(u2) − ε(u1) from the end distance t: ε(2cK − t) = 2cE − ε(t)
        // (υ) and ε((2c+1)K + t) − ε(K − t) = 2cE + 2ε(t) − 2m sn t cd t (α,
        // DLMF 22.16.27); ε(t) = E(am t | m).
        let de = match ends {
            Ends::Periodic { j } => 2.0 * f64::from(j) * ellip_e(modulus),
            Ends::Upsilon { c, jac, e } => {
                2.0 * c * known_or(e, modulus) - 2.0 * ellip_e_inc(jac.am, modulus)
            }
            Ends::Alpha { c, jac, e } => {
                2.0 * c * known_or(e, modulus) + 2.0 * ellip_e_inc(jac.am, modulus)
                    - 2.0 * m * jac.sn * jac.cn / jac.dn
            }
            Ends::General => jacobi_epsilon(u1 + omega, modulus) - jacobi_epsilon(u1, modulus),
        };
        return 2.0 / m - 1.0 - 2.0 * de / (m * omega);
    }
    // The end values are taken at the end distance t, not at u2 = u1 + Ω,
    // whose rounding (ε·Ω) would swamp sn(t) when t = O(k²).
    let (boundary, integral) = match ends {
        Ends::Periodic { j } => (0.0, f64::from(j) * i_period(m)),
        Ends::Upsilon { c, jac, .. } => {
            // φ1 = am t, φ2 = cπ − am t
            let phi1 = jac.am;
            (
                -2.0 * jac.sn * jac.cn / jac.dn,
                i_between(m, phi1, c * PI - phi1),
            )
        }
        Ends::Alpha { c, jac, .. } => {
            // φ1 = am(K − t) = atan2(cn t, k' sn t), φ2 = (c + 1)π − φ1
            let phi1 = jac.cn.atan2(modulus.k_prime() * jac.sn);
            (
                -2.0 * jac.sn * jac.cn / jac.dn,
                i_between(m, phi1, (c + 1.0) * PI - phi1),
            )
        }
        Ends::General => {
            let a = jacobi(u1, modulus);
            let b = jacobi(u1 + omega, modulus);
            (
                b.sn * b.cn / b.dn - a.sn * a.cn / a.dn,
                i_between(m, a.am, b.am),
            )
        }
    };
    -boundary / omega + m / (4.0 * omega) * integral
}

fn known_or(e: f64, modulus: Modulus) -> f64 {
    if e.is_nan() { ellip_e(modulus) } else { e }
}

/// Where the ends of a solution sit, for [`extension`].
#[derive(Debug, Clone, Copy)]
pub(crate) enum Ends {
    /// A whole number of periods (ϑ).
    Periodic { j: u32 },
    /// Anywhere (ends given by u1 and Ω only).
    #[allow(dead_code)]
    General,
    /// υ-family member c with the Jacobi functions at the end distance t
    /// and E(k) if known (NaN otherwise).
    Upsilon { c: f64, jac: Jacobi, e: f64 },
    /// α-family member c with the Jacobi functions at the end distance t
    /// and E(k) if known (NaN otherwise).
    Alpha { c: f64, jac: Jacobi, e: f64 },
}

/// ∫_a^b f for f with period `period`: the whole periods in [a, b] as
/// ∫_0^period f times their number, so the cost is at most two periods'
/// worth of [`gauss_legendre`] pieces however long [a, b] is (n = 10⁹ coils
/// has Ω ≈ 3e9).
pub(crate) fn periodic_integral(
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    period: f64,
    h: f64,
) -> f64 {
    let whole = ((b - a) / period).floor();
    if whole < 1.0 {
        return gauss_legendre(f, a, b, h);
    }
    let rest = a + whole * period;
    // one period from 0, where the arguments carry no rounding of a large u
    whole * gauss_legendre(&f, 0.0, period, h) + gauss_legendre(&f, rest, b, h)
}

impl core::fmt::Display for Elastica {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} elastica, n = {}, {}, k = {}: F = {}, Δz = {}",
            self.shape(),
            self.n,
            self.branch,
            self.modulus.k(),
            self.force(),
            self.extension
        )
    }
}
