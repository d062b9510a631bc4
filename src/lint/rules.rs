//! The lint rules, and the checks made on the interpreter's run. Every
//! check reads what the run computed (the [`Step`]: the block, its
//! canonical calls, the modal state after it, cycle values, tool data);
//! none rebuilds modal state.

use super::Linter;
use crate::canon::{Canon, CanonPlane};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::interp::host::SpindleDir;
use crate::interp::state::ModalMotion;
use crate::interp::watch::Step;
use crate::ir::{CycleKind, DimMode, StmtKind};
use crate::span::Span;

/// A lint rule: its code (name and text in [`crate::diag::codes`]),
/// whether it runs by default, and which dialects it applies to (asked
/// of the spec, never by name).
pub struct Rule {
    pub code: Code,
    pub default: bool,
    pub applies: fn(&DialectSpec) -> bool,
}

fn always(_: &DialectSpec) -> bool {
    true
}

fn length_programmed(s: &DialectSpec) -> bool {
    s.has(Capability::LengthOffsetProgrammed)
}

fn register_names_tool(s: &DialectSpec) -> bool {
    s.has(Capability::LengthRegisterNamesTool)
}

/// Where the spec already makes a missing end an error (E0305).
fn end_optional(s: &DialectSpec) -> bool {
    !s.has(Capability::ProgramEndRequired)
}

/// Dialects with codes that select a work offset (G54..).
fn has_work_offsets(s: &DialectSpec) -> bool {
    s.code_for(crate::dialect::Meaning::WorkOffset(1)).is_some()
}

pub const RULES: &[Rule] = &[
    Rule {
        code: Code::LintFeedSpindleStopped,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintNoLengthOffset,
        default: true,
        applies: length_programmed,
    },
    Rule {
        code: Code::LintLengthOffsetOtherTool,
        default: true,
        applies: register_names_tool,
    },
    Rule {
        code: Code::LintNoProgramEnd,
        default: true,
        applies: end_optional,
    },
    Rule {
        code: Code::LintMoveAfterEnd,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintIncrementalToolChange,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintIncrementalCall,
        default: false,
        applies: always,
    },
    Rule {
        code: Code::LintIncrementalAfterReturn,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintRapidBelowCut,
        default: false,
        applies: always,
    },
    Rule {
        code: Code::LintNoUnits,
        default: false,
        applies: always,
    },
    Rule {
        code: Code::LintNoWorkOffset,
        default: false,
        applies: has_work_offsets,
    },
    Rule {
        code: Code::LintCycleRBelowCut,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintPeckTooDeep,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintStopWithoutMessage,
        default: false,
        applies: always,
    },
    Rule {
        code: Code::LintCuttingWithoutCoolant,
        default: false,
        applies: always,
    },
    Rule {
        code: Code::LintSpindleSpeedZero,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintSpeedForTool,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintFeedForTool,
        default: true,
        applies: always,
    },
    Rule {
        code: Code::LintOtherUnit,
        default: true,
        applies: always,
    },
];

/// The rule of a code, if it is a lint code.
pub fn rule(code: Code) -> Option<&'static Rule> {
    RULES.iter().find(|r| r.code == code)
}

fn has(step: &Step<'_>, f: impl Fn(&StmtKind) -> bool) -> bool {
    step.block.stmts.iter().any(|s| f(&s.kind))
}

fn is_motion(c: &Canon) -> bool {
    matches!(
        c,
        Canon::StraightTraverse(_)
            | Canon::StraightFeed(_)
            | Canon::ArcFeed { .. }
            | Canon::NurbsFeed { .. }
            | Canon::RigidTap { .. }
    )
}

fn is_feed(c: &Canon) -> bool {
    matches!(
        c,
        Canon::StraightFeed(_)
            | Canon::ArcFeed { .. }
            | Canon::NurbsFeed { .. }
            | Canon::RigidTap { .. }
    )
}

