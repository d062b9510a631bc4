//! The machine side of the interpreter: the start-up and end sequences
//! LinuxCNC prints, and the motion primitives ([`MotionHost`]) that
//! cycles and compensation build on.

use super::comp::{CompError, MoveKind};
use super::host::{MotionHost, SpindleDir};
use super::state::{PathControl, State};
use super::{Interp, Stop};
use crate::canon::{Canon, CanonPlane, CanonUnits, MotionMode, Pose};
use crate::diag::Diagnostic;
use crate::ir::LengthUnit;
use crate::span::Span;

/// The calls every run starts with (LinuxCNC's `interp_init`).
pub fn init_sequence(it: &mut Interp<'_, '_>) {
    it.state.retract_initial = !it
        .spec
        .has(crate::dialect::Capability::CycleRetractRPlaneAtStart);
    it.emit(Canon::UseLengthUnits(CanonUnits::Mm));
    // With a parameter file the run starts in the offsets it gives, as
    // rs274's `init` prints them; otherwise every offset prints 0 (a
    // `--machine` description places work zero for the checks only).
    if it.opts.rs274.parameters.is_some() {
        let s = &it.state;
        let index = s.g5x_index;
        let offset = g5x_pose(s, index);
        let g92 = if s.g92_applied { s.g92 } else { [0.0; 9] };
        let g92 = pose6(s, &g92);
        let rotation = s.g5x_rotation[index as usize];
        it.emit(Canon::SetG5xOffset { index, offset });
        it.emit(Canon::SetG92Offset(g92));
        it.emit(Canon::SetXyRotation(rotation));
    } else {
        it.emit(Canon::SetG5xOffset {
            index: 1,
            offset: [0.0; 6],
        });
        it.emit(Canon::SetG92Offset([0.0; 6]));
        it.emit(Canon::SetXyRotation(0.0));
    }
    it.emit(Canon::SetFeedReference);
    it.emit(Canon::OnReset);
}

/// A pose of the first six axes in program units.
pub fn pose6(s: &State, p: &[f64; 9]) -> Pose {
    s.pose6_to_prog(p)
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
        if let Err(e) = self.straight_move(MoveKind::Rapid, to) {
            self.report_stop(e);
        }
    }

    fn feed(&mut self, to: Pose) {
        if let Err(e) = self.straight_move(MoveKind::Feed, to) {
            self.report_stop(e);
        }
    }

    fn arc(&mut self, to: Pose, center: (f64, f64), rotation: i64) {
        if let Err(e) = self.arc_move(to, center, rotation) {
            self.report_stop(e);
        }
    }

    fn dwell(&mut self, seconds: f64) {
        self.out(Canon::Dwell(seconds));
    }

    fn emit(&mut self, call: Canon) {
        self.out(call);
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

    fn path_mode(&self) -> (MotionMode, f64) {
        match self.state.path {
            PathControl::ExactStop => (MotionMode::ExactStop, 0.0),
            PathControl::ExactPath => (MotionMode::ExactPath, 0.0),
            PathControl::Continuous { tolerance, naive } => {
                (MotionMode::Continuous(tolerance), naive)
            }
        }
    }

    fn has(&self, c: crate::dialect::Capability) -> bool {
        self.spec.has(c)
    }

    fn assume_position(&mut self, to: Pose) {
        self.set_position(&to);
    }

    fn overrides_enabled(&self) -> (bool, bool) {
        (self.state.feed_override, self.state.speed_override)
    }
}

impl Interp<'_, '_> {
    /// Sets the current position from a pose in program units.
    pub fn set_position(&mut self, p: &Pose) {
        for (i, v) in p.iter().enumerate() {
            self.state.pos[i] = if State::is_linear(i) {
                self.state.to_mm(*v)
            } else {
                *v
            };
        }
        self.state.canon_pos = self.state.pos;
    }

