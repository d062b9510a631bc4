//! The machine's modal state while a program runs. Lengths are kept in
//! millimetres internally and converted to the program's units where the
//! canon prints them.

use crate::canon::CanonPlane;
use crate::interp::host::SpindleDir;
use crate::ir::{CompSide, CycleKind, FeedMode, LengthUnit, MotionKind};

pub const MM_PER_INCH: f64 = 25.4;

/// The modal motion: what a block with axis words and no motion code does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ModalMotion {
    None,
    Move(MotionKind),
    Cycle(CycleKind),
}

/// Path control mode (G61, G61.1, G64 P Q).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PathControl {
    ExactStop,
    ExactPath,
    Continuous { tolerance: f64, naive: f64 },
}

#[derive(Clone, Debug)]
pub struct State {
    pub units: LengthUnit,
    /// Current position x y z a b c u v w: program frame, mm (angles in degrees).
    pub pos: [f64; 9],
    pub plane: CanonPlane,
    pub absolute: bool,
    pub arc_absolute: bool,
    pub feed_mode: FeedMode,
    /// Feed rate as programmed, in program units per minute (or per rev).
    pub feed: f64,
    pub speed: f64,
    pub spindle: SpindleDir,
    pub motion: ModalMotion,
    /// The G00/G01 in force when a canned cycle began: a control whose
    /// cycles are a modal group of their own (Fanuc group 09) goes back to
    /// it at G80.
    pub motion_before_cycle: Option<MotionKind>,
    /// Active work offset 1..=9 (G54..G59.3).
    pub g5x_index: u32,
    /// Work offsets 1..=9, mm; index 0 unused.
    pub g5x: [[f64; 9]; 10],
    /// XY rotation of each work offset, degrees.
    pub g5x_rotation: [f64; 10],
    /// G92 offset, mm.
    pub g92: [f64; 9],
    pub g92_applied: bool,
    /// #5210, LinuxCNC's G92 flag: 1 after G92/G52/G92.3, 0 after
    /// G92.1/G92.2, or what the parameter file gave.
    pub g92_flag: f64,
    /// Tool length offset x y z a b c u v w, mm.
    pub tool_offset: [f64; 9],
    /// Tool number in the spindle (0: none) and the one selected.
    pub tool_in_spindle: i64,
    /// The tool-table row rs274 treats as the one in the spindle (its
    /// `current_pocket`): row 1 before any change (checked with rs274 2.9),
    /// then the row of the tool M6 or M61 loaded (0 after `T0 M6`). A G10
    /// L1/L10/L11 on that row also rewrites row 0 and #5400..#5410.
    pub spindle_row: i64,
    pub tool_selected: Option<i64>,
    pub comp_side: CompSide,
    pub comp_radius: f64,
    pub retract_initial: bool,
    pub path: PathControl,
    pub flood: bool,
    pub mist: bool,
    /// M48..M51: feed and spindle-speed overrides enabled.
    pub feed_override: bool,
    pub speed_override: bool,
    /// Tool number set by M61 (reported, not used for G43).
    pub tool_number: i64,
    /// G53 in force for the block being run.
    pub machine_coords: bool,
    /// Constant surface speed maximum (G96 D), 0 when off.
    pub css_max: f64,
    /// G7: X words are diameters (halved).
    pub lathe_diameter: bool,
    /// G33/G33.1 K: distance per spindle revolution.
    pub sync_pitch: f64,
    /// The block of the last M61 (G43 in that block uses its tool).
    pub m61_block: Option<crate::span::Span>,
    /// The tool whose table length the active length offset is (the H
    /// register of G43/G44/G43.2, or the tool in the spindle); None when
    /// no table length is active (G49, G43.1, power-on).
    pub length_tool: Option<i64>,
    /// The active table length is subtracted (G44), not added (G43).
    pub length_negative: bool,
    /// The radius register (D) last programmed (see capability
    /// `comp-register-modal`).
    pub comp_register: Option<f64>,
    /// Where the canon layer last put the tool (program frame, mm): the
    /// current position without tool-length shifts since the last move.
    pub canon_pos: [f64; 9],
    /// A tool change happened: the next block re-reads the position from
    /// the canon layer (as rs274 does), dropping tool-length shifts.
    pub resync: bool,
    /// The last values converted by [`State::pose6_to_prog`].
    prog_cache: std::cell::Cell<ProgCache>,
}

/// The last value converted on each axis, in mm (as bits, so that -0 and
/// 0 differ), and its conversion.
#[derive(Clone, Copy, Debug)]
struct ProgCache {
    units: LengthUnit,
    key: [u64; 6],
    pose: [f64; 6],
}

