//! Cutter radius compensation (G40/G41/G42/G41.1/G42.1), computed as
//! LinuxCNC's interpreter computes it, so that the canonical calls match
//! `rs274`'s to four decimals.
//!
//! [`RadiusComp`] sits between the interpreter core and the canon output.
//! The core sends every motion through it, always in *programmed*
//! (uncompensated) coordinates, and every other call through
//! [`RadiusComp::other`]. While compensation is on the engine holds back
//! one move (the output lags a block, as rs274's does): only the next move
//! tells where the held one must end (concave corner) or whether an arc
//! must be added round the corner (convex corner).
//!
//! **Positions.** The core keeps the *programmed* position as its current
//! position: the `from` of each move is the programmed end of the previous
//! one, incremental (G91) moves and arc centres (I/J) are relative to it,
//! and after G40 the exit move starts from it too (as LinuxCNC resets its
//! current point to the programmed one on G40). The tool's actual,
//! compensated position is kept here: [`RadiusComp::compensated`].
//!
//! **Planes.** XY, and XZ as LinuxCNC allows it (lathes): in XZ the engine
//! works on (Z, X) as its (x, y), with Y as the axis, exactly as
//! `ARC_FEED` orders the XZ plane, and straight moves are turned back to
//! X Y Z order when they leave the queue. YZ is refused, as in LinuxCNC.

mod angle;
mod arc;
mod error;
mod queue;
mod straight;

#[cfg(test)]
mod tests;

pub use error::{BlockTag, CompError, CompErrorKind};

use crate::canon::{Canon, CanonPlane, Pose};
use queue::Queue;

/// Which side of the path the tool runs on, looking along the motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompSide {
    /// G41, G41.1.
    Left,
    /// G42, G42.1.
    Right,
}

/// A straight move's kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MoveKind {
    /// G0: `STRAIGHT_TRAVERSE`.
    Rapid,
    /// G1: `STRAIGHT_FEED`.
    Feed,
}

/// The compensation engine. See the module documentation.
#[derive(Clone, Debug)]
pub struct RadiusComp {
    side: Option<CompSide>,
    radius: f64,
    /// The next move is the entry move.
    first_move: bool,
    /// The last G40 flushed a path: the next move must be straight.
    arc_not_allowed: bool,
    /// The compensated tool position (x, y, z), valid after the entry move.
    current: [f64; 3],
    queue: Queue,
    /// The block the calls now arriving belong to.
    block: BlockTag,
    /// The controller's own start-up rules.
    pub rules: CompRules,
}

/// Where controllers differ in starting compensation (from the spec's
/// capabilities; LinuxCNC's rules when both are on).
#[derive(Clone, Copy, Debug, Default)]
pub struct CompRules {
    /// The entry move must be longer than the radius.
    pub entry_longer_than_radius: bool,
    /// G41/G42 while on is an error; otherwise it changes side and radius.
    pub on_when_on_error: bool,
}

impl Default for RadiusComp {
    fn default() -> Self {
        Self::new()
    }
}

impl RadiusComp {
    pub fn new() -> Self {
        RadiusComp {
            side: None,
            radius: 0.0,
            first_move: true,
            arc_not_allowed: false,
            current: [0.0; 3],
            queue: Queue::default(),
            block: 0,
            rules: CompRules {
                entry_longer_than_radius: true,
                on_when_on_error: true,
            },
        }
    }

    /// Tags the calls that follow with the block they come from, so that
    /// errors can name it.
    pub fn set_block(&mut self, block: BlockTag) {
        self.block = block;
    }