    /// Called by every statement: notes a new block, and after a tool
    /// change re-reads the position as rs274 does.
    pub fn begin_block(&mut self, block: &crate::ir::Block) {
        if block.span == self.block_span {
            return;
        }
        self.block_span = block.span;
        super::modal_save::check_auto(self);
        if self.state.resync {
            self.state.resync = false;
            self.state.pos = self.state.canon_pos;
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

impl Interp<'_, '_> {
    /// Emits a non-motion call through compensation (which may hold it
    /// behind a held-back move).
    pub fn out(&mut self, call: Canon) {
        let span = self.span;
        let sink = &mut self.sink;
        self.comp.other(call, &mut |c| sink.call(c, span));
    }

    /// A straight move to `to` (program frame, program units).
    pub fn straight_move(&mut self, kind: MoveKind, to: Pose) -> Result<(), Stop> {
        // Only compensation looks at where the move starts.
        let from = if self.comp.is_on() {
            MotionHost::position(self)
        } else {
            to
        };
        self.set_position(&to);
        let span = self.span;
        let sink = &mut self.sink;
        let r = self
            .comp
            .straight(kind, from, to, &mut |c| sink.call(c, span));
        self.note_compensated();
        r.map_err(|e| self.comp_error(e))
    }

    /// With compensation on, the canon layer's position is the tool's
    /// compensated one (what a tool change re-reads).
    pub fn note_compensated(&mut self) {
        if let Some(c) = self.comp.compensated() {
            for (i, v) in c.iter().enumerate() {
                self.state.canon_pos[i] = self.state.to_mm(*v);
            }
        }
    }

    /// An arc in the active plane to `to` round `center` (plane axes).
    pub fn arc_move(&mut self, to: Pose, center: (f64, f64), rotation: i64) -> Result<(), Stop> {
        let from = MotionHost::position(self);
        self.set_position(&to);
        let span = self.span;
        let sink = &mut self.sink;
        if self.state.plane == CanonPlane::XY || self.comp.is_on() {
            let r = self
                .comp
                .arc(from, to, center, rotation, &mut |c| sink.call(c, span));
            self.note_compensated();
            return r.map_err(|e| self.comp_error(e));
        }
        self.comp.flush(&mut |c| sink.call(c, span));
        let (a, b, n) = super::host::plane_axes(self.state.plane);
        sink.call(
            Canon::ArcFeed {
                first_end: to[a],
                second_end: to[b],
                first_axis: center.0,
                second_axis: center.1,
                rotation,
                axis_end: to[n],
                abc: [to[3], to[4], to[5]],
            },
            span,
        );
        Ok(())
    }

    /// Tags the calls that follow for compensation errors with this block.
    pub fn comp_block(&mut self, span: Span) {
        let tag = self
            .comp_tags
            .back()
            .map(|(t, s)| if *s == span { *t } else { t + 1 })
            .unwrap_or(1);
        if self.comp_tags.back().map(|(t, _)| *t) != Some(tag) {
            self.comp_tags.push_back((tag, span));
            if self.comp_tags.len() > 16 {
                self.comp_tags.pop_front();
            }
        }
        self.comp.set_block(tag);
    }

    /// A compensation error as the diagnostic that stops the run.
    pub fn comp_error(&self, e: CompError) -> Stop {
        let span_of = |t: u64| {
            self.comp_tags
                .iter()
                .find(|(x, _)| *x == t)
                .map(|(_, s)| *s)
        };
        let span = span_of(e.block).unwrap_or(self.span);
        let mut d = Diagnostic::new(e.kind.code(), e.kind.message())
            .primary(span, "found at this block")
            .help(e.kind.hint());
        if let Some(h) = e.held.and_then(span_of) {
            if h != span {
                d = d.secondary(h, "the move held back from here");
            }
        }
        Stop::Error(d)
    }

    /// Reports an error from inside a [`MotionHost`] call; the caller
    /// checks [`Self::take_error`] afterwards.
    fn report_stop(&mut self, e: Stop) {
        if let Stop::Error(d) | Stop::Unknown(d) = e {
            self.diags.push(d);
        }
    }

    /// The first error reported since `mark` (diagnostics count), removed.
    pub fn take_error(&mut self, mark: usize) -> Result<(), Stop> {
        if let Some(i) = self.diags.iter().skip(mark).position(|d| d.is_error()) {
            return Err(Stop::Error(self.diags.remove(mark + i)));
        }
        Ok(())
    }
}

/// M2 / M30: the end sequence rs274 prints, resetting what it resets.
pub fn program_end(it: &mut Interp<'_, '_>, rewind: bool) -> Result<(), Stop> {
    if it.comp.is_on() {
        it.out(Canon::Comment(
            "interpreter: cutter radius compensation off".into(),
        ));
        let span = it.span;
        let sink = &mut it.sink;
        let r = it.comp.stop(&mut |c| sink.call(c, span));
        r.map_err(|e| it.comp_error(e))?;
    }
    {
        let span = it.span;
        let sink = &mut it.sink;
        it.comp.flush(&mut |c| sink.call(c, span));
    }
    let old = it.state.placement();
    it.state.g5x_index = 1;
    it.state.reframe(old);
    it.emit(Canon::SetG5xOffset {
        index: 1,
        offset: g5x_pose(&it.state, 1),
    });
    it.emit(Canon::SetXyRotation(it.state.g5x_rotation[1]));
    if it.state.plane != CanonPlane::XY {
        it.state.plane = CanonPlane::XY;
        it.emit(Canon::SelectPlane(CanonPlane::XY));
    }
    it.state.absolute = true;
    it.state.feed_mode = crate::ir::FeedMode::PerMinute;
    it.emit(Canon::SetFeedMode(0));
    it.state.feed = 0.0;
    it.emit(Canon::SetFeedRate(0.0));
    if !it.state.feed_override {
        it.state.feed_override = true;
        it.emit(Canon::EnableFeedOverride);
    }
    it.state.spindle = SpindleDir::Stopped;
    it.emit(Canon::StopSpindle);
    it.state.css_max = 0.0;
    it.emit(Canon::SetSpindleMode(0.0));
    if it.state.mist {
        it.emit(Canon::MistOff);
    }
    if it.state.flood {
        it.emit(Canon::FloodOff);
    }
    it.state.mist = false;
    it.state.flood = false;
    super::splines::leaving_nurbs(it);
    it.state.motion = super::state::ModalMotion::Move(crate::ir::MotionKind::Linear);
    it.cycles.cancel();
    if rewind {
        it.emit(Canon::PalletShuttle);
    }
    it.emit(Canon::ProgramEnd);
    it.emit(Canon::OnReset);
    it.emit(Canon::OnReset);
    it.ended = true;
    Ok(())
}
