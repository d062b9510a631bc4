#!/usr/bin/env python3
"""An independent ISO 10303-21 reader (standard library only), used by
tests/stepnc_io.rs to check that cncc's normalised STEP-NC output is a
well-formed Part 21 file: header with FILE_DESCRIPTION, FILE_NAME and
FILE_SCHEMA; one `#n=NAME(...);` instance per line; every reference
resolves; reals carry a decimal point; each entity name always has the
same number of parameters.

Usage: part21_check.py FILE [ENTITY=COUNT ...]
Prints `ok N instances` and exits 0, or prints the problems and exits 1.
"""
import re
import sys

TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<comment>/\*.*?\*/)
  | (?P<string>'(?:[^']|'')*')
  | (?P<ref>\#\d+)
  | (?P<enum>\.[A-Z_][A-Z0-9_]*\.)
  | (?P<real>[+-]?\d+\.\d*(?:[eE][+-]?\d+)?)
  | (?P<int>[+-]?\d+)
  | (?P<keyword>!?[A-Z_][A-Z0-9_]*)
  | (?P<punct>[()=,;$*])
""", re.VERBOSE | re.DOTALL)


def tokens(text, problems):
    pos = 0
    out = []
    while pos < len(text):
        if text.startswith("ISO-10303-21;", pos):
            out.append(("begin", "ISO-10303-21"))
            out.append(("punct", ";"))
            pos += len("ISO-10303-21;")
            continue
        if text.startswith("END-ISO-10303-21;", pos):
            out.append(("end", "END-ISO-10303-21"))
            out.append(("punct", ";"))
            pos += len("END-ISO-10303-21;")
            continue
        m = TOKEN.match(text, pos)
        if not m:
            problems.append("unreadable text at offset %d: %r" % (pos, text[pos:pos + 20]))
            return out
        kind = m.lastgroup
        if kind not in ("ws", "comment"):
            out.append((kind, m.group()))
        pos = m.end()
    return out


class Parser:
    def __init__(self, toks):
        self.toks = toks
        self.i = 0

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else ("eof", "")

    def take(self, value=None, kind=None):
        t = self.peek()
        if (value is not None and t[1] != value) or (kind is not None and t[0] != kind):
            raise ValueError("expected %s, found %r" % (value or kind, t[1]))
        self.i += 1
        return t

    def params(self):
        self.take("(")
        out = []
        if self.peek()[1] == ")":
            self.take(")")
            return out
        while True:
            out.append(self.param())
            if self.peek()[1] == ",":
                self.take(",")
                continue
            self.take(")")
            return out

    def param(self):
        kind, value = self.peek()
        if value == "(":
            return ("list", self.params())
        if kind == "keyword":
            self.take()
            inner = self.params()
            if len(inner) != 1:
                raise ValueError("typed parameter %s takes one value" % value)
            return ("typed", (value, inner[0]))
        if kind in ("string", "ref", "enum", "real", "int") or value in ("$", "*"):
            self.take()
            return (kind if kind != "punct" else value, value)
        raise ValueError("unexpected %r" % value)


def refs(p, out):
    kind, v = p
    if kind == "ref":
        out.append(int(v[1:]))
    elif kind == "list":
        for q in v:
            refs(q, out)
    elif kind == "typed":
        refs(v[1], out)


def check(path, expected_counts):
    problems = []
    text = open(path, encoding="ascii").read()
    for n, line in enumerate(text.splitlines(), 1):
        if line.startswith("#") and not re.match(r"^#\d+=[A-Z_][A-Z0-9_]*\(.*\);$", line):
            problems.append("line %d is not one instance: %s" % (n, line[:60]))
    toks = tokens(text, problems)
    p = Parser(toks)
    instances = {}
    header = []
    try:
        p.take(kind="begin"); p.take(";")
        p.take("HEADER"); p.take(";")
        while p.peek()[1] != "ENDSEC":
            name = p.take(kind="keyword")[1]
            header.append((name, p.params()))
            p.take(";")
        p.take("ENDSEC"); p.take(";")
        p.take("DATA"); p.take(";")
        while p.peek()[1] != "ENDSEC":
            n = int(p.take(kind="ref")[1][1:])
            p.take("=")
            name = p.take(kind="keyword")[1]
            params = p.params()
            p.take(";")
            if n in instances:
                problems.append("#%d defined twice" % n)
            instances[n] = (name, params)
        p.take("ENDSEC"); p.take(";")
        p.take(kind="end"); p.take(";")
    except ValueError as e:
        problems.append("syntax: %s (token %d)" % (e, p.i))
    names = [h[0] for h in header]
    if names != ["FILE_DESCRIPTION", "FILE_NAME", "FILE_SCHEMA"]:
        problems.append("header entities are %s" % names)
    counts = {}
    for n, (name, params) in sorted(instances.items()):
        out = []
        for q in params:
            refs(q, out)
        for r in out:
            if r not in instances:
                problems.append("#%d refers to missing #%d" % (n, r))
        c = counts.setdefault(name, len(params))
        if c != len(params):
            problems.append("%s has %d and %d parameters" % (name, c, len(params)))
    for spec in expected_counts:
        name, want = spec.split("=")
        if name in counts and counts[name] != int(want):
            problems.append("%s has %d parameters, expected %s" % (name, counts[name], want))
    if problems:
        for pr in problems[:50]:
            print(pr)
        return 1
    print("ok %d instances" % len(instances))
    return 0


if __name__ == "__main__":
    sys.exit(check(sys.argv[1], sys.argv[2:]))
