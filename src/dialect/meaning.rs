//! What a G or M code means in the meta-model, as named in dialect specs
//! (`meaning="motion.rapid"`). One table serves reading specs and choosing
//! codes when writing.

use crate::ir::{
    ArcDir, CompSide, Coolant, CoordShift, CycleKind, DimMode, FeedMode, LengthComp, LengthUnit,
    MotionKind, PathMode, Plane, StopKind,
};

/// The spindle functions a code can ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpindleFn {
    Cw,
    Ccw,
    Stop,
    Orient,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Meaning {
    Motion(MotionKind),
    Cycle(CycleKind),
    CycleCancel,
    Dwell,
    Plane(Plane),
    Units {
        unit: LengthUnit,
        with_feeds: bool,
    },
    Distance(DimMode),
    ArcDistance(DimMode),
    FeedMode(FeedMode),
    RadiusComp(CompSide),
    /// LinuxCNC G41.1/G42.1: the D word is the tool diameter itself.
    RadiusCompDiameter(CompSide),
    LengthComp(LengthComp),
    /// G54.. with its index (see `StmtKind::WorkOffset`).
    WorkOffset(u32),
    /// G54.1 P / G154 P: the index is the P word.
    WorkOffsetExtended,
    MachineCoords,
    CoordShift(CoordShift),
    SetData,
    /// `direct`: straight to the reference point along the named machine
    /// axes (Siemens `G74 Z1=0`), no intermediate point.
    RefReturn {
        index: u8,
        store: bool,
        direct: bool,
    },
    PathMode(PathMode),
    /// G98 = true (initial level), G99 = false (R plane).
    ReturnMode(bool),
    Rotate(bool),
    Scale(bool),
    Mirror(bool),
    Css(bool),
    MacroCall,
    ModalMacroCall,
    ModalMacroCancel,
    Stop(StopKind),
    Spindle(SpindleFn),
    ToolChange,
    Coolant(Coolant),
    SubCall,
    LocalCall,
    SubReturn,
    /// High-speed contouring / look-ahead on or off by its words (Fanuc
    /// G05 P10000, G5.1 Q1, G08 P1; Haas G187, G103): the control follows
    /// the programmed path within its tolerance, so a run goes on as
    /// programmed. Kept by its code, as `aux` is.
    PathSmoothing,
    /// A machine function kept by its code (`StmtKind::Aux`, written back
    /// as it was read) that the interpreter runs by this meaning.
    Machine(MachineFn),
    /// A machine function with no neutral meaning, kept by its code.
    Aux,
}

/// Functions of one control kept by their code in the meta-model (no
/// other dialect has them, or not as one statement) and run by meaning:
/// the spec says which code is which, never the interpreter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MachineFn {
    /// Feed and speed overrides both on (true) / off (LinuxCNC M48/M49).
    Overrides(bool),
    /// P0 off, else on: feed override (LinuxCNC M50).
    FeedOverride,
    /// Spindle speed override (M51).
    SpeedOverride,
    /// Adaptive feed (M52).
    AdaptiveFeed,
    /// Feed stop / hold control (M53).
    FeedHold,
    /// Q: the tool in the spindle, without a change (M61).
    SetToolNumber,
    /// P: a digital output bit, synchronised with motion or not, on or off (M62..M65).
    DigitalOut { motion: bool, on: bool },
    /// E Q: an analog output, synchronised with motion or not (M67/M68).
    AnalogOut { motion: bool },
    /// Wait on an input (M66): nothing a run computes.
    WaitInput,
    /// Save the modal state; `auto`: restored at the sub's return (M70/M73).
    SaveModal { auto: bool },
    /// Forget the saved modal state (M71).
    InvalidateModal,
    /// Restore the saved modal state (M72).
    RestoreModal,
    /// Lathe X as diameter (true) / radius (G7/G8).
    LatheDiameter(bool),
    /// K: spindle-synchronised motion (G33), or rigid tapping (G33.1): modal.
    SpindleSync { rigid: bool },
    /// LinuxCNC splines: 0 cubic (G5), 1 quadratic (G5.1), 2 NURBS
    /// control points (G5.2, modal), 3 NURBS end (G5.3).
    Spline(u8),
    /// The lathe threading cycle (LinuxCNC G76), modal.
    LatheThread,
    /// A lathe profile cycle on a contour subroutine Q (LinuxCNC G70
    /// finishing, G71 roughing along Z, G72 facing; .1 without pockets,
    /// .2 pockets only).
    LatheProfile(LatheProfile),
    /// Circular pocket milling, clockwise or not (Haas G12/G13).
    CircularPocket { clockwise: bool },
    /// General pocket milling from a contour subprogram (Haas G150):
    /// read and kept, not expanded.
    GeneralPocket,
}

