//! Rules on the values a tool cuts with, read from the run: the surface
//! speed and the feed per revolution against the tool's diameter (W0717,
//! W0718, from the tool table or the program's tool list), and values that
//! look like the other length unit (W0719).

use super::rules::fmt;
use super::{Linter, RunEnd};
use crate::canon::CanonPlane;
use crate::diag::{Code, Diagnostic};
use crate::interp::host::SpindleDir;
use crate::interp::watch::Step;
use crate::ir::{FeedMode, LengthUnit};
use crate::span::Span;

/// What W0719 gathers over the run.
#[derive(Debug, Default)]
pub(super) struct UnitSurvey {
    /// An inch cut was reported far from the work zero.
    inch_reported: bool,
    /// First metric cut; largest metric cutting feed (mm/min) and
    /// distance from the work zero (mm) on any axis.
    metric_first: Option<Span>,
    metric_feed: Option<f64>,
    metric_size: f64,
    /// Cuts in inch were made too: the program switches units.
    any_inch: bool,
}

/// The feed, speed and units a cutting move ran with: the state after its
/// block, or after the block before for a move held over (a corner).
#[derive(Clone, Copy, Debug)]
pub(super) struct CutValues {
    pub feed: f64,
    pub speed: f64,
    pub feed_mode: FeedMode,
    pub units: LengthUnit,
    pub css: bool,
    pub spindle: SpindleDir,
    pub plane: CanonPlane,
}

impl CutValues {
    pub fn of(st: &crate::interp::state::State) -> CutValues {
        CutValues {
            feed: st.feed,
            speed: st.speed,
            feed_mode: st.feed_mode,
            units: st.units,
            css: st.css_max != 0.0,
            spindle: st.spindle,
            plane: st.plane,
        }
    }

    fn scale(&self) -> f64 {
        match self.units {
            LengthUnit::Mm => 1.0,
            LengthUnit::Inch => crate::interp::state::MM_PER_INCH,
        }
    }
}

impl Default for CutValues {
    fn default() -> Self {
        CutValues {
            feed: 0.0,
            speed: 0.0,
            feed_mode: FeedMode::PerMinute,
            units: LengthUnit::Mm,
            css: false,
            spindle: SpindleDir::Stopped,
            plane: CanonPlane::XY,
        }
    }
}

/// Per tool: whether W0717/W0718 were reported since the tool change.
#[derive(Debug, Default)]
pub(super) struct RateReported {
    pub speed: bool,
    pub feed: bool,
}

impl Linter {
    /// The tool's diameter in mm, when a table or the program gives it.
    fn tool_diameter_mm(&self, step: &Step<'_>) -> Option<f64> {
        let t = step.state.tool_in_spindle;
        if t == 0 || step.tools_without_data.contains_key(&t) {
            return None;
        }
        let d = step.tools.get(t)?.diameter * self.machine_scale;
        (d > 0.0).then_some(d)
    }

    /// W0717 and W0718 at a feed move with the spindle turning.
    pub(super) fn cut_rates(&mut self, step: &Step<'_>, block: Span, st: CutValues) {
        if st.spindle == SpindleDir::Stopped || st.speed <= 0.0 || st.css {
            return;
        }
        let Some(d) = self.tool_diameter_mm(step) else {
            return;
        };
        let t = step.state.tool_in_spindle;
        let v = std::f64::consts::PI * d * st.speed / 1000.0;
        let (lo, hi) = (self.cfg.min_surface_speed, self.cfg.max_surface_speed);
        if !self.rates.speed && (v > hi || v < lo) {
            self.rates.speed = true;
            self.report(
                Diagnostic::new(
                    Code::LintSpeedForTool,
                    format!(
                        "S{} on tool {t} (diameter {} mm) cuts at {} m/min, outside {}..{} m/min",
                        fmt(st.speed),
                        fmt(d),
                        fmt(v.round()),
                        fmt(lo),
                        fmt(hi)
                    ),
                )
                .primary(block, "cutting move at this speed")
                .help("check S against the tool, or set [lint.speed-absurd-for-tool] in cncc.toml"),
            );
        }
        let per_rev_mm = match st.feed_mode {
            FeedMode::PerMinute => st.feed * st.scale() / st.speed,
            FeedMode::PerRevolution => st.feed * st.scale(),
            FeedMode::InverseTime => return,
        };
        let max = d * self.cfg.max_feed_per_rev;
        if !self.rates.feed && per_rev_mm > max {
            self.rates.feed = true;
            self.report(
                Diagnostic::new(
                    Code::LintFeedForTool,
                    format!(
                        "F{} at S{} is {} mm per revolution for tool {t} (diameter {} mm), more than {} mm",
                        fmt(st.feed),
                        fmt(st.speed),
                        fmt(per_rev_mm),
                        fmt(d),
                        fmt(max)
                    ),
                )
                .primary(block, "cutting move at this feed")
                .help("check F and S against the tool, or set [lint.feed-absurd-for-tool] max-feed-per-rev in cncc.toml"),
            );
        }
    }

