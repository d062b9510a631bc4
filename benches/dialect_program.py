#!/usr/bin/env python3
"""Write the generated CAM program (../shared/bench/gen_program.py) in one dialect.

    python3 benches/dialect_program.py DIALECT LINES OUT [GEN_PROGRAM.py]

DIALECT is linuxcnc, fanuc, haas, siemens840d or heidenhain. The moves are
the same in every dialect: the generator's RS274/NGC lines are translated
one by one (the generator is modal and simple: G0/G1/G2/G3 with X Y Z I J F,
tool changes, a G83 peck cycle over eight holes, G28 home, M codes):

- linuxcnc: as generated;
- fanuc, haas: every length gets a decimal point (a bare `X17` is 17 least
  input increments there), `G64 P0.01` becomes `G64`;
- siemens840d: `;` comments, G71, `T1 D1 M6`, `G74 Z1=0` for the G28 home,
  `MCALL CYCLE83(...)` over the holes, no `%`/O line;
- heidenhain: numbered Klartext blocks, `L ... FMAX`, `CC` + `C ... DR+/-`
  arcs (absolute centre from the tracked position), `TOOL CALL`,
  `CYCL DEF 200 DRILLING` with `M99` per hole, `L Z+0 R0 FMAX M91` home.

The translation keeps the line count within a few percent of LINES.
"""

import importlib.util
import os
import sys