impl MachineFn {
    /// Is it a motion (run in the motion phase of its block, its block's
    /// axis words its own)?
    pub fn is_motion(self) -> bool {
        matches!(
            self,
            MachineFn::Spline(_)
                | MachineFn::LatheThread
                | MachineFn::LatheProfile(_)
                | MachineFn::CircularPocket { .. }
        )
    }
}

/// Which lathe profile cycle (see [`MachineFn::LatheProfile`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LatheProfile {
    /// Finishing passes along the profile (G70).
    Finish,
    /// Roughing: along Z (turning) or along X (`facing`), and which
    /// parts: 0 everything, 1 no pockets, 2 only the pockets.
    Rough { facing: bool, part: u8 },
}

use MachineFn as F;
use Meaning as M;

/// Every meaning with its name in dialect specs.
pub const MEANINGS: &[(&str, Meaning)] = &[
    ("motion.rapid", M::Motion(MotionKind::Rapid)),
    ("motion.linear", M::Motion(MotionKind::Linear)),
    ("motion.arc-cw", M::Motion(MotionKind::Arc(ArcDir::Cw))),
    ("motion.arc-ccw", M::Motion(MotionKind::Arc(ArcDir::Ccw))),
    ("motion.arc-through", M::Motion(MotionKind::ArcThrough)),
    ("motion.arc-tangent", M::Motion(MotionKind::ArcTangent)),
    (
        "motion.probe-toward",
        M::Motion(MotionKind::Probe {
            toward: true,
            error: true,
        }),
    ),
    (
        "motion.probe-toward-noerror",
        M::Motion(MotionKind::Probe {
            toward: true,
            error: false,
        }),
    ),
    (
        "motion.probe-away",
        M::Motion(MotionKind::Probe {
            toward: false,
            error: true,
        }),
    ),
    (
        "motion.probe-away-noerror",
        M::Motion(MotionKind::Probe {
            toward: false,
            error: false,
        }),
    ),
    ("cycle.drill", M::Cycle(CycleKind::Drill)),
    ("cycle.drill-dwell", M::Cycle(CycleKind::DrillDwell)),
    ("cycle.peck", M::Cycle(CycleKind::Peck)),
    ("cycle.chip-break", M::Cycle(CycleKind::ChipBreak)),
    ("cycle.tap", M::Cycle(CycleKind::Tap)),
    ("cycle.tap-left", M::Cycle(CycleKind::TapLeft)),
    ("cycle.bore-feed-out", M::Cycle(CycleKind::BoreFeedOut)),
    (
        "cycle.bore-stop-rapid-out",
        M::Cycle(CycleKind::BoreStopRapidOut),
    ),
    ("cycle.back-bore", M::Cycle(CycleKind::BackBore)),
    ("cycle.bore-manual", M::Cycle(CycleKind::BoreManual)),
    (
        "cycle.bore-dwell-feed-out",
        M::Cycle(CycleKind::BoreDwellFeedOut),
    ),
    ("cycle.fine-bore", M::Cycle(CycleKind::FineBore)),
    ("cycle.cancel", M::CycleCancel),
    ("dwell", M::Dwell),
    ("plane.xy", M::Plane(Plane::XY)),
    ("plane.zx", M::Plane(Plane::ZX)),
    ("plane.yz", M::Plane(Plane::YZ)),
    (
        "units.inch",
        M::Units {
            unit: LengthUnit::Inch,
            with_feeds: false,
        },
    ),
    (
        "units.mm",
        M::Units {
            unit: LengthUnit::Mm,
            with_feeds: false,
        },
    ),
    (
        "units.inch-with-feeds",
        M::Units {
            unit: LengthUnit::Inch,
            with_feeds: true,
        },
    ),
    (
        "units.mm-with-feeds",
        M::Units {
            unit: LengthUnit::Mm,
            with_feeds: true,
        },
    ),
    ("distance.absolute", M::Distance(DimMode::Absolute)),
    ("distance.incremental", M::Distance(DimMode::Incremental)),
    ("arc-distance.absolute", M::ArcDistance(DimMode::Absolute)),
    (
        "arc-distance.incremental",
        M::ArcDistance(DimMode::Incremental),
    ),
    ("feed-mode.per-minute", M::FeedMode(FeedMode::PerMinute)),
    (
        "feed-mode.per-revolution",
        M::FeedMode(FeedMode::PerRevolution),
    ),
    ("feed-mode.inverse-time", M::FeedMode(FeedMode::InverseTime)),
    ("radius-comp.off", M::RadiusComp(CompSide::Off)),
    ("radius-comp.left", M::RadiusComp(CompSide::Left)),
    ("radius-comp.right", M::RadiusComp(CompSide::Right)),
    (
        "radius-comp.left-diameter",
        M::RadiusCompDiameter(CompSide::Left),
    ),
    (
        "radius-comp.right-diameter",
        M::RadiusCompDiameter(CompSide::Right),
    ),
    ("length-comp.positive", M::LengthComp(LengthComp::Positive)),
    ("length-comp.negative", M::LengthComp(LengthComp::Negative)),
    ("length-comp.cancel", M::LengthComp(LengthComp::Cancel)),
    ("length-comp.dynamic", M::LengthComp(LengthComp::Dynamic)),
    ("length-comp.additive", M::LengthComp(LengthComp::Additive)),
    ("work-offset.extended", M::WorkOffsetExtended),
    ("machine-coords", M::MachineCoords),
    ("coord-shift.set", M::CoordShift(CoordShift::Set)),
    ("coord-shift.reset", M::CoordShift(CoordShift::Reset)),
    ("coord-shift.suspend", M::CoordShift(CoordShift::Suspend)),
    ("coord-shift.restore", M::CoordShift(CoordShift::Restore)),
    ("coord-shift.local", M::CoordShift(CoordShift::Local)),
    ("set-data", M::SetData),
    (
        "ref-return.1",
        M::RefReturn {
            index: 1,
            store: false,
            direct: false,
        },
    ),
    (
        "ref-return.2",
        M::RefReturn {
            index: 2,
            store: false,
            direct: false,
        },
    ),
    (
        "ref-return.machine-axes",
        M::RefReturn {
            index: 1,
            store: false,
            direct: true,
        },
    ),
    (
        "ref-return.store-1",
        M::RefReturn {
            index: 1,
            store: true,
            direct: false,
        },
    ),
    (
        "ref-return.store-2",
        M::RefReturn {
            index: 2,
            store: true,
            direct: false,
        },
    ),
    ("path.exact-stop", M::PathMode(PathMode::ExactStop)),
    (
        "path.exact-stop-block",
        M::PathMode(PathMode::ExactStopBlock),
    ),
    ("path.exact-path", M::PathMode(PathMode::ExactPath)),
    ("path.continuous", M::PathMode(PathMode::Continuous)),
    (
        "path.corner-override",
        M::PathMode(PathMode::CornerOverride),
    ),
    ("path.tapping", M::PathMode(PathMode::Tapping)),
    ("return.initial", M::ReturnMode(true)),
    ("return.r-plane", M::ReturnMode(false)),
    ("rotate.on", M::Rotate(true)),
    ("rotate.off", M::Rotate(false)),
    ("scale.on", M::Scale(true)),
    ("scale.off", M::Scale(false)),
    ("mirror.on", M::Mirror(true)),
    ("mirror.off", M::Mirror(false)),
    ("css.on", M::Css(true)),
    ("css.off", M::Css(false)),
    ("macro.call", M::MacroCall),
    ("macro.modal", M::ModalMacroCall),
    ("macro.cancel", M::ModalMacroCancel),
    ("stop.program", M::Stop(StopKind::Program)),
    ("stop.optional", M::Stop(StopKind::Optional)),
    ("stop.end", M::Stop(StopKind::End)),
    ("stop.end-rewind", M::Stop(StopKind::EndRewind)),
    ("stop.pallet", M::Stop(StopKind::PalletStop)),
    ("spindle.cw", M::Spindle(SpindleFn::Cw)),
    ("spindle.ccw", M::Spindle(SpindleFn::Ccw)),
    ("spindle.stop", M::Spindle(SpindleFn::Stop)),
    ("spindle.orient", M::Spindle(SpindleFn::Orient)),
    ("tool.change", M::ToolChange),
    ("coolant.mist", M::Coolant(Coolant::Mist)),
    ("coolant.flood", M::Coolant(Coolant::Flood)),
    ("coolant.through-tool", M::Coolant(Coolant::ThroughTool)),
    ("coolant.off", M::Coolant(Coolant::Off)),
    ("sub.call", M::SubCall),
    ("sub.local-call", M::LocalCall),
    ("sub.return", M::SubReturn),
    ("path.smoothing", M::PathSmoothing),
    ("override.all-on", M::Machine(F::Overrides(true))),
    ("override.all-off", M::Machine(F::Overrides(false))),
    ("override.feed", M::Machine(F::FeedOverride)),
    ("override.speed", M::Machine(F::SpeedOverride)),
    ("override.adaptive-feed", M::Machine(F::AdaptiveFeed)),
    ("override.feed-hold", M::Machine(F::FeedHold)),
    ("tool.set-number", M::Machine(F::SetToolNumber)),
    (
        "io.digital-on-sync",
        M::Machine(F::DigitalOut {
            motion: true,
            on: true,
        }),
    ),
    (
        "io.digital-off-sync",
        M::Machine(F::DigitalOut {
            motion: true,
            on: false,
        }),
    ),
    (
        "io.digital-on",
        M::Machine(F::DigitalOut {
            motion: false,
            on: true,
        }),
    ),
    (
        "io.digital-off",
        M::Machine(F::DigitalOut {
            motion: false,
            on: false,
        }),
    ),
    ("io.wait-input", M::Machine(F::WaitInput)),
    ("io.analog-sync", M::Machine(F::AnalogOut { motion: true })),
    ("io.analog", M::Machine(F::AnalogOut { motion: false })),
    ("modal.save", M::Machine(F::SaveModal { auto: false })),
    ("modal.invalidate", M::Machine(F::InvalidateModal)),
    ("modal.restore", M::Machine(F::RestoreModal)),
    (
        "modal.save-auto-restore",
        M::Machine(F::SaveModal { auto: true }),
    ),
    ("lathe.diameter", M::Machine(F::LatheDiameter(true))),
    ("lathe.radius", M::Machine(F::LatheDiameter(false))),
    (
        "motion.spindle-sync",
        M::Machine(F::SpindleSync { rigid: false }),
    ),
    (
        "motion.rigid-tap",
        M::Machine(F::SpindleSync { rigid: true }),
    ),
    ("spline.cubic", M::Machine(F::Spline(0))),
    ("spline.quadratic", M::Machine(F::Spline(1))),
    ("spline.nurbs-point", M::Machine(F::Spline(2))),
    ("spline.nurbs-end", M::Machine(F::Spline(3))),
    ("cycle.lathe-thread", M::Machine(F::LatheThread)),
    (
        "cycle.lathe-finish",
        M::Machine(F::LatheProfile(LatheProfile::Finish)),
    ),
    (
        "cycle.lathe-rough",
        M::Machine(F::LatheProfile(LatheProfile::Rough {
            facing: false,
            part: 0,
        })),
    ),
    (
        "cycle.lathe-rough-no-pockets",
        M::Machine(F::LatheProfile(LatheProfile::Rough {
            facing: false,
            part: 1,
        })),
    ),
    (
        "cycle.lathe-rough-pockets",
        M::Machine(F::LatheProfile(LatheProfile::Rough {
            facing: false,
            part: 2,
        })),
    ),
    (
        "cycle.lathe-face",
        M::Machine(F::LatheProfile(LatheProfile::Rough {
            facing: true,
            part: 0,
        })),
    ),
    (
        "cycle.lathe-face-no-pockets",
        M::Machine(F::LatheProfile(LatheProfile::Rough {
            facing: true,
            part: 1,
        })),
    ),
    (
        "cycle.lathe-face-pockets",
        M::Machine(F::LatheProfile(LatheProfile::Rough {
            facing: true,
            part: 2,
        })),
    ),
    (
        "pocket.circular-cw",
        M::Machine(F::CircularPocket { clockwise: true }),
    ),
    (
        "pocket.circular-ccw",
        M::Machine(F::CircularPocket { clockwise: false }),
    ),
    ("pocket.general", M::Machine(F::GeneralPocket)),
    ("aux", M::Aux),
];

impl Meaning {
    /// Reads a meaning name; `work-offset.N` carries its index.
    pub fn parse(name: &str) -> Option<Meaning> {
        if let Some(n) = name.strip_prefix("work-offset.") {
            if let Ok(i) = n.parse::<u32>() {
                return Some(M::WorkOffset(i));
            }
        }
        MEANINGS.iter().find(|(n, _)| *n == name).map(|(_, m)| *m)
    }

    /// The name used in dialect specs.
    pub fn name(self) -> String {
        if let M::WorkOffset(i) = self {
            return format!("work-offset.{i}");
        }
        MEANINGS
            .iter()
            .find(|(_, m)| *m == self)
            .map(|(n, _)| n.to_string())
            .unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for (name, m) in MEANINGS {
            assert_eq!(Meaning::parse(name), Some(*m));
            assert_eq!(m.name(), *name);
        }
        assert_eq!(
            Meaning::parse("work-offset.3"),
            Some(Meaning::WorkOffset(3))
        );
    }
}
