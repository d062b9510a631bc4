//! What the Heidenhain cycles expanded in `cycles_bore`, `cycles_helix`,
//! `cycles_slot` and `cycles_old` share: the defined Q parameters with the
//! heights every cycle derives from them, and [`Place`], moves in a
//! cycle's own plane coordinates (`u`, `v` in the working plane about an
//! origin and turned by an angle, `w` along the tool axis).
//!
//! Heights [K, `reference/dialects.md` §2.6]: Q203 is the surface
//! (absolute; `CYCL CALL POS ... Z` replaces it), Q200 the set-up
//! clearance above it, Q201 the depth from it (signed, negative into the
//! material), Q204 the 2nd set-up clearance above the surface. The final
//! retract goes to the higher of the two clearances [?: the TNC moves to
//! Q204 "if programmed"; below Q200 it would be a move into the set-up
//! clearance zone].

use crate::canon::Pose;
use crate::diag::{Code, Diagnostic};
use crate::interp::host::{plane_axes, MotionHost};

/// The parameters of one numbered cycle definition, read at its call.
pub(super) struct Qs<'a> {
    pub number: u32,
    pub vals: &'a [(u32, f64)],
    /// `CYCL CALL POS`/`PAT` with a Z: the surface for this call.
    pub surface: Option<f64>,
}

