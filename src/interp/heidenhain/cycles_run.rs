//! Runs the Heidenhain cycles expanded by this crate's own code rather
//! than by a Siemens cycle (204, 208, 209, 241, 256, 262; 254 through the
//! Siemens SLOT2 expansion with its own parameter translation): the
//! cycle works in the programmable frame (cycles 7/8/10/11), parameters it
//! does not apply are reported (W0514), the caller's feed rate is set
//! again afterwards.

use super::super::siemens::{milling, FramedHost};
use super::super::{Interp, Stop};
use super::cycles_geom::{Place, Qs};
use super::{cycles_bore, cycles_helix, cycles_slot, Defined};
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::host::MotionHost;
use crate::span::Span;

/// Does this module run the cycle?
pub(super) fn expands(number: u32) -> bool {
    matches!(number, 204 | 208 | 209 | 241 | 254 | 256 | 262)
}

/// What a cycle leaves behind: the feed rate it set last, coolant M
/// functions it ran, warnings.
#[derive(Default)]
pub(super) struct Done {
    pub feed: Option<f64>,
    pub coolant: Vec<i64>,
    pub warnings: Vec<Diagnostic>,
}

impl Done {
    pub fn set_feed(&mut self, host: &mut dyn MotionHost, f: f64) {
        if self.feed != Some(f) {
            host.emit(Canon::SetFeedRate(f));
            self.feed = Some(f);
        }
    }

    /// Coolant by M number (241's Q429/Q430): 7, 8, 9 run; 0 nothing;
    /// other numbers are machine functions (W0515).
    pub fn coolant(&mut self, host: &mut dyn MotionHost, m: f64) {
        match m as i64 {
            0 => {}
            7 => host.emit(Canon::MistOn),
            8 => host.emit(Canon::FloodOn),
            9 => {
                host.emit(Canon::MistOff);
                host.emit(Canon::FloodOff);
            }
            other => {
                self.warnings.push(
                    Diagnostic::new(
                        Code::TncCycleMachineFunction,
                        format!("cycle 241 switches coolant with M{other}, a machine-dependent function: not run"),
                    )
                    .help("M7, M8 and M9 are run; other coolant functions are set by the machine builder"),
                );
                return;
            }
        }
        self.coolant.push(m as i64);
    }
}

/// Parameters with a value the expansion does not apply: (cycle, Q,
/// value that means "nothing to apply", what it is).
const NOT_APPLIED: &[(u32, u32, f64, &str)] = &[
    (209, 403, 1.0, "RPM factor for retraction"),
    (
        254,
        366,
        0.0,
        "plunging strategy (the run plunges vertically)",
    ),
    (254, 369, 0.0, "finishing allowance for floor"),
    (254, 338, 0.0, "infeed for finishing"),
    (254, 439, 0.0, "feed rate reference"),
    (
        256,
        437,
        0.0,
        "approach position (the run approaches from the right)",
    ),
    (256, 369, 0.0, "finishing allowance for floor"),
    (256, 338, 0.0, "infeed for finishing"),
    (256, 439, 0.0, "feed rate reference"),
    (262, 439, 0.0, "feed rate reference"),
];

/// The Q parameters each expansion reads.
fn read_by(number: u32) -> &'static [u32] {
    match number {
        204 => &[200, 249, 250, 251, 252, 253, 254, 255, 203, 204, 214, 336],
        208 => &[200, 201, 206, 334, 203, 204, 335, 342, 351],
        209 => &[200, 201, 239, 203, 204, 257, 256, 336],
        241 => &[
            200, 201, 206, 211, 203, 204, 379, 253, 208, 426, 427, 428, 429, 430, 435,
        ],
        254 => &[
            215, 219, 368, 375, 367, 216, 217, 376, 248, 378, 377, 207, 351, 201, 202, 206, 200,
            203, 204, 385,
        ],
        256 => &[
            218, 424, 219, 425, 220, 368, 224, 367, 207, 351, 201, 202, 206, 200, 203, 204, 370,
            215, 385,
        ],
        _ => &[335, 239, 201, 355, 253, 351, 200, 203, 204, 207, 512],
    }
}

/// W0514 for every parameter the expansion does not read whose value
/// asks for something: the table's values, else anything but 0 [?: 0 is
/// taken as "nothing to apply" for parameters newer software appends,
/// such as Q395 depth reference and Q439 feed reference].
fn not_applied(it: &mut Interp<'_, '_>, span: Span, def: &Defined) {
    for (q, v) in &def.params {
        if read_by(def.number).contains(q) {
            continue;
        }
        let known = NOT_APPLIED
            .iter()
            .find(|(c, k, _, _)| *c == def.number && k == q);
        let none = known.map_or(0.0, |k| k.2);
        if *v == none {
            continue;
        }
        let what = known.map_or(String::new(), |k| format!(" ({})", k.3));
        it.diags.push(
            Diagnostic::new(
                Code::TncCycleParameterNotApplied,
                format!(
                    "cycle {}: Q{q}={v}{what} is not applied by the simulated cycle",
                    def.number
                ),
            )
            .primary(span, "this call runs without it")
            .help("the canonical output, plots and STEP-NC lack its effect; the parameter is kept in the program"),
        );
    }
}