    /// W0719 at a feed move ending at `pose` (program units).
    pub(super) fn unit_values(&mut self, block: Span, st: CutValues, pose: [f64; 3]) {
        match st.units {
            LengthUnit::Inch => {
                self.units.any_inch = true;
                // Units the control was assumed to be in: W0710's matter.
                if self.units.inch_reported || !self.units_set {
                    return;
                }
                let z = pose[2].abs();
                let xy = pose[0].abs().max(pose[1].abs());
                let (axis, v, lim) = if z > self.cfg.inch_max_z {
                    ("Z", pose[2], self.cfg.inch_max_z)
                } else if xy > self.cfg.inch_max_xy {
                    let x = pose[0].abs() >= pose[1].abs();
                    let (a, v) = if x { ("X", pose[0]) } else { ("Y", pose[1]) };
                    (a, v, self.cfg.inch_max_xy)
                } else {
                    return;
                };
                self.units.inch_reported = true;
                self.report(
                    Diagnostic::new(
                        Code::LintOtherUnit,
                        format!(
                            "{axis}{} in an inch program is {} mm from the work zero: the value looks metric",
                            fmt(v),
                            fmt((v * crate::interp::state::MM_PER_INCH).round())
                        ),
                    )
                    .primary(block, format!("cuts more than {} in from the work zero", fmt(lim)))
                    .help("check the units word (G20/G21, G70/G71, INCH/MM) and the post"),
                );
            }
            LengthUnit::Mm => {
                let u = &mut self.units;
                u.metric_first.get_or_insert(block);
                u.metric_size = pose.iter().fold(u.metric_size, |m, v| m.max(v.abs()));
                if st.feed_mode == FeedMode::PerMinute && st.feed > 0.0 {
                    u.metric_feed = Some(u.metric_feed.map_or(st.feed, |f| f.max(st.feed)));
                }
            }
        }
    }

    /// W0719 over the whole run: a metric program whose cuts are all small
    /// and slow, as inch values read as mm are. Where the program never
    /// set its units the finding is a note on W0710 instead: the program
    /// is right on a control left in inch.
    pub(super) fn metric_looks_inch(&mut self, end: RunEnd) -> Option<String> {
        let u = &self.units;
        let (Some(first), Some(feed)) = (u.metric_first, u.metric_feed) else {
            return None;
        };
        if !end.complete
            || u.any_inch
            || feed > self.cfg.metric_max_feed
            || u.metric_size > self.cfg.metric_max_size
        {
            return None;
        }
        let what = format!(
            "every cut stays within {} mm of the work zero at feeds up to F{}: the values look like inches",
            fmt(u.metric_size),
            fmt(feed)
        );
        if !self.units_set {
            return Some(what);
        }
        self.report(
            Diagnostic::new(Code::LintOtherUnit, format!("this metric program's {what}"))
                .primary(first, "first cut, in mm")
                .help("check the units word (G20/G21, G70/G71, INCH/MM) and the post"),
        );
        None
    }
}