    /// G41/G42 (`radius` = the tool table's diameter / 2) or G41.1/G42.1
    /// (`radius` = D / 2). A negative radius swaps the side, as LinuxCNC
    /// does for a negative table diameter. The core should first pass
    /// `COMMENT("interpreter: cutter radius compensation on left|right")`
    /// through [`Self::other`], as rs274 prints it.
    pub fn start(
        &mut self,
        side: CompSide,
        radius: f64,
        plane: CanonPlane,
    ) -> Result<(), CompError> {
        if self.side.is_some() {
            if self.rules.on_when_on_error {
                return Err(self.error(CompErrorKind::AlreadyOn, None));
            }
            // Fanuc and Siemens take a new G41/G42 or D while on as a
            // change of side or offset from the next move on [K].
            self.side = Some(side_of(side, radius < 0.0));
            self.radius = radius.abs();
            return Ok(());
        }
        if plane == CanonPlane::YZ {
            return Err(self.error(CompErrorKind::NotXyPlane, None));
        }
        self.queue.xz = plane == CanonPlane::XZ;
        self.side = Some(side_of(side, radius < 0.0));
        self.radius = radius.abs();
        self.first_move = true;
        Ok(())
    }

    /// G40: flushes the held-back path, ending it where the tool is; the
    /// next move (which must be straight) leaves the path uncompensated.
    /// The core should pass `COMMENT("interpreter: cutter radius
    /// compensation off")` through [`Self::other`] first: rs274 prints it
    /// after the held-back move.
    pub fn stop(&mut self, out: &mut dyn FnMut(Canon)) -> Result<(), CompError> {
        if self.side.is_some() && self.radius > 0.0 {
            let p = (self.current[0], self.current[1]);
            self.move_end_and_flush(p, out)?;
            self.queue.flush(out);
            self.arc_not_allowed = true;
        }
        self.side = None;
        self.first_move = true;
        Ok(())
    }

    /// The lathe tool's orientation (the tool table's Q, 1..8): in the XZ
    /// plane the moves go out for the tool's imaginary tip, not the
    /// centre of its nose radius, as rs274 does (shifts measured with
    /// rs274 2.9, `tests/programs/linuxcnc/oracle/comp-lathe-q*.ngc`).
    pub fn set_tip(&mut self, orientation: i64) {
        let (dx, dz) = tip_direction(orientation);
        self.queue.tip = if self.queue.xz {
            (dz * self.radius, dx * self.radius)
        } else {
            (0.0, 0.0)
        };
    }

    /// Whether compensation is on.
    pub fn is_on(&self) -> bool {
        self.side.is_some()
    }

    /// The side, when on.
    pub fn side(&self) -> Option<CompSide> {
        self.side
    }

    /// The tool radius in use.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Where the tool really is (x, y, z) once the entry move has been
    /// made; `None` while off or before the entry move.
    pub fn compensated(&self) -> Option<[f64; 3]> {
        let c = self.current;
        let real = if self.queue.xz { [c[1], c[2], c[0]] } else { c };
        (self.is_on() && self.radius > 0.0 && !self.first_move).then_some(real)
    }

    /// A pose in the engine's plane order (XZ: Z X Y).
    fn to_plane(&self, p: Pose) -> Pose {
        if self.queue.xz {
            [p[2], p[0], p[1], p[3], p[4], p[5]]
        } else {
            p
        }
    }

    /// Errors when the plane is changed while compensation is on.
    pub fn check_plane_change(&self) -> Result<(), CompError> {
        if self.is_on() {
            return Err(self.error(CompErrorKind::PlaneChange, None));
        }
        Ok(())
    }

    /// Emits everything held back (program end, or before a call that
    /// must not overtake the held-back move).
    pub fn flush(&mut self, out: &mut dyn FnMut(Canon)) {
        self.queue.flush(out);
    }

    /// A non-motion call. Feed, dwell, coolant, spindle and comment calls
    /// wait behind a held-back move; messages go out at once; anything
    /// else (e.g. `PROGRAM_STOP`) first flushes the queue, as rs274 does.
    pub fn other(&mut self, call: Canon, out: &mut dyn FnMut(Canon)) {
        if self.queue.is_empty() || queue::jumps_queue(&call) {
            out(call);
        } else if queue::is_queueable(&call) {
            self.queue.push(queue::Queued::Other(call));
        } else {
            self.queue.flush(out);
            out(call);
        }
    }