/// Runs the numbered cycle `def` at the current position.
pub(super) fn call(
    it: &mut Interp<'_, '_>,
    span: Span,
    def: &Defined,
    surface: Option<f64>,
) -> Result<(), Stop> {
    not_applied(it, span, def);
    let q = Qs {
        number: def.number,
        vals: &def.params,
        surface,
    };
    let radius = super::mapping::tool_radius(it);
    let mills = !matches!(def.number, 204 | 209 | 241);
    if mills && radius == 0.0 && size_unknown(it) {
        not_simulated(it, span, def.number);
        return Ok(());
    }
    let saved = it.state.feed;
    let (frame, scale) = (it.siemens.frame, it.state.scale());
    let mark = it.diags.len();
    let result = {
        let host = &mut FramedHost::new(it, frame, scale);
        match def.number {
            204 => cycles_bore::back_bore(host, &q),
            208 => cycles_helix::bore_mill(host, &q, radius),
            209 => cycles_bore::tap_chip_breaking(host, &q),
            241 => cycles_bore::single_lip(host, &q),
            254 => circular_slot(host, &q, radius),
            256 => cycles_slot::stud(host, &q, radius),
            _ => cycles_helix::thread_mill(host, &q, radius),
        }
    };
    finish(it, span, saved, mark, result)
}

/// The tool in the spindle is one the control holds and no table or
/// program gave sizes for (W0592): its radius is not known here.
fn size_unknown(it: &Interp<'_, '_>) -> bool {
    it.spec.has(crate::dialect::Capability::ControlHoldsTools)
        && it
            .tools_without_data
            .contains_key(&it.state.tool_in_spindle)
}

/// A milling cycle whose path depends on a radius not known here: its
/// moves are not in the run (W0517), which goes on from where it was.
fn not_simulated(it: &mut Interp<'_, '_>, span: Span, number: u32) {
    if !it.once(format!("no radius {number}")) {
        return;
    }
    it.diags.push(
        crate::diag::Diagnostic::new(
            crate::diag::Code::UnknownAtCheckTime,
            format!("cycle {number} mills with the tool's radius, which is not known here: its moves are not in the run"),
        )
        .primary(span, "not simulated")
        .help("give the tool's sizes (`--tool-table`, `TOOL DEF`) to check the cycle's path"),
    );
}

/// After a cycle: the error with the call's span, the caller's feed rate
/// again, coolant state, warnings with the call's span.
pub(super) fn finish(
    it: &mut Interp<'_, '_>,
    span: Span,
    saved: f64,
    mark: usize,
    result: Result<Done, Diagnostic>,
) -> Result<(), Stop> {
    let done = result.map_err(|d| {
        let d = if d.span().is_some() {
            d
        } else {
            d.primary(span, "in this cycle call")
        };
        Stop::Error(d)
    })?;
    if done.feed.is_some_and(|f| f != saved) && saved > 0.0 {
        it.out(Canon::SetFeedRate(saved));
    }
    for m in &done.coolant {
        match m {
            7 => it.state.mist = true,
            8 => it.state.flood = true,
            _ => (it.state.mist, it.state.flood) = (false, false),
        }
    }
    for w in done.warnings {
        it.diags.push(w.primary(span, "in this cycle call"));
    }
    it.take_error(mark)
}

/// 254 through SLOT2 (see `cycles_slot`).
fn circular_slot(host: &mut dyn MotionHost, q: &Qs, r: f64) -> Result<Done, Diagnostic> {
    super::cycles_geom::need_radius(254, r)?;
    let here = Place::here(host).origin();
    let args = cycles_slot::slot2_args(q, here)?;
    match milling::run(host, "SLOT2", &args, r) {
        Ok(milling::Outcome::Done) => Ok(Done::default()),
        Ok(milling::Outcome::NotExpanded(why)) => Ok(Done {
            warnings: vec![Diagnostic::new(
                Code::CannotExpandCycle,
                format!("cycle 254 (run as Siemens SLOT2) not expanded: {why}"),
            )],
            ..Done::default()
        }),
        Err(d) => Err(d.note(
            "cycle 254 runs as the Siemens SLOT2 expansion; its message names SLOT2's parameters",
        )),
    }
}