/// Where a motion call ends, x y z a b c in program units (None for a
/// NURBS curve, whose end cncc does not keep here). An arc's ends are
/// named by the plane it ran in (as rs274 names them: G18's first axis
/// is Z).
fn pose_of(c: &Canon, plane: CanonPlane) -> Option<[f64; 6]> {
    match c {
        Canon::StraightTraverse(p) | Canon::StraightFeed(p) => Some(*p),
        Canon::ArcFeed {
            first_end: f,
            second_end: s,
            axis_end: a,
            abc,
            ..
        } => {
            let [x, y, z] = match plane {
                CanonPlane::XY => [*f, *s, *a],
                CanonPlane::YZ => [*a, *f, *s],
                CanonPlane::XZ => [*s, *a, *f],
            };
            Some([x, y, z, abc[0], abc[1], abc[2]])
        }
        _ => None,
    }
}

/// The Z a motion call ends at, in program units (None: no Z in it).
fn end_z(c: &Canon, plane: CanonPlane) -> Option<f64> {
    match c {
        Canon::RigidTap { z, .. } => Some(*z),
        _ => pose_of(c, plane).map(|p| p[2]),
    }
}

fn is_ref_return(k: &StmtKind) -> bool {
    matches!(k, StmtKind::RefReturn { .. } | StmtKind::MachineCoords)
}

