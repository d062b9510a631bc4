//! Reading the single elements of a dialect spec (`<code>`, `<cycle>`,
//! `<function>` ...) into spec values, with a diagnostic pointing into the
//! XML for every attribute that is missing, unknown or malformed.

use super::meaning::Meaning;
use super::spec::*;
use super::xml::{Attr, Node};
use crate::diag::{Code, Diagnostic};
use crate::ir::{Decimal, DwellUnit, Func};

/// Most codes one `<code-range>` may define.
pub const MAX_RANGE: u32 = 1000;

/// Collects diagnostics while reading one spec file.
#[derive(Default)]
pub struct Ctx {
    pub diags: Vec<Diagnostic>,
}

impl Ctx {
    /// Reports attributes of `n` not in `allowed`.
    pub fn check_attrs(&mut self, n: &Node, allowed: &[&str]) {
        for a in &n.attrs {
            let ignorable = a.name.starts_with("xmlns") || a.name.starts_with("xsi:");
            if !ignorable && !allowed.contains(&a.name.as_str()) {
                let d = Diagnostic::new(
                    Code::SpecUnknownItem,
                    format!("`<{}>` has no attribute `{}`", n.name, a.name),
                )
                .primary(a.name_span, "unknown attribute")
                .help(format!("`<{}>` takes: {}", n.name, allowed.join(", ")));
                self.diags.push(d);
            }
        }
    }

    /// A required attribute; reports E0404 when it is absent.
    pub fn req<'n>(&mut self, n: &'n Node, name: &str) -> Option<&'n Attr> {
        let a = n.attr(name);
        if a.is_none() {
            let d = Diagnostic::new(
                Code::SpecMissing,
                format!("`<{}>` needs the attribute `{}`", n.name, name),
            )
            .primary(n.span, format!("`{name}` missing here"))
            .help(format!("add `{name}=\"...\"` (see dialects/dialect.xsd)"));
            self.diags.push(d);
        }
        a
    }

    /// Reports an attribute value that cannot be read.
    pub fn bad(&mut self, a: &Attr, what: &str, help: impl Into<String>) {
        let d = Diagnostic::new(Code::SpecBadValue, format!("`{}` is not {what}", a.value))
            .primary(a.value_span, format!("expected {what}"))
            .help(help);
        self.diags.push(d);
    }

    pub fn parse<T>(
        &mut self,
        a: &Attr,
        what: &str,
        help: &str,
        f: impl FnOnce(&str) -> Option<T>,
    ) -> Option<T> {
        let v = f(a.value.trim());
        if v.is_none() {
            self.bad(a, what, help);
        }
        v
    }

    pub fn bool_attr(&mut self, n: &Node, name: &str, default: bool) -> bool {
        match n.attr(name) {
            Some(a) => self
                .parse(
                    a,
                    "`true` or `false`",
                    "write `true` or `false`",
                    parse_bool,
                )
                .unwrap_or(default),
            None => default,
        }
    }

    pub fn u32_attr(&mut self, a: &Attr) -> Option<u32> {
        self.parse(a, "a whole number", "write digits only, as in `33`", |s| {
            s.parse().ok()
        })
    }

    pub fn letter_attr(&mut self, a: &Attr) -> Option<char> {
        self.parse(
            a,
            "a single letter",
            "write one letter, as in `X`",
            parse_letter,
        )
    }

    pub fn doc(&self, n: &Node) -> String {
        let doc = n
            .attr("doc")
            .map(|a| a.value.trim().to_string())
            .unwrap_or_default();
        match n.attr("confidence").map(|a| a.value.as_str()) {
            Some("?") => format!("[?] {doc}"),
            _ => doc,
        }
    }
}

pub fn parse_bool(s: &str) -> Option<bool> {
    match s {
        "true" | "1" => Some(true),
        "false" | "0" => Some(false),
        _ => None,
    }
}

pub fn parse_letter(s: &str) -> Option<char> {
    let mut cs = s.chars();
    match (cs.next(), cs.next()) {
        (Some(c), None) if c.is_ascii_alphabetic() || c == '@' || c == '^' => {
            Some(c.to_ascii_uppercase())
        }
        _ => None,
    }
}

/// `P|X Q` to `[[P, X], [Q]]`.
pub fn parse_requires(s: &str) -> Option<Vec<Vec<char>>> {
    s.split_whitespace()
        .map(|alt| {
            alt.split('|')
                .map(parse_letter)
                .collect::<Option<Vec<char>>>()
        })
        .collect()
}

