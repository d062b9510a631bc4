//! From the grammar's [`Node`]s to the line's [`Item`]s: numbered
//! subprogram calls `L123 P3`, tool names `T="NAME"`, spindle positioning
//! `SPOS=90`, words without a value, and named cycle calls checked against
//! their signature in the spec.

use super::builder::Node;
use crate::diag::{Code, Diagnostic};
use crate::dialect::spec::ParamType;
use crate::dialect::DialectSpec;
use crate::ir::{
    Arena, Arg, CallArgs, CallKind, CallTarget, CycleCall, Expr, ExprKind, SpindleState, Stmt,
    StmtKind, ToolRef, Value,
};
use crate::span::Span;
use crate::syntax::{Item, WordSyntax};

pub struct Finish<'a> {
    pub spec: &'a DialectSpec,
    pub exprs: &'a Arena<Expr>,
    pub diags: &'a mut Vec<Diagnostic>,
}

impl Finish<'_> {
    pub fn items(&mut self, nodes: Vec<Node>) -> Vec<Item> {
        let mut out: Vec<Item> = Vec::new();
        for n in nodes {
            if let Some(item) = self.node(n) {
                out.push(item);
            }
        }
        take_call_repeat(&mut out);
        out
    }

    fn node(&mut self, n: Node) -> Option<Item> {
        match n {
            Node::Word {
                addr,
                addr_span,
                value,
                dim,
                extended,
                span,
            } => Some(self.word(addr, addr_span, value, dim, extended, span)),
            Node::Bare { addr, span } => {
                let d = Diagnostic::new(
                    Code::WordWithoutValue,
                    format!("the address `{addr}` has no value"),
                )
                .primary(span, "no value after this address")
                .help(format!(
                    "write a value after it, as in `{addr}10` or `{addr}=R1`"
                ));
                self.diags.push(d);
                None
            }
            Node::WordCall {
                addr,
                number,
                args,
                span,
            } => self.word_call(addr, number, args, span),
            Node::Stmt(s) => {
                if let StmtKind::CycleCall(c) = &s.kind {
                    self.check_cycle(c, s.span);
                }
                Some(Item::Stmt(s))
            }
        }
    }

    fn word(
        &mut self,
        addr: String,
        addr_span: Span,
        value: Value,
        dim: Option<crate::ir::DimMode>,
        extended: bool,
        span: Span,
    ) -> Item {
        if let Some(call) = self.l_call(&addr, &value, None, span) {
            return call;
        }
        if addr == "SPOS" && dim.is_none() {
            // `SPOS=90`: the programmable spindle positioning (M19 takes
            // its angle from setting data).
            let kind = StmtKind::Spindle(SpindleState::Orient(Some(value)));
            return Item::Stmt(Stmt::new(kind, span));
        }
        if addr == "T" {
            if let Value::Expr(e) = &value {
                if let ExprKind::Str(name) = &self.exprs[*e].kind {
                    return Item::Stmt(Stmt::new(
                        StmtKind::ToolSelect(ToolRef::Name(name.clone())),
                        span,
                    ));
                }
            }
        }
        let addr = master_spindle(addr, extended);
        Item::Word(WordSyntax {
            address: addr.into(),
            value,
            dim,
            extended,
            span,
            address_span: addr_span,
        })
    }

    /// `L123`: a call of subprogram 123 (not an extended `L=`).
    fn l_call(
        &self,
        addr: &str,
        value: &Value,
        args: Option<Vec<Arg>>,
        span: Span,
    ) -> Option<Item> {
        let n = value
            .number()
            .filter(|d| addr == "L" && !d.point)?
            .as_int()?;
        let n = u32::try_from(n).ok()?;
        let args = match args {
            None => CallArgs::None,
            Some(a) => CallArgs::Positional(a.into_iter().map(|a| a.value).collect()),
        };
        let kind = StmtKind::Call {
            kind: CallKind::Named,
            target: CallTarget::Number(n),
            args,
            repeat: None,
        };
        Some(Item::Stmt(Stmt::new(kind, span)))
    }

    fn word_call(
        &mut self,
        addr: String,
        number: crate::ir::Decimal,
        args: Vec<Arg>,
        span: Span,
    ) -> Option<Item> {
        let call = self.l_call(&addr, &Value::Number(number), Some(args), span);
        if call.is_none() {
            let d = Diagnostic::new(Code::SyntaxError, format!("`{addr}{number}` cannot take arguments"))
                .primary(span, "arguments after a word")
                .help(format!(
                    "only a subprogram call `L<number>(...)` or a named call `NAME(...)` takes arguments in parentheses; \
                     if `{addr}{number}(...)` is a function the machine builder added (an OEM cycle or M function), \
                     describe the machine in a dialect file that extends this one, with \
                     `<command name=\"{addr}{number}\" doc=\"...\"/>`, and give it with `--dialect-file`"
                ));
            self.diags.push(d);
        }
        call
    }

    fn check_cycle(&mut self, c: &CycleCall, span: Span) {
        let Some(sig) = self.spec.cycle(&c.name) else {
            return;
        };
        if c.args.len() > sig.params.len() {
            let extra = &c.args[sig.params.len()];
            let d = Diagnostic::new(
                Code::CycleTooManyArguments,
                format!(
                    "`{}` takes at most {} arguments, this call gives {}",
                    sig.name,
                    sig.params.len(),
                    c.args.len()
                ),
            )
            .primary(extra.span, "first argument beyond the signature")
            .secondary(span, "in this call")
            .help(Code::CycleTooManyArguments.explanation());
            self.diags.push(d);
        }
        for (a, p) in c.args.iter().zip(&sig.params) {
            if let Some(kind) = a
                .value
                .and_then(|e| self.wrong_kind(&self.exprs[e].kind, p.ty))
            {
                let d = Diagnostic::new(
                    Code::CycleArgumentKind,
                    format!(
                        "`{}` of `{}` takes {}, not {kind}",
                        p.name,
                        sig.name,
                        ty_name(p.ty)
                    ),
                )
                .primary(a.span, format!("{kind} given"))
                .help(format!("give `{}` {}", p.name, ty_name(p.ty)));
                self.diags.push(d);
            }
        }
    }

    /// What is wrong with a literal argument for a parameter type.
    fn wrong_kind(&self, e: &ExprKind, ty: ParamType) -> Option<&'static str> {
        match (e, ty) {
            (ExprKind::Str(_), ParamType::Real | ParamType::Int) => Some("a string"),
            (ExprKind::Number(_) | ExprKind::Bool(_), ParamType::String) => Some("a number"),
            (ExprKind::Number(d), ParamType::Int) if !d.is_integer() => Some("a fraction"),
            _ => None,
        }
    }
}

