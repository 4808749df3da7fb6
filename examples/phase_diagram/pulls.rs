//! The diagram against direct pulls: the check scenes of a computed
//! diagram, `--pull` and the pull every check shares.

use std::error::Error;
use std::sync::atomic::{AtomicBool, Ordering};

use hockle::Stiffness;
use hockle::load::Target;
use hockle::rod::{PhaseDiagram, Pull};
use hockle::spring::{RodModel, Spring};

/// The scenes a computed diagram is checked on: about the reference,
/// where the regions are narrowest ((θ0°, A/B, ν)).
pub(crate) const CHECK_SCENES: [Scene; 14] = [
    (88.0, 5.0, 0.05),
    (88.0, 10.0, 0.05),
    (88.0, 20.0, 0.05),
    (89.0, 5.0, 0.05),
    (89.0, 10.0, 0.05),
    (89.0, 20.0, 0.05),
    (89.5, 5.0, 0.05),
    (89.5, 10.0, 0.05),
    (89.5, 20.0, 0.05),
    (89.8, 5.0, 0.05),
    (89.8, 10.0, 0.05),
    (89.8, 20.0, 0.05),
    (89.5, 10.0, -0.2),
    (89.5, 10.0, 0.2),
];

/// Checks a diagram computed here (not a committed one, whose regions the
/// docs check against pulls) against pulls to F/((2πn)²B) = 3 at
/// [`CHECK_SCENES`]: a pull that sees more pop-outs than a complete
/// diagram counts (which counts them at any force) contradicts it. n = 5
/// did when its third pop-out was traced from its maximum-force fold's
/// cusp (an island about the reference, while pulls away from it still
/// lose a fourth loop: folds that change partners rather than meet;
/// [`super::compute::vanishing_cusp`]).
/// An incomplete diagram ([`PhaseDiagram::is_complete`]) counts a lower
/// bound, which more pop-outs do not contradict. Returns why, where
/// contradicted.
pub(crate) fn contradicted_by_pulls(
    coils: u32,
    diagram: &PhaseDiagram,
) -> Result<Option<&'static str>, Box<dyn Error + Send + Sync>> {
    if !diagram.is_complete() {
        return Ok(None);
    }
    let Some((t, a, nu)) = first_excess(coils, diagram, |_| true)? else {
        return Ok(None);
    };
    eprintln!(
        "the diagram of n = {coils} computed here counts fewer pop-outs than a pull sees at \
         ({t}°, {a}, {nu}): it answers no scene"
    );
    Ok(Some(
        "the diagram computed for this n is contradicted by a pull (docs/ACCURACY.md: its regions are not \
         bounded by single cusp curves there)",
    ))
}

/// A scene: θ0 in degrees, A/B, ν.
type Scene = (f64, f64, f64);

/// The first of the [`CHECK_SCENES`] whose ν passes `at` where a pull to
/// F/((2πn)²B) = 3 sees more pop-outs than `diagram` counts.
pub(crate) fn first_excess(
    coils: u32,
    diagram: &PhaseDiagram,
    at: impl Fn(f64) -> bool,
) -> Result<Option<Scene>, Box<dyn Error + Send + Sync>> {
    for (t, a, nu) in CHECK_SCENES.into_iter().filter(|s| at(s.2)) {
        // (a diagram maps at most n − 1 pop-outs)
        let pulled = pulled(coils, (t, a, nu), 3.0)?
            .pop_outs()
            .len()
            .min(coils as usize - 1);
        let read = diagram.pop_outs(t.to_radians(), a, nu);
        eprintln!("check: ({t}°, {a}, {nu}): pulled to 3: {pulled} pop-outs, diagram: {read:?}");
        if matches!(read, Ok(n) if n < pulled) {
            return Ok(Some((t, a, nu)));
        }
    }
    Ok(None)
}

/// The scene (n coils, C by the Nikolai equality) pulled from rest to
/// F/((2πn)²B) = `to` by the default adaptive rod: the pull of every check
/// of a diagram against pulls.
pub(crate) fn pulled(
    coils: u32,
    scene: Scene,
    to: f64,
) -> Result<hockle::spring::Response, Box<dyn Error + Send + Sync>> {
    Ok(ran(coils, scene, Target::Force(to), None, TOLERANCE, None)?.response)
}

