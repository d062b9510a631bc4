#!/usr/bin/env python3
"""Write the hostile inputs of issue 14 into a folder (for benches/hostile.sh).

    python3 benches/hostile_inputs.py DIR

Each input is deterministic. Sizes are those of the issue: a 50 MB single
line, a 1 MB line of repeated words, 100k nested IF/WHILE (Siemens and
LinuxCNC o-words), a helix of 10^8 turns, a 10M-entity Part 21 file, a
dialect spec with 80k codes, a 50,000-term sum, ABS[ nested 20,000 deep;
and, for scale, large CAM programs of the shared generator.
"""

import os
import subprocess
import sys


def write(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w", encoding="ascii") as f:
        f.write(text)


def line_50mb(folder):
    # About 50 MB of words on one block.
    write(folder, "line50mb.nc", "%\nO1\nG1 " + "X1 Y2 " * (8 << 20) + "\nM30\n%\n")


def words_1mb(folder):
    # Every word repeats the last one: a diagnostic per word (just under
    # the 1 MiB line limit, so the line is read).
    write(folder, "words1mb.nc", "%\nO1\nG0 " + "X1 " * 340_000 + "\nM30\n%\n")


def nested(folder, depth=100_000):
    lines = ["R1=1"]
    lines += ["IF R1==1" if k % 2 == 0 else "WHILE R1==1" for k in range(depth)]
    lines += ["G1 X1 F100", "R1=0"]
    lines += ["ENDIF" if k % 2 == 0 else "ENDWHILE" for k in reversed(range(depth))]
    lines.append("M30")
    write(folder, "nest100k.mpf", "\n".join(lines) + "\n")
    lines = ["#1=1"]
    lines += [
        f"o{k + 1} if [#1 EQ 1]" if k % 2 == 0 else f"o{k + 1} while [#1 EQ 1]"
        for k in range(depth)
    ]
    lines += ["G1 X1 F100", "#1=0"]
    lines += [
        f"o{k + 1} endif" if k % 2 == 0 else f"o{k + 1} endwhile"
        for k in reversed(range(depth))
    ]
    lines.append("M2")
    write(folder, "nest100k.ngc", "\n".join(lines) + "\n")


def helix(folder):
    write(
        folder,
        "helix.ngc",
        "G21 G90 G17 F100\nG0 X0 Y0 Z0\nG1 X5\n"
        "G2 X5 Y0 I-5 J0 Z-100 P100000000\n"
        "G18 G3 X5 Z-100 I-5 K0 Y-50 P10000000\n"
        "G19 G2 Y-50 Z-100 J5 K0 X9 P10000000\nM2\n",
    )


def part21(folder, entities=10_000_000, points=2_200_000):
    # A valid project (two tapped holes) followed by filler: 10M of the
    # shortest entity (unknown to the schema, about 130 MB), 2.2M unused
    # CARTESIAN_POINTs (valid, about 100 MB), and long parameter lists.
    filler(folder, "part21_10m.stp", entities, lambda n: f"#{n}=A();")
    filler(
        folder,
        "part21_points.stp",
        points,
        lambda n: f"#{n}=CARTESIAN_POINT('',({n}.,0.,0.));",
    )
    # 100 MB of unset parameters: 48 bytes in memory for 2 of text.
    filler(folder, "part21_params.stp", 5_000, lambda n: f"#{n}=A(" + "$," * 10_000 + "$);")


def filler(folder, name, count, entity):
    here = os.path.dirname(os.path.abspath(__file__))
    base = os.path.join(here, "..", "tests", "programs", "stepnc", "tapped_holes.stp")
    with open(base, encoding="ascii") as f:
        text = f.read()
    head, tail = text.split("ENDSEC;\nEND-ISO-10303-21;")
    with open(os.path.join(folder, name), "w", encoding="ascii") as f:
        f.write(head)
        first = 1000
        chunk = []
        for n in range(first, first + count):
            chunk.append(entity(n))
            if len(chunk) == 10000:
                f.write("".join(chunk) + "\n")
                chunk = []
        f.write("".join(chunk) + "\nENDSEC;\nEND-ISO-10303-21;" + tail)


def dialect_80k(folder, codes=80_000):
    rows = [
        f'  <code letter="G" number="{1000 + k}" group="non-modal" meaning="aux" '
        f'uses="XYZ" doc="builder code {k}"/>'
        for k in range(codes)
    ]
    write(
        folder,
        "dialect80k.xml",
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<dialect id="big-fanuc" name="80k codes" family="word-address" extends="fanuc">\n'
        + "\n".join(rows)
        + "\n</dialect>\n",
    )
    write(folder, "small.nc", "%\nO1\nG0 X1 Y1\nG1001 X2\nM30\n%\n")


def expressions(folder):
    write(folder, "sum50k.nc", "%\nO1\n#1=1" + "+1" * 50_000 + "\nG0 X#1\nM30\n%\n")
    abs_ = "ABS[" * 20_000 + "1" + "]" * 20_000
    write(folder, "abs20k.nc", f"%\nO1\n#1={abs_}\nG0 X#1\nM30\n%\n")


def cam(folder):
    # Not hostile: large CAM programs (../shared/bench/gen_program.py), of
    # 48 MB for the streaming commands (the port streams too) and 24 MB for
    # `port --verify`, which holds both runs' events.
    here = os.path.dirname(os.path.abspath(__file__))
    gen = os.path.join(here, "..", "..", "shared", "bench", "gen_program.py")
    if not os.path.exists(gen):
        print(f"no {gen}: the CAM program cases are skipped", file=sys.stderr)
        return
    for lines, name in ((3_500_000, "cam48mb.ngc"), (1_750_000, "cam24mb.ngc")):
        out = os.path.join(folder, name)
        subprocess.run([sys.executable, gen, "--lines", str(lines), "-o", out],
                       check=True, stdout=subprocess.DEVNULL)
    # The 48 MB program with a loop near its top: control flow sends the
    # whole program to the walker (its plain moves held as text), not the
    # stream.
    with open(os.path.join(folder, "cam48mb.ngc")) as src, \
            open(os.path.join(folder, "flow48mb.ngc"), "w") as out:
        for i, line in enumerate(src):
            if i == 4:
                out.write("#1=0\no100 while [#1 LT 2]\n#1=[#1+1]\no100 endwhile\n")
            out.write(line)


def main():
    folder = sys.argv[1]
    os.makedirs(folder, exist_ok=True)
    for make in (line_50mb, words_1mb, nested, helix, part21, dialect_80k, expressions, cam):
        make(folder)


if __name__ == "__main__":
    main()
