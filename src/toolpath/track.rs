//! Follows a canonical stream and resolves each motion call into a
//! [`Move`] in millimetres, work coordinates (see the module doc of
//! [`super`]).

use super::{ArcGeom, CoolantState, Event, FeedMode, Move, MoveKind, P3};
use crate::canon::{Canon, CanonPlane, CanonUnits, Pose};
use crate::span::Span;

/// The machine state a canonical stream builds up.
#[derive(Clone, Debug)]
pub struct Tracker {
    /// Millimetres per program unit (1 or 25.4).
    scale: f64,
    g5x: P3,
    g92: P3,
    /// XY rotation in degrees (about the G5x origin).
    rotation: f64,
    plane: CanonPlane,
    /// The current position, work coordinates.
    pos: P3,
    /// The tool length offset in force (program units).
    length_offset: [f64; 3],
    /// Where the tool is in the frame of a new length offset (the machine
    /// stays, the controlled point moves), until the next move: a move
    /// there (`G1` alone after `G43`, which rs274 gives as a feed to its
    /// current position) goes nowhere.
    here_after_offset: Option<P3>,
    feed: f64,
    feed_mode: FeedMode,
    selected: i64,
    tool: i64,
    speed: f64,
    /// +1 clockwise, -1 counter-clockwise, 0 stopped.
    direction: f64,
    coolant: CoolantState,
    /// Spindle-synchronised feed (rigid tapping): mm per revolution.
    sync_pitch: Option<f64>,
}

impl Default for Tracker {
    fn default() -> Self {
        Self::new()
    }
}

impl Tracker {
    pub fn new() -> Self {
        Tracker {
            scale: 1.0,
            g5x: [0.0; 3],
            g92: [0.0; 3],
            rotation: 0.0,
            plane: CanonPlane::XY,
            pos: [0.0; 3],
            length_offset: [0.0; 3],
            here_after_offset: None,
            feed: 0.0,
            feed_mode: FeedMode::PerMinute,
            selected: 0,
            tool: 0,
            speed: 0.0,
            direction: 0.0,
            coolant: CoolantState::default(),
            sync_pitch: None,
        }
    }

    /// The current position, work coordinates (mm).
    pub fn position(&self) -> P3 {
        self.pos
    }

    /// The tool length offset in force along Z (mm).
    pub fn length_offset_mm(&self) -> f64 {
        self.length_offset[2] * self.scale
    }

    /// The tool in the spindle.
    pub fn tool(&self) -> i64 {
        self.tool
    }

    /// A program-frame point (program units) in work coordinates (mm).
    fn to_work(&self, p: [f64; 3]) -> P3 {
        let q = [
            (p[0] + self.g92[0]) * self.scale,
            (p[1] + self.g92[1]) * self.scale,
            (p[2] + self.g92[2]) * self.scale,
        ];
        let (s, c) = self.rotation.to_radians().sin_cos();
        [
            q[0] * c - q[1] * s + self.g5x[0],
            q[0] * s + q[1] * c + self.g5x[1],
            q[2] + self.g5x[2],
        ]
    }

    /// A program-frame XY point (program units) at work height `z` (mm).
    fn to_work_at(&self, xy: [f64; 2], z: f64) -> P3 {
        let mut p = self.to_work([xy[0], xy[1], 0.0]);
        p[2] = z;
        p
    }

    fn offsets(&self, pose: &Pose) -> P3 {
        [
            pose[0] * self.scale,
            pose[1] * self.scale,
            pose[2] * self.scale,
        ]
    }

    /// A new tool length offset: the machine stays where it is, so in the
    /// new offset's frame the tool is elsewhere (see `here_after_offset`).
    /// The path is followed in program coordinates, as before.
    fn apply_length_offset(&mut self, o: [f64; 3]) {
        let mut here = self.here_after_offset.unwrap_or(self.pos);
        for (k, v) in o.iter().enumerate() {
            here[k] -= (v - self.length_offset[k]) * self.scale;
        }
        self.here_after_offset = Some(here);
        self.length_offset = o;
    }

    /// Is a move to `to` the null move to where the tool already is?
    fn goes_nowhere(&mut self, to: &P3) -> bool {
        self.here_after_offset
            .take()
            .is_some_and(|h| crate::toolpath::dist(h, *to) <= 1e-9)
    }

    fn make(&mut self, kind: MoveKind, to: P3, span: Span) -> Event {
        self.here_after_offset = None;
        let from = std::mem::replace(&mut self.pos, to);
        // Synchronised with the spindle, a move advances one pitch per
        // revolution: pitch x speed per minute.
        let feed = match self.sync_pitch {
            Some(p) if kind != MoveKind::Rapid => p * self.speed,
            _ => self.feed,
        };
        Event::Move(Move {
            kind,
            from,
            to,
            feed,
            feed_mode: self.feed_mode,
            tool: self.tool,
            spindle: self.speed * self.direction,
            coolant: self.coolant,
            span,
        })
    }

