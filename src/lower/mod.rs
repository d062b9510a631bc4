//! Lowering: a line's words to meta-model statements, by the dialect spec.
