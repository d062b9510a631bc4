//! Reading parameter values: numbers, strings, booleans, enumerations,
//! lists, and the failures when they are not what the schema says.

use super::{Fail, R};
use crate::span::Span;
use crate::stepnc::part21::{Instance, Param, Value};
use crate::stepnc::schema;

pub(crate) fn fail(span: Span, msg: impl Into<String>) -> Fail {
    Fail {
        msg: msg.into(),
        span,
        invalid: false,
        too_deep: false,
    }
}

/// A failure from nesting or expanding too far (E0812).
pub(crate) fn too_deep(span: Span, msg: impl Into<String>) -> Fail {
    Fail {
        msg: msg.into(),
        span,
        invalid: true,
        too_deep: true,
    }
}

/// A failure where the file breaks the schema.
pub(crate) fn invalid(span: Span, msg: impl Into<String>) -> Fail {
    Fail {
        msg: msg.into(),
        span,
        invalid: true,
        too_deep: false,
    }
}

/// The canonical entity name of an instance.
pub(crate) fn ent(i: &Instance) -> &str {
    schema::canonical(&i.entity)
}

/// Parameter `k` of an instance (validation has checked the count, but a
/// shorter instance still fails cleanly).
pub(crate) fn arg(i: &Instance, k: usize) -> R<&Param> {
    i.params
        .get(k)
        .ok_or_else(|| fail(i.span, format!("{} has no parameter {}", i.entity, k + 1)))
}

pub(crate) fn real(p: &Param) -> R<f64> {
    match p.value {
        Value::Real(v) => Ok(v),
        Value::Int(v) => Ok(v as f64),
        Value::Null => Err(fail(p.span, "a mandatory number is `$`")),
        _ => Err(fail(p.span, "expected a number")),
    }
}

pub(crate) fn opt_real(p: &Param) -> R<Option<f64>> {
    match p.value {
        Value::Null => Ok(None),
        _ => real(p).map(Some),
    }
}

pub(crate) fn int(p: &Param) -> R<i64> {
    match p.value {
        Value::Int(v) => Ok(v),
        _ => Err(fail(p.span, "expected an integer")),
    }
}

pub(crate) fn opt_int(p: &Param) -> R<Option<i64>> {
    match p.value {
        Value::Null => Ok(None),
        _ => int(p).map(Some),
    }
}

/// A string. `$` reads as the empty string: generators leave names and
/// labels unset (`CARTESIAN_POINT($,(...))`); validation warns (W0803).
pub(crate) fn string(p: &Param) -> R<String> {
    match &p.value {
        Value::Str(s) => Ok(s.clone()),
        Value::Null => Ok(String::new()),
        _ => Err(fail(p.span, "expected a string")),
    }
}

/// A boolean. `$` reads as `.F.` (the function is not asked for);
/// validation warns (W0803) and says so.
pub(crate) fn boolean(p: &Param) -> R<bool> {
    match &p.value {
        Value::Enum(e) if e == "T" => Ok(true),
        Value::Enum(e) if e == "F" => Ok(false),
        Value::Null => Ok(false),
        _ => Err(fail(p.span, "expected .T. or .F.")),
    }
}

pub(crate) fn opt_bool(p: &Param) -> R<Option<bool>> {
    match p.value {
        Value::Null => Ok(None),
        _ => boolean(p).map(Some),
    }
}

pub(crate) fn enumeration(p: &Param) -> R<&str> {
    match &p.value {
        Value::Enum(e) => Ok(e),
        Value::Null => Err(fail(p.span, "a mandatory enumeration is `$`")),
        _ => Err(fail(p.span, "expected an enumeration")),
    }
}

pub(crate) fn opt_enum(p: &Param) -> R<Option<&str>> {
    match p.value {
        Value::Null => Ok(None),
        _ => enumeration(p).map(Some),
    }
}

/// A list parameter. `$` reads as the empty list: JSDAI writers put `$`
/// for an empty aggregate, mandatory or not (validation warns, W0803, when
/// the attribute is mandatory); the writer gives `()` back.
pub(crate) fn list(p: &Param) -> R<&[Param]> {
    match &p.value {
        Value::List(l) => Ok(l),
        Value::Null => Ok(&[]),
        _ => Err(fail(p.span, "expected a list")),
    }
}

/// Checks an instance's entity against the accepted names.
pub(crate) fn expect<'i>(i: &'i Instance, names: &[&str], what: &str) -> R<&'i str> {
    let e = ent(i);
    if names.contains(&e) {
        Ok(e)
    } else {
        Err(invalid(
            i.entity_span,
            format!("expected {what}, found {} (#{})", i.entity, i.id),
        ))
    }
}
