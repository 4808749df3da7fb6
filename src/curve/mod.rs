//! [`ForceExtension`]: the one output type of every model in hockle.
//!
//! A curve is a sequence of equilibria in the order a model produced them
//! (along a branch, or along a continuation run), each with its physical
//! force, its extension and the parameter that generated it (the modulus k
//! for an elastica branch, the helix angle θ for a helix, the arclength for a
//! continuation run).

use std::io;

mod dense;
pub use dense::{Curvature, Slope};

use crate::error::{Error, Result};

/// One equilibrium on a force–extension curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ForcePoint {
    /// End-to-end distance along the force per unit length, Δz ∈ [−1, 1].
    pub extension: f64,
    /// Physical tension F = dU/dΔz in units of B/L² (positive when pulling).
    pub force: f64,
    /// The parameter that generated the point (k, θ, arclength, …: see the
    /// curve's [`ForceExtension::parameter_name`]).
    pub parameter: f64,
}

impl ForcePoint {
    /// The force divided by the [`ForceScale`] (2πn)²B, the scale of the
    /// paper's plots.
    ///
    /// ```
    /// use hockle::{ForcePoint, ForceScale};
    /// let p = ForcePoint { extension: 0.5, force: 2.0, parameter: 0.0 };
    /// let scale = ForceScale::new(4, 2.0)?; // n = 4, B = 2
    /// assert_eq!(p.force_scaled(scale), 2.0 / ((2.0 * std::f64::consts::PI * 4.0).powi(2) * 2.0));
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn force_scaled(&self, scale: ForceScale) -> f64 {
        self.force / scale.value()
    }
}

/// The paper's force scale (2πn)²·B: the force that bends a straight rod of
/// bending stiffness B into n full turns per unit length, and the unit of
/// every force axis in its figures (F/((2πn)²B)).
///
/// Defined once here for every model. A spring's own scale is
/// [`Spring::scale`](crate::spring::Spring::scale); the elastica is solved
/// with B = 1 ([`ForceScale::of_coils`]).
/// The equations of every model are invariant when A, B, C and F are
/// scaled together, so curves in this scale do not depend on the units of
/// stiffness.
///
/// ```
/// use hockle::ForceScale;
/// let s = ForceScale::of_coils(4)?; // n = 4, B = 1
/// assert!((s.value() - (8.0 * std::f64::consts::PI).powi(2)).abs() < 1e-12);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ForceScale {
    coils: u32,
    bending: f64,
}

impl ForceScale {
    /// The scale (2πn)²B of `coils` coils with bending stiffness `bending` (B).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `coils` is 0; [`Error::InvalidArgument`] if
    /// B is not finite and positive, or (2πn)²B overflows.
    pub fn new(coils: u32, bending: f64) -> Result<Self> {
        if coils == 0 {
            return Err(Error::InvalidCount {
                name: "coils",
                value: 0,
                allowed: "at least 1 coil",
            });
        }
        let scale = Self { coils, bending };
        if !(bending > 0.0 && scale.value().is_finite() && scale.value() > 0.0) {
            return Err(Error::InvalidArgument {
                name: "bending stiffness B",
                value: bending,
                allowed: "finite and positive, with (2πn)²B finite and positive",
            });
        }
        Ok(scale)
    }

    /// (2πn)² with B = 1, the units of the elastica.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `coils` is 0.
    pub fn of_coils(coils: u32) -> Result<Self> {
        Self::new(coils, 1.0)
    }

    /// The number of coils n.
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.coils
    }

    /// The bending stiffness B.
    #[must_use]
    pub fn bending(&self) -> f64 {
        self.bending
    }

    /// (2πn)²B.
    #[must_use]
    pub fn value(&self) -> f64 {
        let two_pi_n = 2.0 * std::f64::consts::PI * f64::from(self.coils);
        two_pi_n * two_pi_n * self.bending
    }
}

impl core::fmt::Display for ForceScale {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "(2π·{})²·{}", self.coils, self.bending)
    }
}

