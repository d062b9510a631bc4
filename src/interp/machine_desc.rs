//! The machine a program runs on, as far as a check needs it (`--machine
//! FILE`, TOML): where the reference point is (the target of G28, Siemens
//! G74 and Heidenhain M91 returns) and where each work offset puts the work
//! zero, in machine coordinates.
//!
//! ```toml
//! units = "mm"            # of the numbers below (mm or inch)
//! [reference]             # machine coordinates of the reference point
//! x = 0.0
//! y = 0.0
//! z = 0.0
//! [work-offsets]          # machine coordinates of each work zero
//! G54 = { x = -400.0, y = -250.0, z = -500.0 }
//! ```
//!
//! Without a file, `check`, `stats`, `plot` and `stepnc` use
//! [`Machine::default`]: the reference point at machine zero and every
//! work zero (G54..G59) 500 mm below it (a vertical machining centre's Z
//! travel is of that order [?]), so a return to the reference point, and
//! an M91/G53 move to a machine Z near 0, go up, never to "work Z0 minus
//! the tool length". `canon` keeps
//! LinuxCNC's standalone interpreter's state (every stored position 0)
//! unless a file is given, so its calls stay comparable with rs274's.

use serde::Deserialize;
use std::collections::BTreeMap;

/// A machine description, in millimetres.
#[derive(Clone, Debug, PartialEq)]
pub struct Machine {
    /// The reference point (machine X Y Z).
    pub reference: [f64; 3],
    /// Work offsets by index (1 = G54 .. 6 = G59): machine X Y Z of the
    /// work zero.
    pub work_offsets: BTreeMap<u32, [f64; 3]>,
}

impl Default for Machine {
    fn default() -> Self {
        Machine {
            reference: [0.0; 3],
            work_offsets: (1..=6).map(|i| (i, [0.0, 0.0, -500.0])).collect(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    #[serde(default = "mm")]
    units: String,
    #[serde(default)]
    reference: Point,
    #[serde(default, rename = "work-offsets")]
    work_offsets: BTreeMap<String, Point>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Point {
    #[serde(default)]
    x: f64,
    #[serde(default)]
    y: f64,
    #[serde(default)]
    z: f64,
}

fn mm() -> String {
    "mm".into()
}

impl Machine {
    /// Sets the reference point (#5161.., #5181..: G28 and G30) and the
    /// work offsets of a run about to start.
    pub fn apply(&self, it: &mut super::Interp<'_, '_>) {
        let scale = match it.opts.machine_units {
            crate::ir::LengthUnit::Mm => 1.0,
            crate::ir::LengthUnit::Inch => 1.0 / super::state::MM_PER_INCH,
        };
        for (i, v) in self.reference.iter().enumerate() {
            it.params.set_numbered(5161 + i as u32, Some(v * scale));
            it.params.set_numbered(5181 + i as u32, Some(v * scale));
        }
        for (&k, at) in &self.work_offsets {
            it.state.g5x[k as usize][..3].copy_from_slice(at);
        }
    }

    /// Reads a machine description; the error says what is wrong.
    pub fn parse(text: &str) -> Result<Machine, String> {
        let f: File = toml::from_str(text).map_err(|e| e.to_string())?;
        let k = match f.units.as_str() {
            "mm" => 1.0,
            "inch" | "in" => 25.4,
            u => return Err(format!("units = \"{u}\": write \"mm\" or \"inch\"")),
        };
        let p = |p: &Point| [p.x * k, p.y * k, p.z * k];
        // Work offsets the file does not give stay at the default's.
        let mut work_offsets = Machine::default().work_offsets;
        for (name, at) in &f.work_offsets {
            let index = work_offset_index(name)
                .ok_or_else(|| format!("work offset `{name}`: write G54 .. G59"))?;
            work_offsets.insert(index, p(at));
        }
        let m = Machine {
            reference: p(&f.reference),
            work_offsets,
        };
        if m.numbers().any(|v| !v.is_finite() || v.abs() > 1e6) {
            return Err("a coordinate is not a number of at most 1000 m".into());
        }
        Ok(m)
    }

    fn numbers(&self) -> impl Iterator<Item = f64> + '_ {
        self.reference
            .iter()
            .chain(self.work_offsets.values().flatten())
            .copied()
    }
}

/// `G54` → 1 .. `G59` → 6.
fn work_offset_index(name: &str) -> Option<u32> {
    let n: u32 = name
        .trim()
        .to_ascii_uppercase()
        .strip_prefix('G')?
        .parse()
        .ok()?;
    (54..=59).contains(&n).then(|| n - 53)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_machine_in_inches() {
        let m = Machine::parse(
            "units = \"inch\"\n[reference]\nz = 10\n[work-offsets]\nG55 = { x = -10, z = -15 }\n",
        )
        .unwrap();
        assert_eq!(m.reference, [0.0, 0.0, 254.0]);
        assert_eq!(m.work_offsets[&2], [-254.0, 0.0, -381.0]);
    }

    #[test]
    fn says_what_is_wrong() {
        assert!(Machine::parse("[work-offsets]\nG60 = { x = 1 }\n")
            .unwrap_err()
            .contains("G54 .. G59"));
        assert!(Machine::parse("units = \"cm\"\n")
            .unwrap_err()
            .contains("mm"));
        assert!(Machine::parse("[reference]\nw = 1\n").is_err());
    }
}