impl Qs<'_> {
    pub fn get(&self, q: u32) -> Option<f64> {
        if q == 203 {
            if let Some(s) = self.surface {
                return Some(s);
            }
        }
        self.vals.iter().find(|(k, _)| *k == q).map(|(_, v)| *v)
    }

    /// A parameter the run cannot do without (E0523 when absent).
    pub fn need(&self, q: u32, what: &str) -> Result<f64, Diagnostic> {
        self.get(q).ok_or_else(|| {
            Diagnostic::new(
                Code::TncCycleParameterMissing,
                format!("cycle {} is called without Q{q} ({what})", self.number),
            )
            .help(format!(
                "add `Q{q}=...` to the CYCL DEF {}: the run needs its value",
                self.number
            ))
        })
    }

    pub fn or(&self, q: u32, default: f64) -> f64 {
        self.get(q).unwrap_or(default)
    }

    pub fn surface(&self) -> Result<f64, Diagnostic> {
        self.need(203, "workpiece surface coordinate")
    }

    /// Q203 + |Q200|.
    pub fn safe(&self) -> Result<f64, Diagnostic> {
        Ok(self.surface()? + self.need(200, "set-up clearance")?.abs())
    }

    /// Where the cycle ends: the higher of Q203 + |Q204| and the set-up
    /// clearance.
    pub fn clear(&self) -> Result<f64, Diagnostic> {
        let second = self.surface()? + self.need(204, "2nd set-up clearance")?.abs();
        Ok(second.max(self.safe()?))
    }

    /// The bottom: Q203 - |Q201| [?: the sign of Q201 only says which way
    /// the tool goes into the material; a positive depth is refused by the
    /// TNC unless machine parameter 201003 allows it, and is taken as
    /// downwards here].
    pub fn bottom(&self, what: &str) -> Result<f64, Diagnostic> {
        Ok(self.surface()? - self.need(201, what)?.abs())
    }

    /// A feed parameter that must be positive.
    pub fn feed(&self, q: u32, what: &str) -> Result<f64, Diagnostic> {
        let f = self.need(q, what)?;
        if f <= 0.0 {
            return Err(geometry(format!(
                "cycle {}: Q{q} ({what}) is {f}: the tool would not move",
                self.number
            )));
        }
        Ok(f)
    }

    /// A selector parameter that must be one of `allowed`.
    pub fn choice(&self, q: u32, default: i64, allowed: &[i64]) -> Result<i64, Diagnostic> {
        let v = self.get(q).unwrap_or(default as f64);
        let k = v as i64;
        if v.fract() != 0.0 || !allowed.contains(&k) {
            return Err(Diagnostic::new(
                Code::TncCycleBadValue,
                format!(
                    "cycle {}: Q{q}={v} is not one of {}",
                    self.number,
                    allowed
                        .iter()
                        .map(|a| a.to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            )
            .help("correct the value in the CYCL DEF"));
        }
        Ok(k)
    }
}

/// E0524: the sizes do not fit the tool.
pub(super) fn geometry(msg: String) -> Diagnostic {
    Diagnostic::new(Code::TncCycleGeometry, msg)
        .help("check the cycle's Q parameters against the tool radius")
}

/// E0525: a milling cycle without a tool radius.
pub(super) fn need_radius(number: u32, r: f64) -> Result<f64, Diagnostic> {
    if r > 0.0 {
        return Ok(r);
    }
    Err(Diagnostic::new(
        Code::TncCycleNoToolRadius,
        format!("cycle {number} needs the tool radius, and the active tool has none"),
    )
    .help("program `TOOL DEF n L.. R..` before the TOOL CALL, or give a tool table"))
}

/// Moves in a cycle's plane coordinates.
pub(super) struct Place {
    a: usize,
    b: usize,
    n: usize,
    origin: (f64, f64),
    cos: f64,
    sin: f64,
}

impl Place {
    pub fn new(host: &dyn MotionHost, origin: (f64, f64), angle_deg: f64) -> Place {
        let (a, b, n) = plane_axes(host.plane());
        let (sin, cos) = angle_deg.to_radians().sin_cos();
        let snap = crate::geom::snap;
        Place {
            a,
            b,
            n,
            origin,
            cos: snap(cos),
            sin: snap(sin),
        }
    }

    /// At the tool's position in the plane, not turned.
    pub fn here(host: &dyn MotionHost) -> Place {
        let (a, b, _) = plane_axes(host.plane());
        let p = host.position();
        Place::new(host, (p[a], p[b]), 0.0)
    }

    /// The origin in plane terms (the tool position for [`Place::here`]).
    pub fn origin(&self) -> (f64, f64) {
        self.origin
    }

    /// A cycle point in the plane's coordinates.
    pub fn point(&self, u: f64, v: f64) -> (f64, f64) {
        self.at(u, v)
    }

    fn at(&self, u: f64, v: f64) -> (f64, f64) {
        // `+ 0.0` turns a -0 into 0, so that no `-0.0000` is printed.
        (
            self.origin.0 + u * self.cos - v * self.sin + 0.0,
            self.origin.1 + u * self.sin + v * self.cos + 0.0,
        )
    }

    fn pose(&self, host: &dyn MotionHost, u: f64, v: f64, w: f64) -> Pose {
        let (x, y) = self.at(u, v);
        let mut p = host.position();
        p[self.a] = x;
        p[self.b] = y;
        p[self.n] = w;
        p
    }

    /// Where the tool is along the tool axis.
    pub fn w(&self, host: &dyn MotionHost) -> f64 {
        host.position()[self.n]
    }

    pub fn rapid(&self, host: &mut dyn MotionHost, u: f64, v: f64, w: f64) {
        let p = self.pose(host, u, v, w);
        if p != host.position() {
            host.rapid(p);
        }
    }

    /// Rapid along the tool axis only.
    pub fn rapid_w(&self, host: &mut dyn MotionHost, w: f64) {
        let mut p = host.position();
        if p[self.n] != w {
            p[self.n] = w;
            host.rapid(p);
        }
    }

    pub fn feed(&self, host: &mut dyn MotionHost, u: f64, v: f64, w: f64) {
        let p = self.pose(host, u, v, w);
        if p != host.position() {
            host.feed(p);
        }
    }

    /// Feed along the tool axis only.
    pub fn feed_w(&self, host: &mut dyn MotionHost, w: f64) {
        let mut p = host.position();
        if p[self.n] != w {
            p[self.n] = w;
            host.feed(p);
        }
    }

    /// An arc (a helix when `w` differs from the current height) to
    /// (u, v) about (cu, cv); a full turn when the end is the start.
    #[allow(clippy::too_many_arguments)]
    pub fn arc(
        &self,
        host: &mut dyn MotionHost,
        u: f64,
        v: f64,
        w: f64,
        cu: f64,
        cv: f64,
        ccw: bool,
    ) {
        let p = self.pose(host, u, v, w);
        host.arc(p, self.at(cu, cv), if ccw { 1 } else { -1 });
    }
}

/// E0526: a parameter value the cycle does not accept.
pub(super) fn bad_value(number: u32, q: u32, v: f64) -> Diagnostic {
    Diagnostic::new(
        Code::TncCycleBadValue,
        format!("cycle {number}: Q{q}={v} is not a value this parameter takes"),
    )
    .help("correct the value in the CYCL DEF")
}