fn ty_name(t: ParamType) -> &'static str {
    match t {
        ParamType::Real => "a number",
        ParamType::Int => "an integer",
        ParamType::String => "a string",
        ParamType::Any => "any value",
    }
}

/// `L123 P3`, `MYSUB P2`: the P word gives the call's number of passes.
fn take_call_repeat(items: &mut Vec<Item>) {
    let has_call = items.iter().any(|i| {
        matches!(
            i,
            Item::Stmt(Stmt {
                kind: StmtKind::Call { .. },
                ..
            })
        )
    });
    let p = items
        .iter()
        .position(|i| matches!(i, Item::Word(w) if w.address == "P"));
    let (true, Some(p)) = (has_call, p) else {
        return;
    };
    let Item::Word(w) = items.remove(p) else {
        return;
    };
    for i in items.iter_mut() {
        if let Item::Stmt(Stmt {
            kind: StmtKind::Call { repeat, .. },
            span,
        }) = i
        {
            *repeat = Some(w.value);
            *span = span.to(w.span);
            return;
        }
    }
}

/// `M1=3`, `S1=1000`: the M function and speed of spindle 1 (an address
/// extension), which is the master spindle (840D machine data 20090
/// SPIND_DEF_MASTER_SPIND, default 1 [?: a machine may set another]):
/// the same as `M3`, `S1000`. Other spindles' words stay as written.
fn master_spindle(addr: String, extended: bool) -> String {
    let spindle_word = addr.starts_with(['M', 'S']);
    match extended && spindle_word && addr[1..] == *MASTER_SPINDLE {
        true => addr[..1].to_string(),
        false => addr,
    }
}

/// The master spindle's number (840D MD 20090 default) [?].
const MASTER_SPINDLE: &str = "1";
