//! CC2 feature recognition: a program's resolved moves raised into ISO
//! 14649 machining features (2.5D milling) with their operations, after
//! the method of Xu, Anwer and Lavernhe (2014): the moves are cut into
//! chunks (one tool at one place, `segment`); chunks are recognised as
//! drilling (`hole`, `drill`) or as milling cuts made of layers and
//! loops (`cuts`, `level`, `shape`); milling cuts become planar
//! faces (`face`), slots (`slot`), outside profiles (`profile`),
//! closed pockets (`pocket`), open pockets and steps (`open`), tried
//! in that order, with their strategies (`strategy`). An operation
//! over a feature already found is a further operation of it: the last
//! one is the finishing one and the allowances of the earlier ones are
//! read from the offset between them. Whatever is not recognised stays a
//! TOOLPATH_FEATURE with its explicit toolpath (`freeform`), reported
//! with W0870: nothing is dropped. Features, operations and workingsteps
//! are appended in program order.
//!
//! Sizes come from the tool diameters (the context's, else the project's
//! tools); without them a cut stays a toolpath feature. The stock, when
//! given, tells faces, through holes, open ends, steps and open pockets;
//! without it the top is taken at Z0 and a face must cover every other
//! cut from above them.
//!
//! Frames: feature placements and toolpaths are in workpiece
//! coordinates (the setup and workpiece placements are identity); a
//! feature's geometry (depth plane, profiles) is in its local frame. The
//! workingsteps' security plane is at `secplane_z` in workpiece
//! coordinates (as NIST's Example 1 shares one plane).

mod build;
mod cuts;
mod drill;
mod face;
mod freeform;
mod hole;
mod level;
pub mod listing;
mod open;
mod packed;
mod pocket;
mod profile;
mod segment;
mod shape;
mod slot;
mod state;
mod strategy;
#[cfg(test)]
mod tests;

use crate::diag::Diagnostic;
use crate::stepnc::model::{Project, ToolId, P3};
use crate::toolpath::Event;
pub(crate) use state::{Known, Raiser};

/// What recognition needs beyond the moves.
pub struct Cc2Context {
    /// The diameter (mm) of a tool by its number.
    pub tool_diameter: Box<dyn Fn(i64) -> Option<f64>>,
    /// The stock's box (min, max, mm, work coordinates), when known:
    /// through holes, open slot ends, steps and faces are told by it.
    pub stock: Option<(P3, P3)>,
    /// The security plane's Z, work coordinates.
    pub secplane_z: f64,
}

impl Default for Cc2Context {
    fn default() -> Self {
        Cc2Context {
            tool_diameter: Box::new(|_| None),
            stock: None,
            secplane_z: 50.0,
        }
    }
}

/// Appends the features, operations and workingsteps the moves make to
/// the project, in program order. See [`recognise_report`] for the
/// diagnostics (moves left as toolpath features).
pub fn recognise(
    events: &[Event],
    project: &mut Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
) {
    // The moves are all carried into the project; the notes saying which
    // were not recognised are available from `recognise_report`.
    let _notes = recognise_report(events, project, tool, ctx);
}

/// [`recognise`], returning a W0870 note for each run of moves kept as a
/// TOOLPATH_FEATURE.
pub fn recognise_report(
    events: &[Event],
    project: &mut Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
) -> Vec<Diagnostic> {
    let cuts = cuts::stored(events, &|t| radius(project, tool, ctx, t));
    raise_cuts(cuts, project, tool, ctx)
}

/// A run's cuts made event by event ([`segment::Chunker`] and
/// [`cuts::CutBuilder`]): no event outlives the cut it belongs to, so a
/// run is never held as events, and finished cuts are kept packed
/// ([`packed`]). Raised with [`recognise_cuts`].
#[derive(Debug, Default)]
pub struct CutStream {
    chunker: segment::Chunker,
    cuts: cuts::CutBuilder,
}

/// The cuts of a run ([`CutStream::finish`]).
pub struct Cuts(Vec<cuts::Stored>);

impl CutStream {
    /// Takes the next event; `radius` gives a tool's radius (mm).
    pub fn push(&mut self, e: Event, radius: &dyn Fn(i64) -> Option<f64>) {
        if let Some(c) = self.chunker.push(e) {
            self.cuts.push(c, radius);
        }
    }

    pub fn finish(mut self, radius: &dyn Fn(i64) -> Option<f64>) -> Cuts {
        if let Some(c) = self.chunker.finish() {
            self.cuts.push(c, radius);
        }
        Cuts(self.cuts.finish(radius))
    }
}

/// [`recognise_report`] on cuts made by a [`CutStream`] (with the radius
/// [`recognise_report`] would use: the context's, else the project's).
pub fn recognise_cuts(
    cuts: Cuts,
    project: &mut Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
) -> Vec<Diagnostic> {
    raise_cuts(cuts.0, project, tool, ctx)
}

/// Raises the cuts in order, unpacking one at a time; each is dropped
/// once raised (recognition looks at the other cuts only through their
/// envelopes and tops, taken first).
fn raise_cuts(
    cuts: Vec<cuts::Stored>,
    project: &mut Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
) -> Vec<Diagnostic> {
    let envelopes = cuts.iter().map(|c| c.envelope).collect();
    let tops = cuts.iter().map(|c| c.top).collect();
    let mut r = Raiser::new(project, tool, ctx, envelopes, tops);
    for (i, stored) in cuts.into_iter().enumerate() {
        r.current = i;
        let cut = stored.unpack();
        drop(stored);
        match &cut {
            cuts::Cut::Hole { hole, tool, moves } => drill::raise(&mut r, hole, *tool, moves),
            cuts::Cut::Mill(m) => raise_mill(&mut r, m),
            cuts::Cut::Other(c) => freeform::raise(&mut r, c.tool, &c.moves, "moves"),
        }
    }
    r.diags
}

fn raise_mill(r: &mut Raiser, m: &level::MillCut) {
    let Some(rad) = r.radius(m.tool) else {
        return freeform::raise(r, m.tool, &m.moves, "the tool's diameter is unknown; moves");
    };
    let done = face::raise(r, m, rad)
        || slot::raise(r, m, rad)
        || profile::raise(r, m, rad)
        || pocket::raise(r, m, rad);
    if !done {
        freeform::raise(r, m.tool, &m.moves, "milling moves");
    }
}

fn radius(
    project: &Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
    t: i64,
) -> Option<f64> {
    let d = (ctx.tool_diameter)(t).or_else(|| {
        let id = tool(t);
        project
            .tools
            .get(id.index())
            .map(|tl| tl.body.dimension.diameter)
    });
    radius_of(d)
}

/// The radius of a tool of diameter `d`, when that is a size.
pub fn radius_of(d: Option<f64>) -> Option<f64> {
    d.filter(|d| *d > 0.0 && d.is_finite()).map(|d| d / 2.0)
}