/// A force–extension curve: equilibria in order, with the [`ForceScale`]
/// (2πn)²B of the paper's plots.
///
/// ```
/// use hockle::{ForceExtension, ForcePoint, ForceScale};
/// let mut curve = ForceExtension::new("demo", "k", ForceScale::new(4, 2.0)?);
/// curve.push(ForcePoint { extension: 0.1, force: 2.0, parameter: 0.5 });
/// assert_eq!(curve.len(), 1);
/// let scale = (2.0 * std::f64::consts::PI * 4.0).powi(2) * 2.0;
/// assert_eq!(curve.force_scaled(0), Some(2.0 / scale));
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ForceExtension {
    label: String,
    parameter_name: String,
    scale: ForceScale,
    points: Vec<ForcePoint>,
    #[cfg_attr(feature = "serde", serde(default))]
    slopes: Vec<Option<Slope>>,
    #[cfg_attr(feature = "serde", serde(default))]
    curvatures: Vec<Option<Curvature>>,
}

impl ForceExtension {
    /// An empty curve named `label`, whose points carry `parameter_name` as
    /// their parameter, with forces scaled by `scale`.
    #[must_use]
    pub fn new(
        label: impl Into<String>,
        parameter_name: impl Into<String>,
        scale: ForceScale,
    ) -> Self {
        Self {
            label: label.into(),
            parameter_name: parameter_name.into(),
            scale,
            points: Vec::new(),
            slopes: Vec::new(),
            curvatures: Vec::new(),
        }
    }

    /// Appends a point at the end of the curve, without a slope (the
    /// interpolant is linear next to it; see [`Self::push_with_slope`]).
    pub fn push(&mut self, point: ForcePoint) {
        self.align_derivatives();
        self.points.push(point);
        self.slopes.push(None);
        self.curvatures.push(None);
    }

    /// Pads the slopes and curvatures to one per point (a curve read from
    /// a file written before they existed has none).
    fn align_derivatives(&mut self) {
        self.slopes.resize(self.points.len(), None);
        self.curvatures.resize(self.points.len(), None);
    }

    /// What the curve is (a branch name, a model name).
    #[must_use]
    pub fn label(&self) -> &str {
        &self.label
    }

    /// The name of the points' parameter (`"k"`, `"theta"`, `"arclength"`, …).
    #[must_use]
    pub fn parameter_name(&self) -> &str {
        &self.parameter_name
    }

    /// The force scale (2πn)²B of [`Self::force_scaled`].
    #[must_use]
    pub fn scale(&self) -> ForceScale {
        self.scale
    }

    /// (2πn)²B, the value that divides the force in the paper's plots.
    #[must_use]
    pub fn force_scale(&self) -> f64 {
        self.scale.value()
    }

    /// The points, in order.
    #[must_use]
    pub fn points(&self) -> &[ForcePoint] {
        &self.points
    }

    /// The number of points.
    #[must_use]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether the curve has no points.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The force of point `i` divided by (2πn)², or `None` past the end.
    #[must_use]
    pub fn force_scaled(&self, i: usize) -> Option<f64> {
        self.points.get(i).map(|p| p.force / self.force_scale())
    }

    /// Writes the curve as CSV with the header
    /// `extension,force,force_scaled,parameter`, one row per point in order,
    /// numbers in Rust's shortest round-trip form.
    ///
    /// # Errors
    /// Any error of the writer.
    pub fn write_csv<W: io::Write>(&self, mut out: W) -> io::Result<()> {
        writeln!(out, "extension,force,force_scaled,{}", self.parameter_name)?;
        let scale = self.force_scale();
        for p in &self.points {
            writeln!(
                out,
                "{:e},{:e},{:e},{:e}",
                p.extension,
                p.force,
                p.force / scale,
                p.parameter
            )?;
        }
        Ok(())
    }

    /// The folds of the curve: local extrema of the force and of the
    /// extension along it, in order, each located at the vertex of the
    /// parabola (in the points' parameter) through the extreme point and its
    /// two neighbours.
    ///
    /// Models that locate their folds more precisely (continuation) report
    /// those instead; this serves every curve alike.
    #[must_use]
    pub fn folds(&self) -> Vec<Fold> {
        detect_folds(&self.points)
    }
}

impl Extend<ForcePoint> for ForceExtension {
    fn extend<I: IntoIterator<Item = ForcePoint>>(&mut self, iter: I) {
        for p in iter {
            self.push(p);
        }
    }
}

impl core::fmt::Display for ForceExtension {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} ({} points over {}, force scaled by {})",
            self.label,
            self.points.len(),
            self.parameter_name,
            self.scale
        )
    }
}

/// What turns at a fold.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum FoldKind {
    /// A local maximum of the force along the curve (a pop-out starts).
    MaxForce,
    /// A local minimum of the force along the curve (a pop-out ends).
    MinForce,
    /// A local maximum of the extension along the curve.
    MaxExtension,
    /// A local minimum of the extension along the curve.
    MinExtension,
}