def load_gen(path):
    spec = importlib.util.spec_from_file_location("gen_program", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def words(line):
    """(letter, text) pairs of a simple word-address line."""
    out = []
    for w in line.split():
        out.append((w[0], w[1:]))
    return out


def dec(v):
    """A length with a decimal point: 17 -> 17., 1.5 -> 1.5."""
    return v if "." in v else v + "."


class Iso:
    """fanuc / haas: decimal points on lengths."""

    LENGTHS = set("XYZIJKRQ")

    def __init__(self, out):
        self.out = out

    def line(self, s):
        if s.startswith("G64 P"):
            s = "G64"
        elif s[0] not in "(%O":
            s = " ".join(l + (dec(v) if l in self.LENGTHS else v) for l, v in words(s))
        self.out.write(s + "\n")


class Modal:
    """Tracks the generator's modal state (motion, position) for translators."""

    def __init__(self, out):
        self.out = out
        self.motion = "G0"
        self.pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
        self.absolute = True


class Siemens(Modal):
    def __init__(self, out):
        super().__init__(out)
        self.in_cycle = False
        self.tool = 0

    def line(self, s):
        w = self.out.write
        if s == "%":
            return
        if s[0] == "O":
            w("; " + s[s.index("(") + 1:-1] + "\n")
            return
        if s[0] == "(":
            w("; " + s[1:-1] + "\n")
            return
        if s.startswith("G21 "):
            w("G71 G17 G40 G90 G94\n")
            return
        if s.startswith("G64"):
            w("G64\n")
            return
        if s == "G91 G28 Z0":
            w("G74 Z1=0\n")
            return
        if s.startswith("G54 G43 H"):
            w("G54 D1\n")
            return
        if s[0] == "T":
            self.tool = s[1:].split()[0]
            w(f"T{self.tool} D1 M6\n")
            return
        if s.startswith("G98 G83"):
            d = dict(words(s)[2:])
            # RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM, DTB, DTS, FRF, VARI
            w(f"MCALL CYCLE83(5,0,2,{d['Z']},,,{d['Q']},,0,0,1,1)\n")
            w(f"X{d['X']} Y{d['Y']}\n")
            self.in_cycle = True
            return
        if s == "G80":
            w("MCALL\n")
            self.in_cycle = False
            return
        w(s + "\n")


class Heidenhain(Modal):
    def __init__(self, out):
        super().__init__(out)
        self.n = 0
        self.feed = None
        self.tool = None
        self.rpm = None
        self.cycle = None

    def put(self, s):
        self.out.write(f"{self.n} {s}\n")
        self.n += 1

    @staticmethod
    def num(v):
        return v if v.startswith("-") else "+" + v

    def line(self, s):
        if s == "%":
            if self.n == 0:
                self.put("BEGIN PGM CAM MM")
                self.put("BLK FORM 0.1 Z X+0 Y+0 Z-30")
                self.put("BLK FORM 0.2 X+200 Y+150 Z+0")
            else:
                self.put("END PGM CAM MM")
            return
        if s[0] == "O":
            self.put("; " + s[s.index("(") + 1:-1])
            return
        if s[0] == "(":
            self.put("; " + s[1:-1])
            return
        if s.startswith(("G21", "G64", "G90", "M8")) or s.startswith("G54"):
            if s == "M8":
                self.put("L M8")
            return
        if s == "M5 M9":
            self.put("L M5")
            self.put("L M9")
            return
        if s == "G91 G28 Z0":
            self.put("L Z+0 R0 FMAX M91")
            return
        if s[0] == "T":
            self.tool = s[1:].split()[0]
            return
        if s[0] == "S":
            self.rpm = s[1:].split()[0]
            self.put(f"TOOL CALL {self.tool} Z S{self.rpm}")
            self.put("L M3")
            return
        if s.startswith("G98 G83"):
            d = dict(words(s)[2:])
            z, q = d["Z"].rstrip("."), d["Q"].rstrip(".")
            self.put(f"CYCL DEF 200 DRILLING Q200=+2 Q201={self.num(z)} Q206=+150 "
                     f"Q202=+{q} Q210=+0 Q203=+0 Q204=+3 Q211=+0")
            self.cycle = True
            self.hole(d)
            return
        if s == "G80":
            self.cycle = None
            return
        if s == "M30":
            self.put("L M30")
            return
        if self.cycle:
            self.hole(dict(words(s)))
            return
        self.move(words(s))

    def hole(self, d):
        self.pos["X"], self.pos["Y"] = float(d["X"]), float(d["Y"])
        self.put(f"L X{self.num(d['X'])} Y{self.num(d['Y'])} FMAX M99")

    def move(self, ws):
        d = {}
        for l, v in ws:
            if l == "G":
                self.motion = "G" + v
            else:
                d[l] = v
        feed = ""
        if "F" in d:
            self.feed = d.pop("F")
        coords = " ".join(f"{l}{self.num(d[l])}" for l in "XYZ" if l in d)
        if self.motion in ("G2", "G3"):
            cx = self.pos["X"] + float(d.get("I", "0"))
            cy = self.pos["Y"] + float(d.get("J", "0"))
            self.put(f"CC X{self.num(fmt(cx))} Y{self.num(fmt(cy))}")
            dr = "DR-" if self.motion == "G2" else "DR+"
            self.put(f"C {coords} {dr}")
        elif self.motion == "G0":
            self.put(f"L {coords} R0 FMAX")
        else:
            if self.feed is not None:
                feed = f" F{self.feed}"
            self.put(f"L {coords}{feed}")
        for l in "XYZ":
            if l in d:
                self.pos[l] = float(d[l])


def fmt(v):
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


class Sink:
    """The generator writes text here; whole lines go to the translator."""

    def __init__(self, tr):
        self.tr = tr
        self.buf = ""

    def write(self, text):
        self.buf += text
        if "\n" in self.buf:
            *lines, self.buf = self.buf.split("\n")
            for l in lines:
                self.tr.line(l)


def main():
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    dialect, lines, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    here = os.path.dirname(os.path.abspath(__file__))
    gen = sys.argv[4] if len(sys.argv) > 4 else os.path.join(
        here, "..", "..", "shared", "bench", "gen_program.py")
    g = load_gen(gen)
    kinds = {"fanuc": Iso, "haas": Iso, "siemens840d": Siemens, "heidenhain": Heidenhain}
    with open(out, "w", buffering=1 << 20) as f:
        if dialect == "linuxcnc":
            g.generate(f, lines, False)
            return 0
        if dialect not in kinds:
            print(f"unknown dialect {dialect}", file=sys.stderr)
            return 2
        g.generate(Sink(kinds[dialect](f)), lines, False)
    return 0


if __name__ == "__main__":
    sys.exit(main())