/// `XYZRQF` to its letters.
pub fn parse_uses(s: &str) -> Option<Vec<char>> {
    s.chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| parse_letter(&c.to_string()))
        .collect()
}

/// `P:ms X:s` to dwell units per word.
pub fn parse_dwell(s: &str) -> Option<Vec<(char, DwellUnit)>> {
    s.split_whitespace()
        .map(|item| {
            let (l, u) = item.split_once(':')?;
            let unit = match u {
                "ms" => DwellUnit::Milliseconds,
                "s" => DwellUnit::Seconds,
                "rev" => DwellUnit::Revolutions,
                _ => return None,
            };
            Some((parse_letter(l)?, unit))
        })
        .collect()
}

pub const FUNCS: &[(&str, Func)] = &[
    ("sin", Func::Sin),
    ("cos", Func::Cos),
    ("tan", Func::Tan),
    ("asin", Func::Asin),
    ("acos", Func::Acos),
    ("atan", Func::Atan),
    ("atan2", Func::Atan2),
    ("sqrt", Func::Sqrt),
    ("abs", Func::Abs),
    ("round", Func::Round),
    ("floor", Func::Floor),
    ("ceil", Func::Ceil),
    ("trunc", Func::Trunc),
    ("round-away", Func::RoundAway),
    ("ln", Func::Ln),
    ("exp", Func::Exp),
    ("pow", Func::Pow),
    ("square", Func::Square),
    ("bin", Func::Bin),
    ("bcd", Func::Bcd),
    ("min", Func::Min),
    ("max", Func::Max),
    ("position-shortest", Func::PosShortest),
    ("position-plus", Func::PosPlus),
    ("position-minus", Func::PosMinus),
    ("sign", Func::Sign),
    ("log10", Func::Log10),
];

/// Cycle kinds a `<cycle kind=...>` may name.
pub const CYCLE_KINDS: &[&str] = &[
    "drill",
    "drill-dwell",
    "peck",
    "chip-break",
    "tap",
    "tap-left",
    "tap-float",
    "bore-feed-out",
    "bore-stop-rapid-out",
    "back-bore",
    "bore-manual",
    "bore-dwell-feed-out",
    "fine-bore",
    "pattern-row",
    "pattern-circle",
    "pattern-arc",
    "pattern-grid",
    "pocket-rect",
    "pocket-circ",
    "pocket-contour",
    "slot-radial",
    "slot-circle",
    "slot-long",
    "slot-open",
    "spigot-rect",
    "spigot-circ",
    "face",
    "contour",
    "thread-mill",
    "tolerance",
    "swivel",
    "datum-preset",
    "datum-shift",
    "blank",
    "structure",
    "other",
];

/// Address roles an `<address role=...>` may name.
pub const ADDRESS_ROLES: &[&str] = &[
    "axis",
    "rotary-axis",
    "arc-centre",
    "arc-radius",
    "feed",
    "spindle-speed",
    "tool",
    "length-offset",
    "radius-offset",
    "cutting-edge",
    "sequence",
    "program",
    "parameter",
    "repeat",
    "code",
    "polar",
    "aux",
];

fn parse_param_type(s: &str) -> Option<ParamType> {
    match s {
        "real" => Some(ParamType::Real),
        "int" => Some(ParamType::Int),
        "string" => Some(ParamType::String),
        "any" => Some(ParamType::Any),
        _ => None,
    }
}

fn parse_class(s: &str) -> Option<VarClass> {
    match s {
        "local" => Some(VarClass::Local),
        "common" => Some(VarClass::Common),
        "retained" => Some(VarClass::Retained),
        "system" => Some(VarClass::System),
        _ => None,
    }
}

/// `<group name= exclusive= together= doc=/>`.
pub fn read_group(cx: &mut Ctx, n: &Node) -> Option<GroupDef> {
    cx.check_attrs(n, &["name", "exclusive", "together", "doc", "confidence"]);
    let name = cx.req(n, "name")?.value.trim().to_string();
    let exclusive = cx.bool_attr(n, "exclusive", true);
    let together = match n.attr("together") {
        Some(a) => cx.parse(
            a,
            "meanings separated by spaces",
            "meanings are listed in dialects/dialect.xsd (e.g. `coolant.mist coolant.flood`)",
            |s| {
                s.split_whitespace()
                    .map(Meaning::parse)
                    .collect::<Option<Vec<_>>>()
            },
        )?,
        None => Vec::new(),
    };
    Some(GroupDef {
        name,
        exclusive,
        together,
        doc: cx.doc(n),
    })
}

