//! Interpolation for a controller's position loop: the resolved moves of
//! a run ([`crate::toolpath::Move`]) become set-points at a fixed sampling
//! period, along the path (lines, circular and helical arcs) at the
//! programmed feed, with a trapezoidal acceleration-limited feed profile
//! per move ([`profile`]), or a jerk-limited one ([`scurve`]); and, on the
//! BLU grid, reference pulses per axis and period ([`pulses`]).
//!
//! Moves are planned together over a window of `lookahead` moves
//! ([`lookahead`]): a corner is passed at the junction speed its angle
//! allows (the path itself is not rounded), collinear moves run as one,
//! and each move ends at a speed from which the moves after it in the
//! window can still stop. With `lookahead` 0 every move starts and ends at
//! rest. The clock runs on across moves: period `k` is at `k × period`, and a
//! period that spans the end of one move samples the next. Dwells pass
//! time standing still; rapids run at the rapid rate given. The last
//! set-point is at the first period tick at or after the end of the run,
//! at the end point, so that pulses sum to the whole displacement.
//!
//! Streaming: the window (at most `lookahead + 1` moves) is held; memory
//! does not grow with the program.

pub mod lookahead;
pub mod path;
pub mod profile;
pub mod pulses;
pub mod scurve;

use crate::toolpath::{Event, FeedMode, Move, MoveKind};
use lookahead::{Planned, Window};
use nalgebra::Vector3;
use path::Path;
use profile::{Limits, Profile};
use pulses::Q3;

/// How to interpolate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Sampling period, seconds.
    pub period: f64,
    /// Basic length unit (pulse weight), mm.
    pub blu: f64,
    /// Path acceleration, mm/s² (0: unlimited).
    pub accel: f64,
    /// Path jerk, mm/s³ (0: unlimited: the trapezoidal profile).
    pub jerk: f64,
    /// Rapid traverse rate, mm/min.
    pub rapid_rate: f64,
    /// Moves planned ahead of the one run (0: none, every move stops).
    pub lookahead: usize,
    /// Corner tolerance δ of the junction deviation model, mm (0: stop at
    /// every corner).
    pub corner_tolerance: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            period: 0.001,
            blu: 0.001,
            accel: 1000.0,
            jerk: 0.0,
            rapid_rate: 10_000.0,
            lookahead: 64,
            corner_tolerance: 0.01,
        }
    }
}

/// One set-point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Period index; the time is `index × period`.
    pub index: u64,
    pub time: f64,
    /// The set-point, mm, work coordinates.
    pub position: Vector3<f64>,
    /// Path speed at the set-point, mm/min.
    pub speed: f64,
    /// The set-point on the BLU grid, and the pulses since the last one.
    pub grid: Q3,
    pub pulses: Q3,
}

/// Why a move cannot be interpolated.
#[derive(Clone, Debug, PartialEq)]
pub struct NoFeed {
    pub span: crate::span::Span,
    pub why: String,
}

/// The streaming interpolator: feed it events, it calls `out` with
/// every set-point.
pub struct Interpolator<F: FnMut(&Sample)> {
    s: Settings,
    out: F,
    /// The next period to sample.
    next: u64,
    /// Time at which the current (next) move starts.
    clock: f64,
    /// Where the machine is at `clock`, on the grid and in mm; None
    /// before the first move.
    at: Option<(Q3, Vector3<f64>)>,
    /// The last set-point given, on the grid.
    last_grid: Option<Q3>,
    /// The first move that could not be timed (the run stops there).
    pub error: Option<NoFeed>,
    /// Moves and samples so far.
    pub moves: u64,
    /// The moves planned but not yet run.
    window: Window,
    /// The speed at `clock` (the exit of the last move run), mm/s.
    v_now: f64,
    /// The last move taken's end tangent and feed (for the next
    /// junction); None after a stop.
    prev: Option<(Vector3<f64>, f64)>,
}

impl<F: FnMut(&Sample)> Interpolator<F> {
    pub fn new(s: Settings, out: F) -> Self {
        Interpolator {
            s,
            out,
            next: 0,
            clock: 0.0,
            at: None,
            last_grid: None,
            error: None,
            moves: 0,
            window: Window::new(Limits {
                accel: s.accel,
                jerk: s.jerk,
            }),
            v_now: 0.0,
            prev: None,
        }
    }

    /// Takes one event of the run.
    pub fn push(&mut self, e: &Event) {
        if self.error.is_some() {
            return;
        }
        match e {
            Event::Move(m) => self.feed_move(m),
            Event::Dwell { seconds, .. } => {
                self.flush();
                if let Some((q, p)) = self.at {
                    self.hold(seconds.max(0.0), q, p);
                }
            }
            Event::ToolChange { .. } | Event::Stop { .. } => self.flush(),
            Event::Comment { .. } => {}
        }
    }