/// A pull or a stretch of a scene: the spring's response and what the
/// continuation took to get there.
pub(crate) struct Ran {
    pub(crate) response: hockle::spring::Response,
    /// Accepted continuation steps ([`hockle::rod::PullRun::steps`]).
    pub(crate) steps: usize,
    /// Rejected (retried) steps.
    pub(crate) rejected: usize,
    /// The run's tolerance ([`RodModel::tolerance`]).
    pub(crate) tolerance: f64,
    /// The loosest tolerance the run went on at past a failed corrector
    /// ([`hockle::rod::Pull::relax_to`]); its own where it did not.
    pub(crate) relaxed_to: f64,
}

impl Ran {
    /// The end of a `pulled`/`stretched`/`stretch` line: `max_forces=<f1;f2;…>
    /// steps=<accepted> rejected=<count> tolerance=<tol> relaxed_to=<tol>
    /// estimate=<curve error>`.
    fn fields(&self) -> String {
        format!(
            "max_forces={} steps={} rejected={} tolerance={:e} relaxed_to={:e} estimate={:.1e}",
            peak_forces(&self.response).join(";"),
            self.steps,
            self.rejected,
            self.tolerance,
            self.relaxed_to,
            self.response.estimated_error().unwrap_or(f64::NAN)
        )
    }
}

/// The scene (n coils, C by the Nikolai equality) driven from rest to
/// `target` by the adaptive rod at `tolerance` (at most `max_steps` steps
/// where given), going on past a failed corrector at looser tolerances up
/// to `relax_to` where given.
fn ran(
    coils: u32,
    (t, a, nu): Scene,
    target: Target,
    max_steps: Option<usize>,
    tolerance: f64,
    relax_to: Option<f64>,
) -> Result<Ran, Box<dyn Error + Send + Sync>> {
    let spring = Spring::from_degrees(coils, t, Stiffness::nikolai(a, nu)?)?;
    let mut model = RodModel::default()
        .tolerance(tolerance)
        .symmetric(SYMMETRIC.load(Ordering::Relaxed));
    if let Some(loosest) = relax_to {
        model = model.relax_to(loosest);
    }
    let mut pull = model.driver(&spring, target)?;
    if let Some(limit) = max_steps {
        pull = pull.max_steps(limit);
    }
    let run = pull.run(())?;
    let (steps, rejected) = (run.steps(), run.rejected());
    let relaxed_to = run.relaxations().last().map_or(tolerance, |r| r.tolerance);
    Ok(Ran {
        response: RodModel::response(run)?,
        steps,
        rejected,
        tolerance,
        relaxed_to,
    })
}

/// `--symmetric`: every pull and stretch solves the rod on its half
/// ([`RodModel::symmetric`]: the equilibria symmetric end to end, without
/// the antisymmetric modes along which loops slide); set by `main` before
/// any run.
pub(crate) static SYMMETRIC: AtomicBool = AtomicBool::new(false);

/// The rod's default tolerance, at which every pull and stretch runs first.
const TOLERANCE: f64 = Pull::DEFAULT_TOLERANCE;

/// The tolerances a stretch that stops short is run again at from rest,
/// in turn. Where loops slide (near 90° at ν < 0, or at A/B = 100 past most
/// pop-outs) Newton's corrections stall at 1e-9–1e-8 relative, above the
/// corrector's 1e-10 at the default 1e-6, and the default stretch ends with
/// `CorrectorDrifted` or a Newton failure at its shortest step; the looser
/// runs' correctors (1e-9, 1e-8) take those points: of the 14 grid
/// stretches (n = 5–8) the default left short, 6 reach Δz = 0.99 at 1e-5
/// and 2 more at 1e-4 (7 Dec; at 1e-3 they fail sooner: n = 5 at
/// (89.8°, 10, −0.2) sees no pop-out before Newton diverges). The counts
/// need no more: the maximum forces of these stretches lie at least 0.04
/// apart in F/((2πn)²B), and the retried runs' maxima agree with the
/// default's to 3e-4 where both see them (docs/ACCURACY.md, "Stretched").
const RETRY_TOLERANCES: [f64; 2] = [1e-5, 1e-4];

/// Where every retry stops short: the default stretch going on from its
/// failed corrector at looser tolerances up to this
/// ([`hockle::rod::Pull::relax_to`]: 1e-5, then 1e-4), the last resort, not
/// the first. From the failure the run is already where loops slide, and a
/// looser corrector can follow the slide: n = 7 at (89°, 100, 0.05) went on
/// from there along a branch that retraced its last pop-out in the plot
/// (eleven "maxima", ending at F/((2πn)²B) = 83 still holding two loops),
/// where the retry from rest at 1e-5 passes the six the diagram counts.
/// Where all three retries fail it passes n = 8 at (89.8°, 10, −0.1).
const RELAX_TO: f64 = 1e-4;