/// `<address letter= role= length= doc=/>`.
pub fn read_address(cx: &mut Ctx, n: &Node) -> Option<AddressDef> {
    cx.check_attrs(n, &["letter", "role", "length", "doc", "confidence"]);
    let letter = cx.req(n, "letter").and_then(|a| cx.letter_attr(a));
    let role = cx.req(n, "role").and_then(|a| {
        let help = format!("roles: {}", ADDRESS_ROLES.join(", "));
        cx.parse(a, "an address role", &help, |s| {
            ADDRESS_ROLES.contains(&s).then(|| s.to_string())
        })
    });
    let length = cx.bool_attr(n, "length", false);
    Some(AddressDef {
        letter: letter?,
        role: role?,
        length,
    })
}

/// The attributes of `<code>` and `<code-range>` shared by both.
pub struct CodeCommon {
    pub group: String,
    pub meaning: Meaning,
    pub requires: Vec<Vec<char>>,
    pub uses: Vec<char>,
    pub dwell_units: Vec<(char, DwellUnit)>,
    pub preferred: bool,
    pub run: crate::dialect::spec::AuxRun,
    pub shift: Option<crate::dialect::spec::ShiftDir>,
    pub first_index: Option<u32>,
    pub doc: String,
}

pub const CODE_ATTRS: &[&str] = &[
    "letter",
    "number",
    "group",
    "meaning",
    "requires",
    "uses",
    "dwell",
    "preferred",
    "run",
    "shift",
    "first-index",
    "doc",
    "confidence",
];

pub fn read_code_common(cx: &mut Ctx, n: &Node, groups: &[GroupDef]) -> Option<CodeCommon> {
    let group = cx.req(n, "group").and_then(|a| {
        let known: Vec<&str> = groups.iter().map(|g| g.name.as_str()).collect();
        let help = format!(
            "declare it with `<group name=\"{}\"/>`, or use one of: {}",
            a.value,
            known.join(", ")
        );
        cx.parse(a, "a declared modal group", &help, |s| {
            known.contains(&s).then(|| s.to_string())
        })
    });
    let meaning = cx.req(n, "meaning").and_then(|a| {
        cx.parse(a, "a meaning", "meanings are listed in dialects/dialect.xsd (e.g. `motion.rapid`, `work-offset.1`, `aux`)", Meaning::parse)
    });
    let help = "letters, alternatives joined by `|`, groups separated by spaces: `P|X`";
    let requires = match n.attr("requires") {
        Some(a) => cx.parse(a, "a list of required words", help, parse_requires),
        None => Some(Vec::new()),
    };
    let uses = match n.attr("uses") {
        Some(a) => cx.parse(
            a,
            "a list of word letters",
            "letters only, as in `XYZRQF`",
            parse_uses,
        ),
        None => Some(Vec::new()),
    };
    let dwell_units = match n.attr("dwell") {
        Some(a) => cx.parse(
            a,
            "a list of dwell units",
            "`LETTER:UNIT` with unit ms, s or rev, as in `P:ms X:s`",
            parse_dwell,
        ),
        None => Some(Vec::new()),
    };
    let preferred = cx.bool_attr(n, "preferred", false);
    let run = match n.attr("run") {
        Some(a) => cx.parse(
            a,
            "`stop`, `pass`, `kinematics`, `machine-datum` or `user-program`",
            "`run` says what the canonical run does with an aux code",
            |s| {
                use crate::dialect::spec::AuxRun;
                match s {
                    "stop" => Some(AuxRun::Stop),
                    "pass" => Some(AuxRun::Pass),
                    "kinematics" => Some(AuxRun::Kinematics),
                    "machine-datum" => Some(AuxRun::MachineDatum),
                    "user-program" => Some(AuxRun::UserProgram),
                    _ => None,
                }
            },
        ),
        None => Some(Default::default()),
    };
    let shift = match n.attr("shift") {
        Some(a) => cx
            .parse(
                a,
                "a shift direction",
                "`+X`, `-X`, `+Y` or `-Y` (as in G17)",
                crate::dialect::spec::ShiftDir::parse,
            )
            .map(Some),
        None => Some(None),
    };
    let first_index = match n.attr("first-index") {
        Some(a) => cx
            .parse(
                a,
                "a work offset number",
                "`first-index` of `work-offset.extended` is the work offset P1 selects, as in `7`",
                |s| s.parse::<u32>().ok().filter(|n| *n > 0),
            )
            .map(Some),
        None => Some(None),
    };
    Some(CodeCommon {
        first_index: first_index?,
        group: group?,
        meaning: meaning?,
        requires: requires?,
        uses: uses?,
        dwell_units: dwell_units?,
        preferred,
        run: run?,
        shift: shift?,
        doc: cx.doc(n),
    })
}