impl State {
    pub fn new() -> State {
        State {
            units: LengthUnit::Mm,
            pos: [0.0; 9],
            plane: CanonPlane::XY,
            absolute: true,
            arc_absolute: false,
            feed_mode: FeedMode::PerMinute,
            feed: 0.0,
            speed: 0.0,
            spindle: SpindleDir::Stopped,
            motion: ModalMotion::None,
            motion_before_cycle: None,
            g5x_index: 1,
            g5x: [[0.0; 9]; 10],
            g5x_rotation: [0.0; 10],
            g92: [0.0; 9],
            g92_applied: false,
            g92_flag: 0.0,
            tool_offset: [0.0; 9],
            tool_in_spindle: 0,
            spindle_row: 1,
            tool_selected: None,
            comp_side: CompSide::Off,
            comp_radius: 0.0,
            retract_initial: false,
            path: PathControl::Continuous {
                tolerance: 0.0,
                naive: 0.0,
            },
            flood: false,
            mist: false,
            feed_override: true,
            speed_override: true,
            tool_number: 0,
            machine_coords: false,
            css_max: 0.0,
            lathe_diameter: false,
            sync_pitch: 0.0,
            m61_block: None,
            length_tool: None,
            length_negative: false,
            comp_register: None,
            canon_pos: [0.0; 9],
            resync: false,
            prog_cache: std::cell::Cell::new(ProgCache {
                units: LengthUnit::Mm,
                key: [0; 6],
                pose: [0.0; 6],
            }),
        }
    }

    /// mm per program unit.
    pub fn scale(&self) -> f64 {
        match self.units {
            LengthUnit::Mm => 1.0,
            LengthUnit::Inch => MM_PER_INCH,
        }
    }

    /// A length in program units, as mm.
    pub fn to_mm(&self, v: f64) -> f64 {
        v * self.scale()
    }

    /// A length in mm, in program units; the noise of the round trip
    /// through mm (1.5 in -> 38.1 mm -> 1.4999999999999998 in) is removed,
    /// so that comparisons (R plane against the current level) see the
    /// number as written.
    pub fn to_prog(&self, mm: f64) -> f64 {
        let v = match self.units {
            LengthUnit::Mm => mm,
            LengthUnit::Inch => mm / MM_PER_INCH,
        };
        if !(v.abs() < 1e6) {
            return v;
        }
        let snapped = round_small(v * 1e9) / 1e9;
        if (v - snapped).abs() < 1e-12 {
            snapped
        } else {
            v
        }
    }

    /// Is axis `i` (0..9) a length axis (X Y Z U V W) rather than an angle?
    pub fn is_linear(i: usize) -> bool {
        !(3..6).contains(&i)
    }

    /// The first six axes of a pose in mm/degrees, in program units
    /// (lengths only). Each axis's last conversion is remembered: moves
    /// convert the same values again and again.
    pub fn pose6_to_prog(&self, p: &[f64; 9]) -> [f64; 6] {
        let mut c = self.prog_cache.get();
        let same_units = c.units == self.units;
        c.units = self.units;
        for i in 0..6 {
            let bits = p[i].to_bits();
            if same_units && c.key[i] == bits {
                continue;
            }
            c.key[i] = bits;
            c.pose[i] = if State::is_linear(i) {
                self.to_prog(p[i])
            } else {
                p[i]
            };
        }
        self.prog_cache.set(c);
        c.pose
    }

    /// A pose in mm/degrees converted to program units (lengths only).
    pub fn pose_to_prog(&self, p: &[f64; 9]) -> [f64; 9] {
        let mut out = *p;
        for (i, v) in out.iter_mut().enumerate() {
            if State::is_linear(i) {
                *v = self.to_prog(*v);
            }
        }
        out
    }
}

/// `x.round()` (half away from zero) for `|x| < 2^52`, without a libm
/// call: the integer part is exact there, and so is the remainder.
fn round_small(x: f64) -> f64 {
    let t = (x as i64) as f64;
    let frac = x - t;
    if frac >= 0.5 {
        t + 1.0
    } else if frac <= -0.5 {
        t - 1.0
    } else if t == 0.0 && x.is_sign_negative() {
        -0.0
    } else {
        t
    }
}

impl Default for State {
    fn default() -> Self {
        State::new()
    }
}

/// Where the program frame sits in machine coordinates, as rs274 places
/// it: `machine = R(rotation) (program + G92) + work offset + tool offset`,
/// the rotation (G10 L2 R, degrees) turning X and Y only, about the work
/// origin, with G92 inside the rotated frame. Lengths in mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub g5x: [f64; 9],
    pub g92: [f64; 9],
    pub tool: [f64; 9],
    pub rotation: f64,
}