    /// Takes one call; hands the events it makes (none, one, or two for a
    /// rigid tap's in and out) to `emit`.
    pub fn push(&mut self, call: &Canon, span: Span, mut emit: impl FnMut(Event)) {
        if let Some(e) = self.step(call, span, &mut emit) {
            emit(e);
        }
    }

    fn step(&mut self, call: &Canon, span: Span, emit: &mut impl FnMut(Event)) -> Option<Event> {
        use Canon::*;
        match call {
            UseLengthUnits(u) => {
                self.scale = match u {
                    CanonUnits::Inches => 25.4,
                    CanonUnits::Mm => 1.0,
                }
            }
            SetG5xOffset { offset, .. } => self.g5x = self.offsets(offset),
            SetG92Offset(o) => self.g92 = [o[0], o[1], o[2]],
            UseToolLengthOffset(o) => self.apply_length_offset([o[0], o[1], o[2]]),
            SetXyRotation(r) => self.rotation = *r,
            SelectPlane(p) => self.plane = *p,
            SetFeedRate(f) => self.feed = f * self.scale,
            SetFeedMode(m) => {
                self.feed_mode = if *m == 1 {
                    FeedMode::PerRev
                } else {
                    FeedMode::PerMinute
                }
            }
            SelectTool(t) => self.selected = *t,
            ChangeTool(_) | ChangeToolNumber(_) => {
                self.tool = self.selected;
                return Some(Event::ToolChange {
                    tool: self.tool,
                    span,
                });
            }
            StopSpindle => self.direction = 0.0,
            SpindleCw => self.direction = 1.0,
            SpindleCcw => self.direction = -1.0,
            SetSpindleSpeed(s) => self.speed = *s,
            FloodOn => self.coolant.flood = true,
            FloodOff => self.coolant.flood = false,
            MistOn => self.coolant.mist = true,
            MistOff => self.coolant.mist = false,
            StraightTraverse(p) | StraightFeed(p)
                if self.goes_nowhere(&self.to_work([p[0], p[1], p[2]])) => {}
            StraightTraverse(p) => {
                return Some(self.make(MoveKind::Rapid, self.to_work([p[0], p[1], p[2]]), span))
            }
            StraightFeed(p) => {
                return Some(self.make(MoveKind::Line, self.to_work([p[0], p[1], p[2]]), span))
            }
            StraightProbe(p) => {
                return Some(self.make(MoveKind::Probe, self.to_work([p[0], p[1], p[2]]), span))
            }
            RigidTap { x, y, z } => {
                // Down to the point and back out along the same line,
                // the spindle reversed on the way out (as the tap turns).
                let start = self.pos;
                let down = self.to_work([*x, *y, *z]);
                emit(self.make(MoveKind::Line, down, span));
                let mut out = self.make(MoveKind::Line, start, span);
                if let Event::Move(m) = &mut out {
                    m.spindle = -m.spindle;
                }
                return Some(out);
            }
            ArcFeed {
                first_end,
                second_end,
                first_axis,
                second_axis,
                rotation,
                axis_end,
                ..
            } => {
                return Some(self.arc(
                    *first_end,
                    *second_end,
                    [*first_axis, *second_axis],
                    *rotation,
                    *axis_end,
                    span,
                ))
            }
            NurbsFeed { points, order } => {
                // Straight segments along the curve, fine enough to plot
                // and compare; the height stays where it is.
                let z = self.pos[2];
                let n = (points.len() * 16).clamp(16, 4096);
                let samples = super::nurbs::sample(points, *order, n);
                let last = samples.len().saturating_sub(1);
                for (i, q) in samples.into_iter().enumerate() {
                    let to = self.to_work_at([q[0], q[1]], z);
                    let m = self.make(MoveKind::Line, to, span);
                    if i == last {
                        return Some(m);
                    }
                    emit(m);
                }
            }
            StartSpeedFeedSync { pitch, .. } => self.sync_pitch = Some(pitch * self.scale),
            StopSpeedFeedSync => self.sync_pitch = None,
            Dwell(s) => return Some(Event::Dwell { seconds: *s, span }),
            ProgramStop | OptionalProgramStop => return Some(Event::Stop { end: false, span }),
            ProgramEnd => return Some(Event::Stop { end: true, span }),
            Comment(t) | Message(t) => {
                return Some(Event::Comment {
                    text: t.clone(),
                    span,
                })
            }
            OnReset
            | SetFeedReference
            | LogOpen(_)
            | LogAppend(_)
            | Log(_)
            | LogClose
            | StartChange
            | SetSpindleMode(_)
            | OrientSpindle { .. }
            | WaitOrientComplete(_)
            | SetMotionControlMode(_)
            | SetNaivecamTolerance(_)
            | PalletShuttle
            | Finish
            | EnableFeedOverride
            | DisableFeedOverride
            | EnableSpeedOverride
            | DisableSpeedOverride
            | EnableAdaptiveFeed
            | DisableAdaptiveFeed
            | EnableFeedHold
            | DisableFeedHold
            | TurnProbeOn
            | TurnProbeOff
            | SetToolTableEntry { .. }
            | Io(_) => {}
        }
        None
    }