/// A turning point of force or extension along the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Fold {
    /// What turns.
    pub kind: FoldKind,
    /// The index of the curve point at which the fold was found: the
    /// extreme sample where a curve's folds are detected from its points
    /// ([`ForceExtension::folds`]), the last point before the fold where a
    /// model located it between points (continuation).
    pub index: usize,
    /// The fold itself (located between curve points where the model could;
    /// its parameter is then the curve parameter at the fold).
    pub point: ForcePoint,
}

impl core::fmt::Display for FoldKind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::MaxForce => "maximum-force fold",
            Self::MinForce => "minimum-force fold",
            Self::MaxExtension => "maximum-extension fold",
            Self::MinExtension => "minimum-extension fold",
        })
    }
}

impl core::fmt::Display for Fold {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} at Δz = {}, F = {}",
            self.kind, self.point.extension, self.point.force
        )
    }
}

/// Local extrema of force and extension along the curve, each located at
/// the vertex of the parabola through the point and its two neighbours
/// (in the curve's parameter).
fn detect_folds(pts: &[ForcePoint]) -> Vec<Fold> {
    let mut folds = Vec::new();
    for i in 1..pts.len().saturating_sub(1) {
        let (a, b, c) = (&pts[i - 1], &pts[i], &pts[i + 1]);
        for (quantity, value) in [(0, b.force), (1, b.extension)] {
            let get = |p: &ForcePoint| if quantity == 0 { p.force } else { p.extension };
            let (va, vc) = (get(a), get(c));
            let kind = match quantity {
                0 if value > va && value >= vc => FoldKind::MaxForce,
                0 if value < va && value <= vc => FoldKind::MinForce,
                1 if value > va && value >= vc => FoldKind::MaxExtension,
                1 if value < va && value <= vc => FoldKind::MinExtension,
                _ => continue,
            };
            folds.push(Fold {
                kind,
                index: i,
                point: parabola_vertex(a, b, c, get),
            });
        }
    }
    folds
}

/// The point at the extremum of `get` on the parabolas through (t, ·) of
/// the three points, t the curve parameter; falls back to `b` when the
/// parameters do not separate the points.
fn parabola_vertex(
    a: &ForcePoint,
    b: &ForcePoint,
    c: &ForcePoint,
    get: impl Fn(&ForcePoint) -> f64,
) -> ForcePoint {
    let (ta, tb, tc) = (a.parameter, b.parameter, c.parameter);
    let (ya, yb, yc) = (get(a), get(b), get(c));
    let denom = (ta - tb) * (ta - tc) * (tb - tc);
    if denom == 0.0 || denom.is_nan() {
        return *b;
    }
    let num = ta * ta * (yb - yc) + tb * tb * (yc - ya) + tc * tc * (ya - yb);
    let den = 2.0 * (ta * (yb - yc) + tb * (yc - ya) + tc * (ya - yb));
    let t = num / den;
    if !(t.is_finite() && t >= ta.min(tc) && t <= ta.max(tc)) {
        return *b;
    }
    let quad = |fa: f64, fb: f64, fc: f64| {
        fa * (t - tb) * (t - tc) / ((ta - tb) * (ta - tc))
            + fb * (t - ta) * (t - tc) / ((tb - ta) * (tb - tc))
            + fc * (t - ta) * (t - tb) / ((tc - ta) * (tc - tb))
    };
    ForcePoint {
        extension: quad(a.extension, b.extension, c.extension),
        force: quad(a.force, b.force, c.force),
        parameter: t,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trips_every_number() {
        let mut c = ForceExtension::new("t", "k", ForceScale::of_coils(1).unwrap());
        c.push(ForcePoint {
            extension: 0.1,
            force: 1.0 / 3.0,
            parameter: 0.7,
        });
        let mut buf = Vec::new();
        c.write_csv(&mut buf).unwrap();
        let text = String::from_utf8(buf).unwrap();
        let row: Vec<f64> = text
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(row[0], 0.1);
        assert_eq!(row[1], 1.0 / 3.0);
        assert_eq!(row[3], 0.7);
    }

    #[test]
    fn zero_coils_or_a_bad_b_is_an_error() {
        assert!(matches!(
            ForceScale::new(0, 1.0),
            Err(Error::InvalidCount { name: "coils", .. })
        ));
        for b in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e308] {
            assert!(ForceScale::new(u32::MAX, b).is_err(), "B = {b}");
        }
    }
}
