//! [`Stats`] as text for people (a table per tool and a total) or as JSON.

use super::{Bounds, Stats, ToolStats};
use crate::compare::describe::num;
use std::fmt::Write;

/// `h:mm:ss.s`
pub fn duration(s: f64) -> String {
    let s = s.max(0.0);
    let h = (s / 3600.0).floor();
    let m = ((s - h * 3600.0) / 60.0).floor();
    let sec = s - h * 3600.0 - m * 60.0;
    format!("{}:{:02}:{:04.1}", h as u64, m as u64, sec)
}

fn range(r: Option<[f64; 2]>) -> String {
    match r {
        None => "-".into(),
        Some([a, b]) if (a - b).abs() < 1e-9 => num(a),
        Some([a, b]) => format!("{}..{}", num(a), num(b)),
    }
}

fn boxed(b: &Bounds) -> String {
    if b.is_empty() {
        return "-".into();
    }
    let axis = |k: usize| format!("{}..{}", num(b.min[k]), num(b.max[k]));
    format!("X{} Y{} Z{}", axis(0), axis(1), axis(2))
}

fn row(out: &mut String, name: &str, t: &ToolStats) {
    let dia = t
        .diameter_mm
        .map(|d| num((d * 1000.0).round() / 1000.0))
        .unwrap_or("-".into());
    let _ = writeln!(
        out,
        "{name:<7} {dia:>8} {:>12} {:>11} {:>14} {:>11}  {}  Z {}",
        format!("{:.1}", t.cutting_mm),
        format!("{:.1}", t.rapid_mm),
        range(t.feed_range),
        duration(t.total_s()),
        boxed(&t.cutting_box),
        range(t.z_range),
    );
}

/// The table for people.
pub fn human(s: &Stats) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<7} {:>8} {:>12} {:>11} {:>14} {:>11}  cutting box; Z range of all moves",
        "tool", "dia mm", "cutting mm", "rapid mm", "feed mm/min", "time"
    );
    for t in &s.tools {
        row(&mut out, &format!("T{}", t.tool), t);
    }
    row(&mut out, "total", &s.total);
    let t = &s.total;
    let _ = writeln!(
        out,
        "estimated time {} = cutting {} + rapids {} + dwells {} + {} tool change{} {} \
         (rapids at {} mm/min, {} s per tool change)",
        duration(t.total_s()),
        duration(t.cutting_s),
        duration(t.rapid_s),
        duration(t.dwell_s),
        t.tool_changes,
        if t.tool_changes == 1 { "" } else { "s" },
        duration(t.tool_change_s),
        num(s.rapid_rate),
        num(s.tool_change_time_s),
    );
    if t.no_feed_mm > 0.0 {
        let _ = writeln!(
            out,
            "note: {:.1} mm of feed moves had no feed rate and are not timed",
            t.no_feed_mm
        );
    }
    out
}

/// One JSON object: `tools` (array), `total`, the options, and each
/// one's `time_s`.
pub fn json(s: &Stats) -> String {
    let one = |t: &ToolStats| {
        let mut v = serde_json::to_value(t).unwrap_or_default();
        if let Some(o) = v.as_object_mut() {
            o.insert("time_s".into(), t.total_s().into());
            if t.cutting_box.is_empty() {
                o.insert("cutting_box".into(), serde_json::Value::Null);
            }
        }
        v
    };
    let v = serde_json::json!({
        "tools": s.tools.iter().map(one).collect::<Vec<_>>(),
        "total": one(&s.total),
        "rapid_rate_mm_min": s.rapid_rate,
        "tool_change_time_s": s.tool_change_time_s,
    });
    let mut text = serde_json::to_string_pretty(&v).unwrap_or_default();
    text.push('\n');
    text
}
