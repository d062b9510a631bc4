//! Writers: meta-model to dialect text.
