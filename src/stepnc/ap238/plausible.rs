//! A plausibility check of the units an AP238 file declares [?].
//!
//! Every value is converted by its own declared unit (a length by its
//! `LENGTH_MEASURE_WITH_UNIT` or its representation context, a feed by its
//! `DERIVED_UNIT`). A file may still write millimetre numbers under an
//! inch unit (STEP-NC Maker's `test_program.stpnc` declares inch for a
//! 10-unit tool, a 2000 unit/min feed and a 20-unit square: a 254 mm end
//! mill at 50.8 m/min, or a 10 mm one at 2 m/min). All lengths scale
//! together, so the feed per revolution relative to the tool is the same
//! either way; only the absolute sizes tell. When, read in the declared
//! unit, the feed or the tool's cutting speed is beyond what milling runs
//! and the same numbers read as mm are not, `W0808 ap238-units-doubtful`
//! says so. The declared unit is kept: the reading is the standard's,
//! the doubt a warning.
//!
//! The limits are judgement, not standard [?]: 20 000 mm/min for a
//! cutting feed and 2 000 m/min for a cutting speed (high-speed aluminium
//! milling reaches about 1 000–3 000 m/min with small tools).

use crate::diag::{Code, Diagnostic};
use crate::span::Span;
use crate::stepnc::model::Technology;

/// Above this a cutting feed is implausible, mm/min [?].
pub const MAX_FEED: f64 = 20_000.0;
/// Above this a cutting speed is implausible, m/min [?].
pub const MAX_CUT_SPEED: f64 = 2_000.0;

/// An operation's values read in the declared unit and as mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Doubt {
    pub feed: f64,
    pub diameter: f64,
    pub rpm: f64,
    /// mm per unit of the feed's declared length unit.
    pub unit_mm: f64,
}

fn cut_speed(diameter_mm: f64, rpm: f64) -> f64 {
    std::f64::consts::PI * diameter_mm * rpm / 1000.0
}

fn implausible(feed: f64, diameter: f64, rpm: f64) -> bool {
    feed > MAX_FEED || cut_speed(diameter, rpm) > MAX_CUT_SPEED
}

/// The doubt about a technology's feed (in mm/min, converted from a
/// length unit of `unit_mm` mm) with a tool of `diameter` mm, when the
/// declared reading is implausible and the millimetre one is not. The
/// tool's diameter is read back by the feed's unit [?: a file giving
/// the tool in another unit than the feed is not told apart].
pub fn doubt(tech: &Technology, diameter: f64, unit_mm: f64) -> Option<Doubt> {
    let feed = tech.feed?;
    let rpm = tech.spindle.map_or(0.0, f64::abs);
    if !(unit_mm > 1.0 && unit_mm.is_finite()) {
        return None;
    }
    let as_mm = (feed / unit_mm, diameter / unit_mm);
    (implausible(feed, diameter, rpm) && !implausible(as_mm.0, as_mm.1, rpm)).then_some(Doubt {
        feed,
        diameter,
        rpm,
        unit_mm,
    })
}

impl Doubt {
    pub fn diagnostic(&self, tool: &str, at: Span) -> Diagnostic {
        let k = self.unit_mm;
        Diagnostic::new(
            Code::Ap238UnitsDoubtful,
            format!(
                "AP238: in the units the file declares (a length unit of {k} mm), this feed is {:.0} mm/min with tool `{tool}` {:.1} mm across at {:.0} rpm (cutting speed {:.0} m/min): implausible for milling [?]",
                self.feed,
                self.diameter,
                self.rpm,
                cut_speed(self.diameter, self.rpm),
            ),
        )
        .primary(at, "the feed, in its declared unit")
        .help(format!(
            "read as millimetres the same numbers give {:.0} mm/min with a {:.2} mm tool ({:.0} m/min); cncc keeps the declared units (see `cncc explain W0808`)",
            self.feed / k,
            self.diameter / k,
            cut_speed(self.diameter / k, self.rpm),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tech(feed: f64, rpm: f64) -> Technology {
        Technology {
            feed: Some(feed),
            spindle: Some(rpm),
            ..Technology::default()
        }
    }

    #[test]
    fn inch_numbers_that_look_like_mm_are_doubted() {
        // 2000 in/min, a 10 in tool, 3000 rpm.
        let d = doubt(&tech(50_800.0, -3000.0), 254.0, 25.4).unwrap();
        assert_eq!(d.rpm, 3000.0);
        // A plausible inch job (a 0.5 in tool at 40 in/min) is not.
        assert_eq!(doubt(&tech(1016.0, 8000.0), 12.7, 25.4), None);
        // Nor a millimetre file, however fast.
        assert_eq!(doubt(&tech(50_800.0, 3000.0), 254.0, 1.0), None);
    }
}
