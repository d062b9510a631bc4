//! The post template sets, one per target dialect, compiled in from
//! `posts/<dialect>/*.j2` so the binary is self-contained. A set lists
//! what the target can do: a feature whose template is missing (no
//! `pocket_rect.j2` on Fanuc) is posted as explicit moves.
//! (Generated list: keep it in step with the folders; a test checks.)

macro_rules! set {
    ($dir:literal: $($name:literal),* $(,)?) => {
        &[$(($name, include_str!(concat!("../../posts/", $dir, "/", $name)))),*]
    };
}

type Set = &'static [(&'static str, &'static str)];

const SIEMENS_840D: Set = set!("siemens840d": "approach.j2", "arc.j2", "begin.j2", "bore.j2", "comment.j2", "coolant.j2", "cycle_end.j2", "drill.j2", "drill_dwell.j2", "end.j2", "face.j2", "helix.j2", "hole_at.j2", "holes_circle.j2", "holes_grid.j2", "holes_row.j2", "line.j2", "peck.j2", "pocket_circ.j2", "pocket_circ_any.j2", "pocket_rect.j2", "pocket_rect_any.j2", "rapid.j2", "ream.j2", "retract.j2", "slot1.j2", "slot_longhole.j2", "spindle.j2", "stop.j2", "tap.j2", "tap_float.j2", "tilt.j2", "tolerance.j2", "tool_change.j2", "tool_data.j2", "untilt.j2");
const FANUC: Set = set!("fanuc": "approach.j2", "arc.j2", "begin.j2", "bore.j2", "comment.j2", "coolant.j2", "cycle_end.j2", "drill.j2", "drill_dwell.j2", "end.j2", "helix.j2", "hole_at.j2", "line.j2", "peck.j2", "rapid.j2", "ream.j2", "retract.j2", "spindle.j2", "stop.j2", "tap.j2", "tool_change.j2");
const HAAS: Set = set!("haas": "approach.j2", "arc.j2", "begin.j2", "bore.j2", "comment.j2", "coolant.j2", "cycle_end.j2", "drill.j2", "drill_dwell.j2", "end.j2", "helix.j2", "hole_at.j2", "line.j2", "peck.j2", "pocket_circ_g12.j2", "rapid.j2", "ream.j2", "retract.j2", "spindle.j2", "stop.j2", "tap.j2", "tool_change.j2");
const HEIDENHAIN: Set = set!("heidenhain": "approach.j2", "arc.j2", "begin.j2", "bore.j2", "comment.j2", "coolant.j2", "cycle_end.j2", "drill.j2", "drill_dwell.j2", "end.j2", "face.j2", "helix.j2", "hole_at.j2", "holes_circle.j2", "holes_grid.j2", "holes_row.j2", "line.j2", "peck.j2", "peck_universal.j2", "pocket_circ.j2", "pocket_rect.j2", "rapid.j2", "ream.j2", "retract.j2", "slot.j2", "spindle.j2", "stop.j2", "tap.j2", "tap_float.j2", "tilt.j2", "tolerance.j2", "tool_change.j2", "tool_data.j2", "untilt.j2");
const LINUXCNC: Set = set!("linuxcnc": "approach.j2", "arc.j2", "begin.j2", "bore.j2", "comment.j2", "coolant.j2", "cycle_end.j2", "drill.j2", "drill_dwell.j2", "end.j2", "helix.j2", "hole_at.j2", "line.j2", "peck.j2", "rapid.j2", "ream.j2", "retract.j2", "spindle.j2", "stop.j2", "tap.j2", "tool_change.j2");

/// The templates of a dialect (by id), if it has a post.
pub fn template_set(dialect: &str) -> Option<Set> {
    Some(match dialect {
        "siemens840d" => SIEMENS_840D,
        "fanuc" => FANUC,
        "haas" => HAAS,
        "linuxcnc" => LINUXCNC,
        "heidenhain" => HEIDENHAIN,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_template_file_is_compiled_in() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("posts");
        for d in ["siemens840d", "fanuc", "haas", "linuxcnc", "heidenhain"] {
            let mut on_disk: Vec<String> = std::fs::read_dir(root.join(d))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect();
            on_disk.sort();
            let compiled: Vec<String> = template_set(d)
                .unwrap()
                .iter()
                .map(|(n, _)| n.to_string())
                .collect();
            assert_eq!(on_disk, compiled, "{d}");
        }
    }
}
