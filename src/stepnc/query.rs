//! Attribute paths over a Part 21 file (placeholder replaced below).
