//! Writing the generic graph as Part 21 text: a header, then one instance
//! per line, `#n=NAME(p1,p2);`, reals always with a decimal point, strings
//! re-escaped.

use super::lexer::encode_string;
use super::{Instance, Param, Record, Value};
use std::fmt::Write;

/// The whole file: header records then instances in the order given.
pub fn write_file(header: &[Record], instances: &[Instance]) -> String {
    let mut out = String::with_capacity(64 * instances.len() + 256);
    out.push_str("ISO-10303-21;\nHEADER;\n");
    for r in header {
        write_record(&mut out, r);
        out.push_str(";\n");
    }
    out.push_str("ENDSEC;\nDATA;\n");
    for i in instances {
        write_instance(&mut out, i);
    }
    out.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    out
}

/// `#n=NAME(...);` and a newline.
pub fn write_instance(out: &mut String, i: &Instance) {
    let _ = write!(out, "#{}=", i.id);
    if i.is_complex() {
        out.push('(');
        write_parts(out, &i.entity, &i.params);
        for r in &i.more_parts {
            write_record(out, r);
        }
        out.push(')');
    } else {
        write_parts(out, &i.entity, &i.params);
    }
    out.push_str(";\n");
}

pub fn write_record(out: &mut String, r: &Record) {
    write_parts(out, &r.entity, &r.params);
}

fn write_parts(out: &mut String, entity: &str, params: &[Param]) {
    out.push_str(entity);
    out.push('(');
    write_params(out, params);
    out.push(')');
}

fn write_params(out: &mut String, params: &[Param]) {
    for (k, p) in params.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        write_value(out, &p.value);
    }
}

/// One parameter value.
pub fn write_value(out: &mut String, v: &Value) {
    match v {
        Value::Null => out.push('$'),
        Value::Derived => out.push('*'),
        Value::Int(i) => {
            let _ = write!(out, "{i}");
        }
        Value::Real(r) => push_real(out, *r),
        Value::Str(s) => push_string(out, s),
        Value::Enum(e) => {
            let _ = write!(out, ".{e}.");
        }
        Value::Binary(b) => {
            let _ = write!(out, "\"{b}\"");
        }
        Value::Ref(n) => {
            let _ = write!(out, "#{n}");
        }
        Value::List(l) => {
            out.push('(');
            write_params(out, l);
            out.push(')');
        }
        Value::Typed(name, p) => {
            out.push_str(name);
            out.push('(');
            write_value(out, &p.value);
            out.push(')');
        }
    }
}

/// Appends [`real`] without a String of its own.
pub fn push_real(out: &mut String, r: f64) {
    if push_short_decimal(out, r) {
        return;
    }
    let start = out.len();
    let _ = write!(out, "{r}");
    if !out[start..].contains('.') {
        out.push('.');
    }
}

/// The common case of [`push_real`] without the general float formatter:
/// `r` is `m / 10^k` for an integer `|m| < 2^52` and a small `k`. Then
/// `m` is the only such integer for that `k` (doubles there are closer
/// than `10^-k`), and the least such `k` gives the shortest digits, which
/// is what `{}` prints. Anything else (or a doubt: `m` ending in 0 means
/// a smaller `k` was missed) returns false and is left to `{}`.
fn push_short_decimal(out: &mut String, r: f64) -> bool {
    const POW10: [f64; 7] = [1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6];
    const LIMIT: f64 = (1u64 << 52) as f64;
    if r == 0.0 && r.is_sign_negative() {
        return false;
    }
    for (k, &p) in POW10.iter().enumerate() {
        let m = (r * p).round();
        if !(m.abs() < LIMIT) {
            return false;
        }
        if m / p != r {
            continue;
        }
        let m = m.abs() as u64;
        if k > 0 && m % 10 == 0 {
            return false;
        }
        if r < 0.0 {
            out.push('-');
        }
        let scale = 10u64.pow(k as u32);
        let _ = write!(out, "{}.", m / scale);
        if k > 0 {
            let _ = write!(out, "{:0width$}", m % scale, width = k);
        }
        return true;
    }
    false
}

/// Appends `'text'`, escaped as Part 21 wants.
pub fn push_string(out: &mut String, s: &str) {
    out.push('\'');
    if s.bytes()
        .all(|b| matches!(b, b' '..=b'~') && b != b'\'' && b != b'\\')
    {
        out.push_str(s);
    } else {
        out.push_str(&encode_string(s));
    }
    out.push('\'');
}

/// A real in the shortest form that reads back to the same `f64`, always
/// with a decimal point (`10.`, `0.04`, `-12.`).
pub fn real(r: f64) -> String {
    let mut s = format!("{r}");
    if !s.contains('.') {
        s.push('.');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_decimals_print_as_display_does() {
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut values = vec![
            0.0,
            1.0,
            -1.0,
            0.5,
            12.345,
            -27.94,
            1e-6,
            4503599627370495.0,
        ];
        for _ in 0..200_000 {
            let x = next();
            let digits = (x % 7) as i32;
            let m = ((x >> 8) % 100_000_000) as f64 - 50_000_000.0;
            values.push(m / 10f64.powi(digits));
            values.push(f64::from_bits(next() >> 2));
            values.push((next() % 1000) as f64 * 0.001 + 0.1);
        }
        for v in values {
            let mut pushed = String::new();
            push_real(&mut pushed, v);
            assert_eq!(pushed, real(v), "{v:e}");
        }
    }

    #[test]
    fn strings_pushed_as_encoded() {
        for t in ["plain", "it's", "a\\b", "Peça", ""] {
            let mut pushed = String::new();
            push_string(&mut pushed, t);
            assert_eq!(pushed, format!("'{}'", encode_string(t)));
        }
    }

    #[test]
    fn reals_have_a_point_and_round_trip() {
        assert_eq!(real(10.0), "10.");
        assert_eq!(real(0.04), "0.04");
        assert_eq!(real(-12.0), "-12.");
        for v in [0.1 + 0.2, 1e-9, 123456.789, 1e22, -0.0, 7.0] {
            assert_eq!(real(v).parse::<f64>().unwrap(), v);
            let mut pushed = String::from("x");
            push_real(&mut pushed, v);
            assert_eq!(pushed, format!("x{}", real(v)));
        }
    }
}