pub fn code_letter(cx: &mut Ctx, n: &Node) -> Option<char> {
    let a = cx.req(n, "letter")?;
    cx.parse(a, "`G` or `M`", "codes are G or M codes", |s| match s {
        "G" | "g" => Some('G'),
        "M" | "m" => Some('M'),
        _ => None,
    })
}

pub fn code_number(cx: &mut Ctx, a: &Attr) -> Option<Decimal> {
    cx.parse(
        a,
        "a code number",
        "write the number as in `0`, `54.1`",
        |s| Decimal::parse(s).ok().filter(|d| !d.is_negative()),
    )
}

/// `<code letter= number= group= meaning= .../>`.
pub fn read_code(cx: &mut Ctx, n: &Node, groups: &[GroupDef]) -> Option<CodeDef> {
    cx.check_attrs(n, CODE_ATTRS);
    let letter = code_letter(cx, n);
    let code = cx.req(n, "number").and_then(|a| code_number(cx, a));
    let c = read_code_common(cx, n, groups)?;
    Some(CodeDef {
        letter: letter?,
        code: code?,
        group: c.group,
        meaning: c.meaning,
        requires: c.requires,
        uses: c.uses,
        dwell_units: c.dwell_units,
        preferred: c.preferred,
        run: c.run,
        shift: c.shift,
        first_index: c.first_index,
        doc: c.doc,
        span: n.span,
    })
}

/// `<code-range letter= first= last= .../>`: one code per whole number;
/// a `work-offset.N` meaning counts up from N.
pub fn read_code_range(cx: &mut Ctx, n: &Node, groups: &[GroupDef]) -> Vec<CodeDef> {
    let mut allowed: Vec<&str> = CODE_ATTRS
        .iter()
        .copied()
        .filter(|a| *a != "number")
        .collect();
    allowed.extend(["first", "last"]);
    cx.check_attrs(n, &allowed);
    let letter = code_letter(cx, n);
    let first = cx.req(n, "first").and_then(|a| cx.u32_attr(a));
    let last_attr = cx.req(n, "last");
    let last = last_attr.and_then(|a| cx.u32_attr(a));
    let common = read_code_common(cx, n, groups);
    let (Some(letter), Some(first), Some(last), Some(c), Some(la)) =
        (letter, first, last, common, last_attr)
    else {
        return Vec::new();
    };
    if last < first || last - first >= MAX_RANGE {
        cx.bad(
            la,
            &format!("a last code from {first} to {}", first + MAX_RANGE - 1),
            "a range runs upwards and holds at most 1000 codes",
        );
        return Vec::new();
    }
    (first..=last)
        .map(|i| CodeDef {
            letter,
            code: Decimal::from_int(i as i64),
            group: c.group.clone(),
            meaning: match c.meaning {
                Meaning::WorkOffset(base) => Meaning::WorkOffset(base + (i - first)),
                m => m,
            },
            requires: c.requires.clone(),
            uses: c.uses.clone(),
            dwell_units: c.dwell_units.clone(),
            preferred: c.preferred,
            run: c.run,
            shift: c.shift,
            first_index: c.first_index,
            doc: c.doc.clone(),
            span: n.span,
        })
        .collect()
}

