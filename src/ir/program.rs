//! A whole program: its blocks and the arenas they refer to.

use super::arena::Arena;
use super::expr::Expr;
use super::stmt::Block;
use crate::span::FileId;
use serde::Serialize;

#[derive(Clone, Debug, Default, Serialize)]
pub struct Program {
    pub file: FileId,
    /// The id of the dialect it was read as (`fanuc`, `siemens840d`, ...).
    pub dialect: String,
    pub blocks: Vec<Block>,
    pub exprs: Arena<Expr>,
}

impl Program {
    pub fn new(file: FileId, dialect: impl Into<String>) -> Self {
        Program {
            file,
            dialect: dialect.into(),
            blocks: Vec::new(),
            exprs: Arena::new(),
        }
    }
}
