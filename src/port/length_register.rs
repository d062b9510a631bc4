//! `Z4. H2` (a length register alone while G43/G44 is in force) for a
//! target where an H needs its G43 (capability `offset-register-alone`
//! in the source, not in the target): the register becomes `G43 H2`
//! (`G44 H2` under G44), which every target writes in its own form (a
//! LinuxCNC `G43 H2`; the Siemens and Klartext tool call carries the
//! length). On the source the new register's length replaces the old
//! from this block on, so the same length is used.
//!
//! The mode is followed in written order [?: a G43 set in a subprogram
//! and an H alone in its caller are not seen; verify would tell].

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{LengthComp, Program, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if !from.has(Capability::OffsetRegisterAlone) || to.has(Capability::OffsetRegisterAlone) {
        return;
    }
    let letters: Vec<char> = from
        .addresses
        .iter()
        .filter(|a| a.role == "length-offset")
        .map(|a| a.letter)
        .collect();
    let mut mode: Option<LengthComp> = None;
    for b in &mut p.blocks {
        // `G42 H19`: the H of a compensation block is not a length [?].
        let comp = b
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::RadiusComp { .. }));
        for s in &mut b.stmts {
            match &s.kind {
                StmtKind::LengthComp { mode: m, .. } => {
                    mode = match m {
                        LengthComp::Positive | LengthComp::Negative => Some(*m),
                        _ => None,
                    };
                }
                StmtKind::OffsetRegister { letter, value } if letters.contains(letter) && !comp => {
                    if let Some(m) = mode {
                        s.kind = StmtKind::LengthComp {
                            mode: m,
                            register: Some(value.clone()),
                            axes: Box::default(),
                        };
                    }
                }
                _ => {}
            }
        }
    }
}