    /// Runs every move planned, to rest.
    fn flush(&mut self) {
        while !self.window.is_empty() {
            self.run_next();
        }
        self.v_now = 0.0;
        self.prev = None;
    }

    /// Ends the run: the last set-point, at the end point. The total time,
    /// seconds (the end of the last move).
    pub fn finish(mut self) -> f64 {
        self.flush();
        if let Some((q, p)) = self.at {
            let last_time = self.next as f64 * self.s.period - self.s.period;
            if self.last_grid != Some(q) || last_time < self.clock - 1e-9 {
                self.emit(p, 0.0, q);
            }
        }
        self.clock
    }

    /// Speed of a move, mm/s.
    fn speed(&self, m: &Move) -> Result<f64, String> {
        let per_min = match (m.kind, m.feed_mode) {
            (MoveKind::Rapid, _) => self.s.rapid_rate,
            (_, FeedMode::PerMinute) => m.feed,
            (_, FeedMode::PerRev) => m.feed * m.spindle.abs(),
        };
        if per_min > 0.0 && per_min.is_finite() {
            Ok(per_min / 60.0)
        } else if m.feed_mode == FeedMode::PerRev {
            Err(format!(
                "a feed per revolution ({}) with the spindle at {} rpm",
                m.feed, m.spindle
            ))
        } else {
            Err(format!("a feed move at feed {}", m.feed))
        }
    }

    fn feed_move(&mut self, m: &Move) {
        let path = match m.kind {
            MoveKind::Arc(g) => Path::arc(m.from, m.to, g),
            MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => Path::line(m.from, m.to),
        };
        if self.at.is_none() {
            // The machine stands at the first move's start.
            let start = path.start();
            self.at = Some((pulses::round_point(&start, self.s.blu), start));
        }
        let length = path.length();
        if length <= 0.0 {
            return;
        }
        let v = match self.speed(m) {
            Ok(v) => v,
            Err(why) => {
                // The moves before it run, to rest; the run stops here.
                self.flush();
                self.error = Some(NoFeed { span: m.span, why });
                return;
            }
        };
        self.moves += 1;
        let junction = match self.prev {
            Some((t, feed)) if self.s.lookahead > 0 => lookahead::junction_speed(
                &t,
                &path.tangent(0.0),
                self.s.accel,
                self.s.corner_tolerance,
            )
            .min(feed),
            _ => 0.0,
        };
        self.prev = Some((path.tangent(1.0), v));
        self.window.push(Planned::new(path, length, v, junction));
        while self.window.len() > self.s.lookahead {
            self.run_next();
        }
    }

    /// Runs the first move of the window, from the current speed to the
    /// exit speed the plan allows.
    fn run_next(&mut self) {
        let Some((m, v1)) = self.window.pop(self.v_now) else {
            return;
        };
        let lim = Limits {
            accel: self.s.accel,
            jerk: self.s.jerk,
        };
        let prof = Profile::between(m.length, self.v_now, m.speed, v1, lim);
        let path = m.path;
        let qs = pulses::round_point(&path.start(), self.s.blu);
        let qe = pulses::round_point(&path.end(), self.s.blu);
        let end = self.clock + prof.duration();
        while (self.next as f64) * self.s.period <= end {
            let local = self.next as f64 * self.s.period - self.clock;
            let (dist, speed) = prof.at(local);
            let f = dist / m.length;
            let p = path.point(f);
            let q = match path {
                Path::Line { .. } => pulses::line_point(qs, qe, f),
                Path::Arc { .. } => pulses::round_point(&p, self.s.blu),
            };
            self.emit(p, speed * 60.0, q);
        }
        self.clock = end;
        self.v_now = v1;
        self.at = Some((qe, path.end()));
    }

    /// Time passing standing still.
    fn hold(&mut self, seconds: f64, q: Q3, p: Vector3<f64>) {
        let end = self.clock + seconds;
        while (self.next as f64) * self.s.period <= end {
            self.emit(p, 0.0, q);
        }
        self.clock = end;
    }

    fn emit(&mut self, position: Vector3<f64>, speed: f64, grid: Q3) {
        let before = self.last_grid.unwrap_or(grid);
        let sample = Sample {
            index: self.next,
            time: self.next as f64 * self.s.period,
            position,
            speed,
            grid,
            pulses: pulses::pulses(before, grid),
        };
        (self.out)(&sample);
        self.last_grid = Some(grid);
        self.next += 1;
    }
}
