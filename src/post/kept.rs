//! Why a workingstep the reader kept as written cannot be posted. The
//! reader keeps a `MACHINING_WORKINGSTEP` raw (W0802) when a mandatory
//! reference under it is `$`: an operation whose technology is `$`, a
//! tool whose body is `$`. ISO 14649-10/11/111 give these no default
//! (a technology is the feed and the speed; a tool body is the tool's
//! type and diameter), so nothing can stand in for them: the post
//! refuses with E0901, naming each such attribute by its query path from
//! the workingstep, and the first is located in the file
//! ([`crate::stepnc::query::locate_path`]).

use super::PostError;
use crate::diag::Code;
use crate::stepnc::model::{Raw, RawValue};
use crate::stepnc::schema::{self, Kind};

/// A mandatory reference left `$`: its path and attribute.
struct Missing {
    path: String,
    entity: String,
    attr: String,
}

/// The refusal of the raw workingstep `raw`, found at query path `path`.
pub fn refusal(raw: &Raw, path: &str) -> PostError {
    let id = match raw.params.first() {
        Some(RawValue::String(s)) if !s.is_empty() => s.clone(),
        _ => raw.entity.clone(),
    };
    let mut found = Vec::new();
    // The operation (and its tool) first: what the post needs most.
    for attr in ["its_operation", "its_feature"] {
        if let Some((k, RawValue::Instance(inner))) = attr_of(raw, attr) {
            let _ = k;
            missing(inner, &format!("{path}/{attr}"), &mut found, 0);
        }
    }
    let Some(first) = found.first() else {
        return PostError::unsupported(
            &id,
            "a workingstep cncc kept as written when reading (the kept-raw warning W0802 names the attribute that does not fit ISO 14649)",
        );
    };
    let more: Vec<String> = found
        .iter()
        .skip(1)
        .filter(|m| meaning(&m.attr).is_some())
        .take(4)
        .map(|m| format!("{}.{}", m.entity, m.attr))
        .collect();
    let also = if more.is_empty() {
        String::new()
    } else {
        format!("; also `$`: {}", more.join(", "))
    };
    PostError {
        code: Code::PostBadProject,
        message: format!(
            "`{}`: workingstep `{id}` cannot be posted: its {}.{} is `$`, which ISO 14649 makes mandatory and gives no default for ({}){also}",
            first.path,
            first.entity,
            first.attr,
            meaning(&first.attr).unwrap_or("a value the workingstep needs")
        ),
        help: "give the attribute its value in the STEP-NC file (the kept-raw warning W0802 points at it too)".into(),
    }
}

fn attr_of<'r>(raw: &'r Raw, name: &str) -> Option<(usize, &'r RawValue)> {
    let def = schema::entity(&raw.entity)?;
    let k = def.attr_index(name)?;
    Some((k, raw.params.get(k)?))
}

/// Mandatory instance attributes left `$` under `raw`, depth first in
/// attribute order.
fn missing(raw: &Raw, path: &str, out: &mut Vec<Missing>, depth: usize) {
    let Some(def) = schema::entity(&raw.entity) else {
        return;
    };
    if depth > 8 {
        return;
    }
    for (a, v) in def.attrs.iter().zip(&raw.params) {
        let reference = matches!(a.kind, Kind::Instance | Kind::Select);
        match v {
            RawValue::Null if reference && !a.optional => out.push(Missing {
                path: format!("{path}/{}", a.name),
                entity: def.name.clone(),
                attr: a.name.clone(),
            }),
            RawValue::Instance(inner) => {
                missing(inner, &format!("{path}/{}", a.name), out, depth + 1)
            }
            _ => {}
        }
    }
}

/// What the attribute would have told the post.
fn meaning(attr: &str) -> Option<&'static str> {
    Some(match attr {
        "its_technology" => "the feed and the spindle speed",
        "its_machine_functions" => "coolant and the other machine functions",
        "its_tool" => "the tool",
        "its_tool_body" => "the tool's type and diameter",
        "distance" => "the path's length",
        "its_direction" => "the path's direction",
        "depth" => "the feature's depth",
        "feature_placement" => "where the feature is",
        "location" => "the placement's point",
        _ => return None,
    })
}
