//! The machine side of the interpreter: the start-up and end sequences
//! LinuxCNC prints, and the motion primitives ([`MotionHost`]) that
//! cycles and compensation build on.

use super::host::{MotionHost, SpindleDir};
use super::state::State;
use super::Interp;
use crate::canon::{Canon, CanonPlane, CanonUnits, Pose};
use crate::diag::Diagnostic;
use crate::ir::LengthUnit;

/// The calls every run starts with (LinuxCNC's `interp_init`).
pub fn init_sequence(it: &mut Interp<'_, '_>) {
    it.emit(Canon::UseLengthUnits(CanonUnits::Mm));
    it.emit(Canon::SetG5xOffset { index: 1, offset: [0.0; 6] });
    it.emit(Canon::SetG92Offset([0.0; 6]));
    it.emit(Canon::SetXyRotation(0.0));
    it.emit(Canon::SetFeedReference);
    it.emit(Canon::OnReset);
}

/// A pose of the first six axes in program units.
pub fn pose6(s: &State, p: &[f64; 9]) -> Pose {
    let q = s.pose_to_prog(p);
    [q[0], q[1], q[2], q[3], q[4], q[5]]
}

/// The current work offset as printed (program units).
pub fn g5x_pose(s: &State, index: u32) -> Pose {
    pose6(s, &s.g5x[index as usize])
}

/// After a failed block: what rs274 prints when it stops on an error.
pub fn abort_sequence(it: &mut Interp<'_, '_>) {
    it.emit(Canon::OnReset);
    it.emit(Canon::OnReset);
}

/// The program ran out of blocks without M2/M30 or `%`.
pub fn fell_off_end(it: &mut Interp<'_, '_>, diags: &mut Vec<Diagnostic>) {
    if it.spec.has(crate::dialect::Capability::ProgramEndRequired) && !it.ended {
        diags.push(Diagnostic::new(
            crate::diag::Code::NoProgramEnd,
            "file ended with no percent sign or program end",
        ));
        abort_sequence(it);
    }
}

impl MotionHost for Interp<'_, '_> {
    fn position(&self) -> Pose {
        pose6(&self.state, &self.state.pos)
    }

    fn plane(&self) -> CanonPlane {
        self.state.plane
    }

    fn units(&self) -> CanonUnits {
        match self.state.units {
            LengthUnit::Mm => CanonUnits::Mm,
            LengthUnit::Inch => CanonUnits::Inches,
        }
    }

    fn feed_rate(&self) -> f64 {
        self.state.feed
    }

    fn rapid(&mut self, to: Pose) {
        self.set_position(&to);
        self.emit(Canon::StraightTraverse(to));
    }

    fn feed(&mut self, to: Pose) {
        self.set_position(&to);
        self.emit(Canon::StraightFeed(to));
    }

    fn arc(&mut self, to: Pose, center: (f64, f64), rotation: i64) {
        let (a, b, n) = super::host::plane_axes(self.state.plane);
        self.set_position(&to);
        self.emit(Canon::ArcFeed {
            first_end: to[a],
            second_end: to[b],
            first_axis: center.0,
            second_axis: center.1,
            rotation,
            axis_end: to[n],
            abc: [to[3], to[4], to[5]],
        });
    }

    fn dwell(&mut self, seconds: f64) {
        self.emit(Canon::Dwell(seconds));
    }

    fn emit(&mut self, call: Canon) {
        Interp::emit(self, call);
    }

    fn report(&mut self, diag: Diagnostic) {
        self.diags.push(diag);
    }

    fn spindle(&self) -> SpindleDir {
        self.state.spindle
    }

    fn spindle_speed(&self) -> f64 {
        self.state.speed
    }
}

impl Interp<'_, '_> {
    /// Sets the current position from a pose in program units.
    pub fn set_position(&mut self, p: &Pose) {
        for (i, v) in p.iter().enumerate() {
            self.state.pos[i] = if State::is_linear(i) { self.state.to_mm(*v) } else { *v };
        }
    }
}

/// A closing `%`: LinuxCNC ends with FINISH instead of PROGRAM_END.
pub fn finish_sequence(it: &mut Interp<'_, '_>) {
    it.emit(Canon::Finish);
    it.emit(Canon::OnReset);
    it.emit(Canon::OnReset);
    it.ended = true;
}