/// Where a stretch ends, Δz (extension control): the rod nearly straight.
/// Past its pop-outs it pulls there with F/((2πn)²B) of 1.0–2.6 (n = 8
/// to 2; n = 4 at (88°, 10, −0.2): 1.66, its last maximum 3.37); a loop
/// still held at 0.99 takes forces of order 10² (n = 4 at (87.9°, 24.7,
/// −0.184): 254, two loops left, its last maximum 17.2), so a stretch
/// counts as past its pop-outs only where it ends below its last maximum
/// force ([`past_pop_outs`]).
pub(crate) const STRETCH_TO: f64 = 0.99;

/// The step limit of a stretch: the stretches that pass every pop-out
/// take 200–400 steps (n = 4); where the loops left in the rod slide near
/// 90° at negative ν a stretch crawls (20 000 steps, 231 s, at (89.5°, 10,
/// −0.2) without reaching its third maximum), and one stopped here keeps
/// what it saw.
pub(crate) const STRETCH_STEPS: usize = 2000;

/// The scene (n coils, C by the Nikolai equality) stretched from rest to
/// Δz = `to` under extension control by the default adaptive rod, at most
/// [`STRETCH_STEPS`] steps; where that stops short of Δz, stretched again
/// at each of [`RETRY_TOLERANCES`] until one reaches Δz, and last going on
/// from the default's failed corrector up to [`RELAX_TO`] (else the default
/// run is kept). A pop-out's maximum force is no fold of the continuation
/// here (the pull passes it with Δz rising), so where the pop-outs come at
/// high forces a stretch sees them without the force pulled to them: n = 4
/// at (88°, 10, −0.2) sees 3 pop-outs, the third at F/((2πn)²B) = 3.37,
/// ending at 1.66.
pub(crate) fn stretched(
    coils: u32,
    scene: Scene,
    to: f64,
) -> Result<Ran, Box<dyn Error + Send + Sync>> {
    let stretch = |tol, relax| {
        ran(
            coils,
            scene,
            Target::Extension(to),
            Some(STRETCH_STEPS),
            tol,
            relax,
        )
    };
    let first = stretch(TOLERANCE, None)?;
    if first.response.reached_target() {
        return Ok(first);
    }
    for tol in RETRY_TOLERANCES {
        let again = stretch(tol, None)?;
        if again.response.reached_target() {
            return Ok(again);
        }
    }
    let relaxed = stretch(TOLERANCE, Some(RELAX_TO))?;
    Ok(if relaxed.response.reached_target() {
        relaxed
    } else {
        first
    })
}

/// How far either side in θ0 a count read differently marks a scene as
/// near a line (the reading's own error, docs/ACCURACY.md).
pub(crate) const NEAR_DEG: f64 = 0.1;

/// The diagram's count at the scene (`None` where it is not mapped), and
/// whether it is read differently [`NEAR_DEG`] either side in θ0.
pub(crate) fn read_near_line(diagram: &PhaseDiagram, (t, a, nu): Scene) -> (Option<usize>, bool) {
    let read = |deg: f64| diagram.pop_outs(deg.to_radians(), a, nu).ok();
    let count = read(t);
    let near = count != read(t - NEAR_DEG) || count != read((t + NEAR_DEG).min(89.999));
    (count, near)
}

/// The maximum forces F/((2πn)²B) of a pull's pop-outs, as printed.
pub(crate) fn peak_forces(response: &hockle::spring::Response) -> Vec<String> {
    let scale = response.curve().scale();
    response
        .pop_outs()
        .iter()
        .map(|p| format!("{:.4}", p.max.point.force_scaled(scale)))
        .collect()
}

/// Whether a stretch reached its Δz past its pop-outs: ending below its
/// last pop-out's maximum force (a loop still held at Δz = [`STRETCH_TO`]
/// pulls far above it); and its force F/((2πn)²B) at the end.
pub(crate) fn past_pop_outs(response: &hockle::spring::Response) -> (bool, f64) {
    let scale = response.curve().scale();
    let end = response
        .curve()
        .points()
        .last()
        .map_or(f64::NAN, |p| p.force_scaled(scale));
    let last_max = response
        .pop_outs()
        .last()
        .map(|p| p.max.point.force_scaled(scale));
    let past = response.reached_target() && last_max.is_some_and(|f| end < f);
    (past, end)
}