    /// A straight move from the programmed `from` to the programmed `to`.
    pub fn straight(
        &mut self,
        kind: MoveKind,
        from: Pose,
        to: Pose,
        out: &mut dyn FnMut(Canon),
    ) -> Result<(), CompError> {
        // rs274 compensates only with a radius above zero: with D0 (or
        // no tool) the moves go out as programmed.
        if self.side.is_none() || self.radius == 0.0 {
            self.arc_not_allowed = false;
            self.queue.flush(out);
            out(match kind {
                MoveKind::Rapid => Canon::StraightTraverse(to),
                MoveKind::Feed => Canon::StraightFeed(to),
            });
            return Ok(());
        }
        let (from, to) = (self.to_plane(from), self.to_plane(to));
        if self.first_move {
            self.straight_entry(kind, from, to)
        } else {
            self.straight_next(kind, from, to, out)
        }
    }

    /// An arc in the compensation plane from the programmed `from` to the
    /// programmed `to` round `centre` (the plane's first and second axes), `rotation` turns with sign (+ CCW, as in
    /// `ARC_FEED`); the Z end is `to[2]`. For the entry arc the centre must
    /// be the one LinuxCNC finds from I/J (start + offset).
    pub fn arc(
        &mut self,
        from: Pose,
        to: Pose,
        centre: (f64, f64),
        rotation: i64,
        out: &mut dyn FnMut(Canon),
    ) -> Result<(), CompError> {
        if self.side.is_none() || self.radius == 0.0 {
            if self.side.is_none() && self.arc_not_allowed {
                return Err(self.error(CompErrorKind::ArcAfterExit, None));
            }
            self.queue.flush(out);
            // Zero-radius compensation (D0) in G18 still writes the arc in
            // the plane's axis order (Z X, Y the axis end), as rs274 does.
            let p = if self.side.is_some() {
                self.to_plane(to)
            } else {
                to
            };
            out(Canon::ArcFeed {
                first_end: p[0],
                second_end: p[1],
                first_axis: centre.0,
                second_axis: centre.1,
                rotation,
                axis_end: p[2],
                abc: [p[3], p[4], p[5]],
            });
            return Ok(());
        }
        let (from, to) = (self.to_plane(from), self.to_plane(to));
        if self.first_move {
            self.arc_entry(from, to, centre, rotation)
        } else {
            self.arc_next(from, to, centre, rotation, out)
        }
    }

    fn left(&self) -> bool {
        self.side == Some(CompSide::Left)
    }

    fn error(&self, kind: CompErrorKind, held: Option<BlockTag>) -> CompError {
        CompError {
            kind,
            block: self.block,
            held,
        }
    }

    fn move_end_and_flush(
        &mut self,
        p: (f64, f64),
        out: &mut dyn FnMut(Canon),
    ) -> Result<(), CompError> {
        self.queue
            .move_end_and_flush(p, out)
            .map_err(|(kind, held)| self.error(kind, Some(held)))
    }
}

/// From the nose centre to the imaginary tip of a lathe tool, in radii
/// along X and Z, by orientation (LinuxCNC's numbering; 0 and 9: the
/// centre).
fn tip_direction(orientation: i64) -> (f64, f64) {
    match orientation {
        1 => (-1.0, 1.0),
        2 => (-1.0, -1.0),
        3 => (1.0, -1.0),
        4 => (1.0, 1.0),
        5 => (0.0, 1.0),
        6 => (-1.0, 0.0),
        7 => (0.0, -1.0),
        8 => (1.0, 0.0),
        _ => (0.0, 0.0),
    }
}

/// The side compensation works on: a negative radius swaps it.
fn side_of(side: CompSide, swap: bool) -> CompSide {
    match (side, swap) {
        (CompSide::Left, false) | (CompSide::Right, true) => CompSide::Left,
        _ => CompSide::Right,
    }
}
