//! The post templates a spec can declare (`<post-template name="drill"/>`):
//! what a target's post can write. Each name is a template file
//! `NAME.j2` that `cncc post` fills (src/post/); a spec that declares a
//! name must have its file (in `--post-dir`, or in the built-in folder
//! `posts/<id>/` of the spec or of one it extends), and a feature whose
//! template the spec does not declare is refused, or posted another way
//! where the post has one (a pocket without `pocket_rect` becomes
//! explicit moves). The schema's `postTemplate` enumeration lists the
//! same names (a test checks).

use crate::span::Span;

/// (name, what the template writes).
pub const POST_TEMPLATES: &[(&str, &str)] = &[
    (
        "begin",
        "the program start: number, title, modal reset, blank form",
    ),
    ("end", "the program end"),
    ("comment", "a comment line"),
    ("tool_change", "a tool change"),
    (
        "tool_data",
        "a tool's data in the program (840D $TC_DP, Heidenhain TOOL DEF)",
    ),
    ("spindle", "the spindle on at a speed"),
    ("coolant", "coolant on or off"),
    ("stop", "an optional stop"),
    ("tolerance", "the path tolerance for a workingstep"),
    (
        "approach",
        "the first positioning of a workingstep (with the length offset)",
    ),
    ("retract", "the retract to the clearance plane"),
    ("rapid", "a rapid move"),
    ("line", "a feed move"),
    ("arc", "a circular move in the XY plane"),
    ("helix", "one piece of a helix (at most half a turn)"),
    ("drill", "the drilling cycle"),
    (
        "drill_dwell",
        "the drilling cycle with a dwell at the bottom",
    ),
    ("peck", "the peck drilling cycle"),
    (
        "peck_universal",
        "a pecking cycle with decreasing infeeds and chip breaking",
    ),
    ("ream", "the reaming cycle"),
    ("bore", "the boring cycle"),
    ("tap", "the tapping cycle"),
    ("tap_float", "tapping with a compensating chuck"),
    ("hole_at", "a hole position for the modal cycle"),
    ("cycle_end", "the end of a modal cycle"),
    ("holes_row", "holes on a line as one pattern"),
    ("holes_grid", "holes on a grid as one pattern"),
    ("holes_circle", "holes on a circle as one pattern"),
    ("face", "the face milling cycle"),
    (
        "pocket_rect",
        "the rectangular pocket cycle, at the pocket's centre",
    ),
    (
        "pocket_rect_any",
        "the rectangular pocket cycle with an approach and allowances on floor",
    ),
    (
        "pocket_circ",
        "the circular pocket cycle, at the pocket's centre",
    ),
    (
        "pocket_circ_any",
        "the circular pocket cycle with an approach and allowances on floor",
    ),
    ("pocket_circ_g12", "one circular pocket pass (Haas G12/G13)"),
    ("slot", "the slot cycle"),
    ("slot1", "the slot cycle of the 840D (SLOT1)"),
    ("slot_longhole", "the elongated hole cycle (LONGHOLE)"),
    ("tilt", "tilting the working plane onto a feature's axis"),
    ("untilt", "the working plane back to the machine's"),
];

/// A `<post-template>` a spec declares, with where (for a missing file).
#[derive(Clone, Debug, PartialEq)]
pub struct PostTemplateDecl {
    pub name: String,
    pub span: Span,
}

/// True when `name` is a template the post knows.
pub fn is_post_template(name: &str) -> bool {
    POST_TEMPLATES.iter().any(|(n, _)| *n == name)
}
