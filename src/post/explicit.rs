//! Explicit moves through the target's `rapid.j2`, `line.j2` and `arc.j2`
//! templates (arc centres incremental from the start, I J).

use super::paths::Move;
use super::values::Vals;
use super::{PostError, Writer};

pub fn write(w: &mut Writer<'_>, moves: &[Move], feed: f64, clear: f64) -> Result<(), PostError> {
    let f = w.fmt.feed(feed);
    let mut at: Option<[f64; 3]> = None;
    for m in moves {
        match m {
            Move::Rapid(p) => {
                w.emit("rapid.j2", xyz(w, *p))?;
                at = Some(*p);
            }
            Move::Line(p) => {
                w.emit("line.j2", xyz(w, *p).set("f", f.clone()))?;
                at = Some(*p);
            }
            Move::Arc { to, centre, ccw } => {
                let from = at.unwrap_or([to[0], to[1], clear]);
                let v = Vals::new()
                    .set("g", if *ccw { "3" } else { "2" })
                    .set("x", w.fmt.len(to[0]))
                    .set("y", w.fmt.len(to[1]))
                    .set("i", w.fmt.len(centre[0] - from[0]))
                    .set("j", w.fmt.len(centre[1] - from[1]))
                    .set("f", f.clone());
                w.emit("arc.j2", v)?;
                at = Some(*to);
            }
        }
    }
    Ok(())
}

fn xyz(w: &Writer<'_>, p: [f64; 3]) -> Vals {
    Vals::new()
        .set("x", w.fmt.len(p[0]))
        .set("y", w.fmt.len(p[1]))
        .set("z", w.fmt.len(p[2]))
}