impl Linter {
    /// One block of the run.
    pub fn step(&mut self, step: &Step<'_>) {
        self.enter_or_leave(step);
        let scale = step.state.scale();
        let machine = has(step, is_ref_return);
        let cycle_ran = matches!(step.state.motion, ModalMotion::Cycle(_))
            && step.calls.iter().any(|(c, _)| is_feed(c));
        if cycle_ran {
            self.cycle(step, scale);
        }
        // A length register (`H..`, the spec's `length-offset` address)
        // alone while G43 is in force changes the offset register
        // on Fanuc-like controls [?: G43 kept through M6 by the machine's
        // macro]: the new tool's length is active for this block's moves.
        if step.state.length_tool.is_some()
            && has(
                step,
                |k| matches!(k, StmtKind::OffsetRegister { letter, .. } if self.length_letters.contains(letter)),
            )
        {
            self.length_pending = None;
        }
        let mut moved = false;
        for (call, span) in step.calls {
            self.call(step, call, *span, scale, machine, cycle_ran, &mut moved);
        }
        if has(step, |k| matches!(k, StmtKind::Units { .. })) {
            self.units_set = true;
        }
        if has(step, |k| {
            matches!(k, StmtKind::WorkOffset { .. } | StmtKind::CoordShift { .. })
        }) {
            self.work_offset_set = true;
        }
        // A block without axis words may still make a call that goes
        // nowhere new (a resync after a tool change): not a move.
        let written = has(step, |k| match k {
            StmtKind::Motion(m) => {
                !m.target.is_empty() || m.polar_radius.is_some() || m.polar_angle.is_some()
            }
            StmtKind::Approach(_) => true,
            StmtKind::Cycle(_) | StmtKind::CycleCall(_) => true,
            _ => false,
        });
        if moved && written {
            self.first_motion.get_or_insert(step.block.span);
            self.after_move(step, machine);
        }
        if has(step, |k| matches!(k, StmtKind::RefReturn { .. })) && !step.state.absolute {
            self.ref_return = Some(step.block.span);
        }
        self.last_z_mm = step.state.pos[2];
        self.last_values = super::values::CutValues::of(step.state);
    }

    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        step: &Step<'_>,
        call: &Canon,
        span: Span,
        scale: f64,
        machine: bool,
        cycle_ran: bool,
        moved: &mut bool,
    ) {
        let block = step.block.span;
        match call {
            Canon::ChangeTool(_) => {
                self.length_pending = Some(span);
                self.after_change = Some(span);
                self.coolant_reported = false;
                self.rates = Default::default();
                self.forget_cuts();
            }
            Canon::UseToolLengthOffset(_) => {
                self.length_pending = None;
                self.other_tool(step, span);
            }
            Canon::UseLengthUnits(_) => self.units_set = true,
            // (A program end resets to G54 with a call too: whether the
            // program selects an offset is read from its statements.)
            Canon::SetG5xOffset { .. } | Canon::SetG92Offset(_) | Canon::SetXyRotation(_) => {
                self.forget_cuts()
            }
            Canon::SpindleCw | Canon::SpindleCcw => self.spindle_reported = false,
            Canon::SetSpindleSpeed(_) => {
                self.speed_reported = false;
                self.speed_programmed = true;
            }
            Canon::ProgramEnd => self.ended = true,
            _ => {}
        }
        if !is_motion(call) {
            return;
        }
        // A move an earlier block made and a later one let out (a held
        // corner) ran with the plane, feed, speed and spindle as that
        // earlier block left them.
        let inside =
            span.file == block.file && block.start <= span.start && span.start <= block.end;
        let values = if inside {
            super::values::CutValues::of(step.state)
        } else {
            self.last_values
        };
        let plane = values.plane;
        let pose = pose_of(call, plane).map(|p| p.map(|v| v * scale));
        if let (Some(p), Some(last)) = (pose, self.last_pose) {
            if (3..6).any(|i| (p[i] / scale - last[i] / scale).abs() > 1e-6) {
                // A rotary axis turned the part: heights of the cuts so
                // far are in another orientation.
                self.forget_cuts();
            }
        }
        if pose.is_none_or(|p| {
            self.last_pose
                .is_none_or(|l| (0..6).any(|i| (p[i] - l[i]).abs() > 1e-6))
        }) {
            *moved = true;
        }
        if pose.is_some() {
            self.last_pose = pose;
        }
        let z_mm = end_z(call, plane).map(|z| z * scale);
        if let (Some(z), Some(s)) = (z_mm, self.length_pending) {
            if (z - self.last_z_mm).abs() > 1e-6 && !machine {
                self.length_pending = None;
                self.report(
                    Diagnostic::new(
                        Code::LintNoLengthOffset,
                        "Z moves after a tool change before a length offset is activated for the new tool",
                    )
                    .primary(block, "first Z move of the new tool")
                    .secondary(s, "tool changed here")
                    .help("activate the new tool's length offset (G43 H..) in or before this block"),
                );
            }
        }
        if is_feed(call) {
            self.spindle_stopped(step, block, if inside { block } else { span }, values);
            if let Some(p) = pose_of(call, plane) {
                self.unit_values(block, values, [p[0], p[1], p[2]]);
            }
            if let (Some(z), Some(p)) = (z_mm, pose) {
                if plane == CanonPlane::XY {
                    self.min_cut_mm = Some(self.min_cut_mm.map_or(z, |m: f64| m.min(z)));
                    self.cut_box = Some(match self.cut_box {
                        None => [p[0], p[1], p[0], p[1]],
                        Some(b) => [
                            b[0].min(p[0]),
                            b[1].min(p[1]),
                            b[2].max(p[0]),
                            b[3].max(p[1]),
                        ],
                    });
                }
            }
            self.below_reported = false;
        } else if let (Some(z), Some(p), false, false) = (z_mm, pose, machine, cycle_ran) {
            self.rapid_below(step, block, z, [p[0], p[1]]);
        }
        if let Some(z) = z_mm {
            self.last_z_mm = z;
        }
    }

    /// W0701 (and W0715..W0718) at a feed move; `at` is its block, or the
    /// move itself where an earlier block made it.
    fn spindle_stopped(
        &mut self,
        step: &Step<'_>,
        block: Span,
        at: Span,
        values: super::values::CutValues,
    ) {
        let spindle = values.spindle;
        self.speed_and_coolant(step, block, spindle);
        self.cut_rates(step, at, values);
        if spindle != SpindleDir::Stopped || self.spindle_reported {
            return;
        }
        self.spindle_reported = true;
        self.report(
            Diagnostic::new(Code::LintFeedSpindleStopped, "cutting move while the spindle is stopped")
                .primary(at, "feed move with no M3/M4 in force")
                .help("start the spindle (S.. M3) before the first cutting move of each tool; later moves of this stretch are not reported"),
        );
    }

    /// W0716 and W0715, at a feed move.
    fn speed_and_coolant(&mut self, step: &Step<'_>, block: Span, spindle: SpindleDir) {
        let st = step.state;
        // A speed the program never set is the control's last one, not 0.
        if spindle != SpindleDir::Stopped
            && st.speed <= 0.0
            && self.speed_programmed
            && !self.speed_reported
        {
            self.speed_reported = true;
            self.report(
                Diagnostic::new(
                    Code::LintSpindleSpeedZero,
                    "cutting move with the spindle on at speed 0",
                )
                .primary(block, "feed move at S0")
                .help("program the tool's speed (S..) with M3/M4"),
            );
        }
        let coolant = st.flood || st.mist;
        if coolant {
            self.had_coolant = true;
        } else if self.had_coolant && !self.coolant_reported {
            self.coolant_reported = true;
            self.report(
                Diagnostic::new(Code::LintCuttingWithoutCoolant, "this tool cuts with coolant off; an earlier tool had it on")
                    .primary(block, "feed move with no M7/M8")
                    .help("switch the coolant on (M8) after the tool change, or ignore W0715 for dry cutting"),
            );
        }
    }

    fn rapid_below(&mut self, step: &Step<'_>, block: Span, z: f64, xy: [f64; 2]) {
        let Some(min) = self.min_cut_mm else { return };
        if step.state.plane != CanonPlane::XY
            || self.below_reported
            || z >= min - self.cfg.below_tolerance_mm
            || !self.over_cuts(xy)
        {
            return;
        }
        self.below_reported = true;
        let u = step.state.scale();
        self.report(
            Diagnostic::new(
                Code::LintRapidBelowCut,
                format!(
                    "rapid to Z{} below the lowest cut of this tool (Z{}) with no feed move between",
                    fmt(z / u),
                    fmt(min / u)
                ),
            )
            .primary(block, "rapid into material not cut yet")
            .help("retract, or feed (G1) down from the last cutting height"),
        );
    }

    /// Whether a point (mm) lies over the area this tool has cut (the box
    /// round its feed moves): outside it the tool may well be in the air
    /// beside the part, as CAM systems plunge for the next level.
    fn over_cuts(&self, xy: [f64; 2]) -> bool {
        let t = 1e-6;
        self.cut_box.is_some_and(|b| {
            xy[0] >= b[0] - t && xy[1] >= b[1] - t && xy[0] <= b[2] + t && xy[1] <= b[3] + t
        })
    }

    /// The cuts so far no longer tell where material is (a tool change,
    /// another work offset, a rotary axis turned).
    pub(super) fn forget_cuts(&mut self) {
        self.min_cut_mm = None;
        self.cut_box = None;
    }

    fn other_tool(&mut self, step: &Step<'_>, span: Span) {
        let (Some(h), t) = (step.state.length_tool, step.state.tool_in_spindle) else {
            return;
        };
        if t == 0 || h == t {
            return;
        }
        self.report(
            Diagnostic::new(
                Code::LintLengthOffsetOtherTool,
                format!("length offset of tool {h} while tool {t} is in the spindle"),
            )
            .primary(span, format!("H{h} is not T{t}"))
            .help(format!(
                "use H{t}, or ignore W0703 if your shop numbers H registers otherwise"
            )),
        );
    }

    /// A canned cycle ran this block: its R plane and its peck.
    fn cycle(&mut self, step: &Step<'_>, scale: f64) {
        let block = step.block.span;
        if !has(step, |k| matches!(k, StmtKind::Cycle(_))) {
            return;
        }
        let hole = step
            .calls
            .iter()
            .find_map(|(c, _)| pose_of(c, step.state.plane))
            .map(|p| [p[0] * scale, p[1] * scale]);
        if let (Some(min), Some(xy)) = (self.min_cut_mm, hole) {
            let r = step.cycles.r * scale;
            if step.state.absolute
                && !step.cycles.r_below_part
                && step.state.plane == CanonPlane::XY
                && r < min - self.cfg.below_tolerance_mm
                && self.over_cuts(xy)
            {
                self.report(
                    Diagnostic::new(
                        Code::LintCycleRBelowCut,
                        format!(
                            "the cycle's R plane (Z{}) is below the lowest cut of this tool (Z{})",
                            fmt(step.cycles.r),
                            fmt(min / scale)
                        ),
                    )
                    .primary(block, "rapids down to R into material not cut yet")
                    .help("raise R above the part, or check its sign"),
                );
            }
        }
        self.peck(step, scale);
    }

    fn peck(&mut self, step: &Step<'_>, scale: f64) {
        if !matches!(
            step.cycles.active,
            Some(CycleKind::Peck | CycleKind::ChipBreak)
        ) {
            return;
        }
        let t = step.state.tool_in_spindle;
        if t == 0 || step.tools_without_data.contains_key(&t) {
            return;
        }
        let Some(tool) = step.tools.get(t) else {
            return;
        };
        let dia_mm = tool.diameter * self.machine_scale;
        let q_mm = step.cycles.q.abs() * scale;
        let max = dia_mm * self.cfg.peck_max_diameters;
        if dia_mm <= 0.0 || q_mm <= max + 1e-9 {
            return;
        }
        self.report(
            Diagnostic::new(
                Code::LintPeckTooDeep,
                format!(
                    "peck of {} is more than {} x the diameter of tool {t} ({})",
                    fmt(q_mm / scale),
                    fmt(self.cfg.peck_max_diameters),
                    fmt(dia_mm / scale)
                ),
            )
            .primary(step.block.span, "peck depth Q")
            .help("peck at most the limit, or set [lint.peck-too-deep] max-diameters in cncc.toml"),
        );
    }

    /// The block moved: modes left incremental by a tool change, a
    /// reference return or a caller.
    fn after_move(&mut self, step: &Step<'_>, machine: bool) {
        if machine {
            return;
        }
        let block = step.block.span;
        let mut said = false;
        if let Some(s) = self.after_change.take() {
            if !step.state.absolute {
                said = true;
                self.report(
                    Diagnostic::new(
                        Code::LintIncrementalToolChange,
                        "the new tool's first move runs in incremental mode (G91)",
                    )
                    .primary(block, "moves relative to where the tool is")
                    .secondary(s, "tool changed here")
                    .help("program G90 before or in this block"),
                );
            }
        }
        if let Some(s) = self.ref_return.take() {
            if !step.state.absolute && !said {
                self.report(
                    Diagnostic::new(
                        Code::LintIncrementalAfterReturn,
                        "G91 of the reference return is still on for this move",
                    )
                    .primary(block, "moves incremental")
                    .secondary(s, "G91 with the reference return")
                    .help("program G90 after the reference return"),
                );
            }
        }
        self.incremental_in_sub(step);
    }

    fn incremental_in_sub(&mut self, step: &Step<'_>) {
        let Some(frame) = self.frames.last_mut() else {
            return;
        };
        if frame.reported || frame.sets_mode || !frame.entered_incremental || step.state.absolute {
            return;
        }
        frame.reported = true;
        let call = frame.call;
        self.report(
            Diagnostic::new(
                Code::LintIncrementalCall,
                "the subprogram moves in the incremental mode its caller left on",
            )
            .primary(
                step.block.span,
                "moves incremental; the subprogram never sets G90/G91",
            )
            .secondary(call, "called in G91 here")
            .help("program G90 before the call, or set the mode in the subprogram"),
        );
    }

    /// Keeps the stack of subprogram calls for W0707.
    fn enter_or_leave(&mut self, step: &Step<'_>) {
        while self.frames.len() > step.depth {
            self.frames.pop();
        }
        while self.frames.len() < step.depth {
            let (call, g91) = self.last_block;
            self.frames.push(super::Frame {
                call,
                entered_incremental: !self.last_absolute && !g91,
                sets_mode: false,
                reported: false,
            });
        }
        if has(step, |k| matches!(k, StmtKind::Distance(_))) {
            if let Some(f) = self.frames.last_mut() {
                f.sets_mode = true;
            }
        }
        let g91 = has(step, |k| {
            matches!(k, StmtKind::Distance(DimMode::Incremental))
        });
        self.last_block = (step.block.span, g91);
        self.last_absolute = step.state.absolute;
    }
}

/// A number as a program writes it: up to 4 places, no trailing zeros.
pub fn fmt(v: f64) -> String {
    crate::ir::num::short_text(v, 4)
}