/// Turns (x, y) by `deg` degrees counterclockwise.
/// The geometry kernel's rotation about Z, unsnapped as rs274 computes it.
pub fn rotate_xy(x: f64, y: f64, deg: f64) -> (f64, f64) {
    let v = crate::geom::Transform::rot_z_unsnapped(deg).apply_dir(crate::geom::V3::new(x, y, 0.0));
    (v.x, v.y)
}

impl Placement {
    /// The plain sum of the offsets (the whole origin when unrotated).
    pub fn origin(&self) -> [f64; 9] {
        std::array::from_fn(|i| self.g5x[i] + self.g92[i] + self.tool[i])
    }

    /// Machine coordinates of a program point.
    pub fn to_machine(&self, p: &[f64; 9]) -> [f64; 9] {
        let o = self.origin();
        let mut m: [f64; 9] = std::array::from_fn(|i| p[i] + o[i]);
        if self.rotation != 0.0 {
            let (x, y) = rotate_xy(p[0] + self.g92[0], p[1] + self.g92[1], self.rotation);
            m[0] = x + self.g5x[0] + self.tool[0];
            m[1] = y + self.g5x[1] + self.tool[1];
        }
        m
    }

    /// Program coordinates of a machine point.
    pub fn from_machine(&self, m: &[f64; 9]) -> [f64; 9] {
        let o = self.origin();
        let mut p: [f64; 9] = std::array::from_fn(|i| m[i] - o[i]);
        if self.rotation != 0.0 {
            let (x, y) = rotate_xy(
                m[0] - self.g5x[0] - self.tool[0],
                m[1] - self.g5x[1] - self.tool[1],
                -self.rotation,
            );
            p[0] = x - self.g92[0];
            p[1] = y - self.g92[1];
        }
        p
    }
}

impl State {
    /// The origin of the program frame in machine coordinates, mm:
    /// work offset plus G92 offset (when applied) plus tool length offset
    /// (the rotation aside: see [`Self::placement`]).
    pub fn origin(&self) -> [f64; 9] {
        self.placement().origin()
    }

    /// The placement of the program frame (work offset `index`).
    pub fn placement_in(&self, index: u32) -> Placement {
        let ix = (index as usize).min(self.g5x.len() - 1);
        Placement {
            g5x: self.g5x[ix],
            g92: if self.g92_applied { self.g92 } else { [0.0; 9] },
            tool: self.tool_offset,
            rotation: self.g5x_rotation[ix],
        }
    }

    /// The placement of the program frame in force.
    pub fn placement(&self) -> Placement {
        self.placement_in(self.g5x_index)
    }

    /// The current position in machine coordinates, mm.
    pub fn machine_pos(&self) -> [f64; 9] {
        self.placement().to_machine(&self.pos)
    }

    /// Moves the current position by the change of placement from `old`
    /// (the tool stays where it is; its program coordinates change).
    pub fn reframe(&mut self, old: Placement) {
        let new = self.placement();
        self.pos = Self::moved(old, new, &self.pos);
        self.canon_pos = Self::moved(old, new, &self.canon_pos);
    }

    /// A point's program coordinates after a change of placement (without
    /// rotation, as a shift by the change of origin, to keep the sums exact).
    fn moved(old: Placement, new: Placement, p: &[f64; 9]) -> [f64; 9] {
        if old.rotation == 0.0 && new.rotation == 0.0 {
            let (o, n) = (old.origin(), new.origin());
            std::array::from_fn(|i| p[i] + (o[i] - n[i]))
        } else {
            new.from_machine(&old.to_machine(p))
        }
    }

    /// As [`Self::reframe`] for a tool length change: the canon layer's
    /// position is not shifted.
    pub fn reframe_keep_canon(&mut self, old: Placement) {
        let new = self.placement();
        self.pos = Self::moved(old, new, &self.pos);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn round_small_is_round() {
        let mut state = 0x2545f4914f6cdd1du64;
        for i in 0..200_000u64 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let mag = [0.5, 1.0, 1e3, 1e9, 1e15][(i % 5) as usize];
            let x = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0 * mag;
            let x = if i % 3 == 0 {
                (x * 2.0).round() / 2.0
            } else {
                x
            };
            let (a, b) = (super::round_small(x), x.round());
            assert!(
                a == b && a.is_sign_negative() == b.is_sign_negative(),
                "{x:e}: {a} {b}"
            );
        }
        for x in [
            0.5,
            -0.5,
            1.5,
            -2.5,
            0.49999999999999994,
            -0.0,
            0.0,
            -0.3,
            4503599627370495.5,
        ] {
            assert_eq!(super::round_small(x).to_bits(), x.round().to_bits(), "{x}");
        }
    }
}