    fn arc(&mut self, e1: f64, e2: f64, c: [f64; 2], rotation: i64, w: f64, span: Span) -> Event {
        // Program-frame end and centre, then both into work coordinates.
        let axes = match self.plane {
            CanonPlane::XY => [0, 1, 2],
            CanonPlane::YZ => [1, 2, 0],
            CanonPlane::XZ => [2, 0, 1],
        };
        let mut end = [0.0; 3];
        let mut centre = [0.0; 3];
        end[axes[0]] = e1;
        end[axes[1]] = e2;
        end[axes[2]] = w;
        centre[axes[0]] = c[0];
        centre[axes[1]] = c[1];
        let end = self.to_work(end);
        let mut centre = self.to_work(centre);
        centre[axes[2]] = self.pos[axes[2]];
        let geom = ArcGeom {
            axes,
            centre,
            rotation,
        };
        self.make(MoveKind::Arc(geom), end, span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(calls: &[Canon]) -> Vec<Event> {
        let mut t = Tracker::new();
        let mut out = Vec::new();
        for c in calls {
            t.push(c, Span::default(), |e| out.push(e));
        }
        out
    }

    fn moves(ev: &[Event]) -> Vec<&Move> {
        ev.iter()
            .filter_map(|e| match e {
                Event::Move(m) => Some(m),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn inches_offsets_and_rotation_become_work_millimetres() {
        let ev = run(&[
            Canon::UseLengthUnits(CanonUnits::Inches),
            Canon::SetG5xOffset {
                index: 1,
                offset: [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            },
            Canon::SetXyRotation(90.0),
            Canon::SetFeedRate(10.0),
            Canon::StraightFeed([1.0, 0.0, -0.5, 0.0, 0.0, 0.0]),
        ]);
        let m = moves(&ev)[0];
        assert!((m.to[0] - 25.4).abs() < 1e-9 && (m.to[1] - 25.4).abs() < 1e-9);
        assert!((m.to[2] + 12.7).abs() < 1e-9);
        assert!((m.feed - 254.0).abs() < 1e-9);
        assert_eq!(m.from, [0.0; 3]);
    }

    /// rs274 gives `G1` alone after `G43 H1` as a feed to its current
    /// position in the new offset's frame: the machine does not move, so
    /// it is no plunge; the next real move still counts.
    #[test]
    fn a_move_to_where_the_tool_is_after_a_length_offset_goes_nowhere() {
        let ev = run(&[
            Canon::StraightTraverse([0.0, 0.0, 5.0, 0.0, 0.0, 0.0]),
            Canon::UseToolLengthOffset([0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
            Canon::SetFeedRate(10.0),
            Canon::StraightFeed([0.0, 0.0, 3.0, 0.0, 0.0, 0.0]),
            Canon::StraightFeed([0.0, 0.0, 3.0, 0.0, 0.0, 0.0]),
        ]);
        let m = moves(&ev);
        assert_eq!(m.len(), 2, "{m:?}");
        assert_eq!(m[1].to, [0.0, 0.0, 3.0]);
        assert_eq!(m[1].from, [0.0, 0.0, 5.0]);
    }

    #[test]
    fn arcs_tools_spindle_and_rigid_taps() {
        let ev = run(&[
            Canon::SelectTool(3),
            Canon::ChangeTool(1),
            Canon::SetSpindleSpeed(1000.0),
            Canon::SpindleCcw,
            Canon::StraightTraverse([10.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
            Canon::ArcFeed {
                first_end: 0.0,
                second_end: 10.0,
                first_axis: 0.0,
                second_axis: 0.0,
                rotation: 1,
                axis_end: -1.0,
                abc: [0.0; 3],
            },
            Canon::RigidTap {
                x: 0.0,
                y: 10.0,
                z: -5.0,
            },
        ]);
        assert!(matches!(ev[0], Event::ToolChange { tool: 3, .. }));
        let m = moves(&ev);
        assert_eq!(m.len(), 4);
        assert_eq!(m[1].spindle, -1000.0);
        assert_eq!(m[1].tool, 3);
        let len = m[1].length();
        assert!((len - (5.0 * std::f64::consts::PI).hypot(1.0)).abs() < 1e-9);
        assert_eq!(m[3].to, m[2].from);
    }
}
