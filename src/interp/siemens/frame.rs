//! The Siemens programmable frame as an affine map from programmed
//! coordinates to the settable work offset's frame (the "base" in which
//! canonical calls are printed).
//!
//! Sources: SINUMERIK 840D programming manual (fundamentals), "Frames"
//! chapter, as summarised in `reference/dialects.md` §1.5 [K]:
//!
//! * The frame chain is machine → basic frame → settable frame (G54..) →
//!   programmable frame. Canon positions are printed in the settable
//!   frame's coordinates (as rs274 prints positions relative to G5x), so
//!   only the programmable frame is applied here.
//! * Within one programmable frame the components act in the order
//!   TRANS, ROT, SCALE, MIRROR. Every additive instruction (ATRANS, AROT,
//!   ASCALE, AMIRROR) acts in the coordinate system the frame built so far
//!   defines, so a later ATRANS is rotated, scaled and mirrored by what was
//!   programmed before it. The map is kept as `base = m · p + t`; an
//!   additive step `g` gives `m' = m · g.m`, `t' = m · g.t + t`.
//! * An absolute instruction (TRANS, ROT, SCALE, MIRROR) replaces the whole
//!   programmable frame; written without axes it clears it.
//! * `ROT X.. Y.. Z..` turns about Z, then the new Y, then the newest X
//!   (roll-pitch-yaw order of MD 10600 FRAME_ANGLE_ORDER's default) [?];
//!   `ROT RPL=` turns about the active plane's normal (G17 Z, G18 Y,
//!   G19 X), positive counter-clockwise looking down the normal.
//! * `MIRROR X0` inverts the X direction; the value written is ignored [K].
//! * Lengths are millimetres, like the interpreter's state.

//!
//! The map itself is the geometry kernel's [`crate::geom::Transform`]
//! (`base = m · p + t`); this module names it for the 840D.

/// One programmable frame: `base = m · p + t` (mm).
pub use crate::geom::Transform as ProgFrame;