/// `<cycle name= kind= doc=>` with `<param name= type= doc=/>` children.
pub fn read_cycle(cx: &mut Ctx, n: &Node) -> Option<CycleSig> {
    cx.check_attrs(n, &["name", "kind", "doc", "confidence"]);
    let name = cx
        .req(n, "name")
        .map(|a| a.value.trim().to_ascii_uppercase());
    let kind = cx.req(n, "kind").and_then(|a| {
        let help = format!("kinds: {}", CYCLE_KINDS.join(", "));
        cx.parse(a, "a cycle kind", &help, |s| {
            CYCLE_KINDS.contains(&s).then(|| s.to_string())
        })
    });
    let mut params: Vec<ParamSig> = Vec::new();
    for p in &n.children {
        if p.name != "param" {
            unknown_element(cx, p, "<cycle>", &["param"]);
            continue;
        }
        if let Some(sig) = read_param(cx, p) {
            if params
                .iter()
                .any(|q| q.name.eq_ignore_ascii_case(&sig.name))
            {
                cx.diags.push(
                    Diagnostic::new(
                        Code::SpecDuplicate,
                        format!("parameter `{}` is listed twice", sig.name),
                    )
                    .primary(p.span, "second definition")
                    .help("each parameter name appears once in a cycle signature"),
                );
            }
            params.push(sig);
        }
    }
    Some(CycleSig {
        name: name?,
        kind: kind?,
        params,
        doc: cx.doc(n),
        span: n.span,
    })
}

fn read_param(cx: &mut Ctx, n: &Node) -> Option<ParamSig> {
    cx.check_attrs(n, &["name", "type", "doc", "confidence"]);
    let name = cx.req(n, "name").map(|a| a.value.trim().to_string());
    let ty = cx.req(n, "type").and_then(|a| {
        cx.parse(
            a,
            "a parameter type",
            "types: real, int, string, any",
            parse_param_type,
        )
    });
    Some(ParamSig {
        name: name?,
        ty: ty?,
        doc: cx.doc(n),
    })
}

/// `<function name= func= arity= doc=/>`.
pub fn read_function(cx: &mut Ctx, n: &Node) -> Option<FunctionDef> {
    cx.check_attrs(n, &["name", "func", "arity", "doc", "confidence"]);
    let name = cx
        .req(n, "name")
        .map(|a| a.value.trim().to_ascii_uppercase());
    let func = cx.req(n, "func").and_then(|a| {
        let names: Vec<&str> = FUNCS.iter().map(|(n, _)| *n).collect();
        let help = format!("functions: {}", names.join(", "));
        cx.parse(a, "a function meaning", &help, |s| {
            FUNCS.iter().find(|(n, _)| *n == s).map(|(_, f)| *f)
        })
    });
    let arity = cx.req(n, "arity").and_then(|a| {
        cx.parse(a, "an argument count from 0 to 9", "write 1 or 2", |s| {
            s.parse::<usize>().ok().filter(|n| *n < 10)
        })
    });
    Some(FunctionDef {
        name: name?,
        func: func?,
        arity: arity?,
    })
}

/// `<variables prefix= first= last= class= writable= doc=/>`.
pub fn read_variables(cx: &mut Ctx, n: &Node) -> Option<VarRange> {
    cx.check_attrs(
        n,
        &[
            "prefix",
            "first",
            "last",
            "class",
            "writable",
            "doc",
            "confidence",
        ],
    );
    let prefix = cx.req(n, "prefix").and_then(|a| {
        cx.parse(
            a,
            "`#` or `R`",
            "numbered variables are `#n` or `Rn`",
            |s| match s {
                "#" => Some('#'),
                "R" => Some('R'),
                _ => None,
            },
        )
    });
    let first = cx.req(n, "first").and_then(|a| cx.u32_attr(a));
    let last_attr = cx.req(n, "last");
    let last = last_attr.and_then(|a| cx.u32_attr(a));
    let class = cx.req(n, "class").and_then(|a| {
        cx.parse(
            a,
            "a variable class",
            "classes: local, common, retained, system",
            parse_class,
        )
    });
    let writable = cx.bool_attr(n, "writable", true);
    let (first, last, la) = (first?, last?, last_attr?);
    if last < first {
        cx.bad(
            la,
            &format!("a last number not below {first}"),
            "a range runs upwards",
        );
        return None;
    }
    Some(VarRange {
        prefix: prefix?,
        first,
        last,
        class: class?,
        writable,
    })
}

/// Reports an element the schema does not allow here.
pub fn unknown_element(cx: &mut Ctx, n: &Node, parent: &str, allowed: &[&str]) {
    cx.diags.push(
        Diagnostic::new(
            Code::SpecUnknownItem,
            format!("`<{}>` is not an element of {parent}", n.name),
        )
        .primary(n.span, "unknown element")
        .help(format!("{parent} contains: {}", allowed.join(", "))),
    );
}