/// `--stretch`: the scene stretched from rest to Δz = `to`
/// ([`stretched`]), its pop-outs and their maximum forces.
pub(crate) fn stretch_scene(
    coils: u32,
    (t, a, nu): (f64, f64, f64),
    to: f64,
) -> Result<(), Box<dyn Error + Send + Sync>> {
    let stretch = stretched(coils, (t, a, nu), to)?;
    let (past, end) = past_pop_outs(&stretch.response);
    print_run(
        "stretched",
        to,
        &stretch,
        &format!(" past_pop_outs={past} end_force={end:.4}"),
    );
    Ok(())
}

/// `--pull`: the scene pulled from rest to F/((2πn)²B) = `to`, its
/// pop-outs and their maximum forces.
pub(crate) fn pull_scene(
    coils: u32,
    (t, a, nu): (f64, f64, f64),
    to: f64,
) -> Result<(), Box<dyn Error + Send + Sync>> {
    let pull = ran(coils, (t, a, nu), Target::Force(to), None, TOLERANCE, None)?;
    print_run("pulled", to, &pull, "");
    Ok(())
}

/// One line `<word> pop_outs=<count> to=<to> reached=<bool><extra>
/// max_forces=<f1;f2;…> steps=<accepted> rejected=<count> tolerance=<tol>
/// relaxed_to=<tol> estimate=<curve error>` for a pull or a stretch of a scene, and on
/// standard error why it stopped short.
fn print_run(word: &str, to: f64, ran: &Ran, extra: &str) {
    let response = &ran.response;
    println!(
        "{word} pop_outs={} to={to} reached={}{extra} {}",
        response.pop_outs().len(),
        response.reached_target(),
        ran.fields()
    );
    if !response.reached_target() {
        eprintln!("  {}", response.termination());
    }
}

/// Scenes where a pull to a force saw fewer pop-outs than the diagram
/// counts, stretched to Δz = [`STRETCH_TO`] ([`stretched_past`]).
#[derive(Default)]
pub(crate) struct Stretched {
    /// The stretch reached Δz past its pop-outs ([`past_pop_outs`]) and
    /// saw the diagram's count.
    pub(crate) confirmed: usize,
    /// The stretch reached Δz past its pop-outs ([`past_pop_outs`]) and saw
    /// fewer: the diagram counts a pop-out (a fold pair) that the path from
    /// rest does not pass.
    pub(crate) fewer: usize,
    /// The stretch stopped short (its step limit, a Newton failure), or
    /// reached Δz with a loop still held, with no more than the diagram's
    /// count so far.
    pub(crate) short: usize,
}

/// Stretches each scene of `fewer` ((scene, diagram's count, pull's
/// count), where the pull saw fewer) to Δz = [`STRETCH_TO`] and prints
/// `stretch theta0=<deg> a_over_b=<x> nu=<x> diagram=<count>
/// stretched=<count> reached=<bool> past_pop_outs=<bool> end_force=<F>
/// max_forces=<F;…> steps=<accepted> rejected=<count> tolerance=<tol>
/// relaxed_to=<tol> estimate=<curve error>` (of the stretch kept, [`stretched`]); a stretch
/// that sees more pop-outs than the diagram counts is added to
/// `contradicted`.
pub(crate) fn stretched_past(
    coils: u32,
    fewer: &[((f64, f64, f64), usize, usize)],
    contradicted: &mut Vec<(f64, f64, f64)>,
) -> Result<Stretched, Box<dyn Error + Send + Sync>> {
    let mut tally = Stretched::default();
    for &((t, a, nu), diagram, _) in fewer {
        let stretch = stretched(coils, (t, a, nu), STRETCH_TO)?;
        let count = stretch.response.pop_outs().len();
        let reached = stretch.response.reached_target();
        let (past, end) = past_pop_outs(&stretch.response);
        println!(
            "stretch theta0={t} a_over_b={a} nu={nu} diagram={diagram} stretched={count} reached={reached} past_pop_outs={past} end_force={end:.4} {}",
            stretch.fields()
        );
        match (count, past) {
            (k, _) if k > diagram => contradicted.push((t, a, nu)),
            (k, true) if k == diagram => tally.confirmed += 1,
            (_, true) => tally.fewer += 1,
            _ => tally.short += 1,
        }
    }
    Ok(tally)
}
