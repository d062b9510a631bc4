//! Calls of Siemens programs in other files (`L140`, `L140(1, 2.5)`,
//! `KONUS(3)`) for a word-address target, matching how
//! [`super::proc_file`] writes the called `PROC` file:
//!
//! * LinuxCNC: `o<l140> call [1] [2.5]`, `o<konus> call [3]`: the control
//!   finds `l140.ngc` / `konus.ngc` on its subroutine path, a file that
//!   holds `o<l140> sub` ... `o<l140> endsub`.
//! * Fanuc, Haas: `L140(1, 2.5)` → `G65 P140 A1. B2.5`, the arguments on
//!   the letters in order (`A`, `B`, `C`, `I`, `J`, `K`, `D`, ...), which
//!   the ported PROC reads; a call without arguments stays `M98 P140`. A
//!   named PROC has no program number: the writer refuses the call.
//!
//! An empty argument slot (`L140(1,,3)`) passes 0: Siemens gives a value
//! parameter left out its type's default, 0 [?: from the 840D programming
//! manual's description of value parameters; not checked on a control],
//! where a Fanuc letter left out would leave the local vacant.

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{CallArgs, CallKind, CallTarget, Decimal, ExprKind, Program, StmtKind, Value};

/// The argument letters in the order [`super::proc_file`] gives them.
const LETTERS: [char; 21] = [
    'A', 'B', 'C', 'I', 'J', 'K', 'D', 'E', 'F', 'H', 'M', 'Q', 'R', 'S', 'T', 'U', 'V', 'W', 'X',
    'Y', 'Z',
];

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if !from.has(Capability::StructuredControl) || to.has(Capability::StructuredControl) {
        return;
    }
    let to_oword = to.has(Capability::OWords);
    let to_macro = to.has(Capability::NumberedPrograms) && to.has(Capability::MacroB);
    if !to_oword && !to_macro {
        return;
    }
    for bi in 0..p.blocks.len() {
        for si in 0..p.blocks[bi].stmts.len() {
            let StmtKind::Call {
                kind: kind @ CallKind::Named,
                target,
                args,
                repeat: None,
            } = &mut p.blocks[bi].stmts[si].kind
            else {
                continue;
            };
            if to_oword {
                let Some(name) = file_name(target) else {
                    continue;
                };
                *target = CallTarget::Name(name);
                *kind = CallKind::OWord;
                continue;
            }
            let CallArgs::Positional(list) = args else {
                continue;
            };
            if list.is_empty() || list.len() > LETTERS.len() {
                continue;
            }
            let list = std::mem::take(list);
            let letters: Vec<(char, Value)> = LETTERS
                .iter()
                .zip(list)
                .map(|(l, a)| {
                    let v = match a.map(|e| (e, &p.exprs[e].kind)) {
                        Some((_, ExprKind::Number(d))) => Value::Number(*d),
                        Some((e, _)) => Value::Expr(e),
                        None => Value::Number(Decimal::from_int(0)),
                    };
                    (*l, v)
                })
                .collect();
            let StmtKind::Call { kind, args, .. } = &mut p.blocks[bi].stmts[si].kind else {
                continue;
            };
            *kind = CallKind::Macro;
            *args = CallArgs::Letters(letters);
        }
    }
}

/// The LinuxCNC name of the called program's file: `L140` → `l140`.
fn file_name(target: &CallTarget) -> Option<String> {
    match target {
        CallTarget::Number(n) => Some(format!("l{n}")),
        CallTarget::Name(n) => Some(n.to_ascii_lowercase()),
        CallTarget::Computed(_) => None,
    }
}
