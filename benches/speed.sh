#!/usr/bin/env bash
# Speed and memory benchmark (issue 17): not a test, figures are printed.
#
#   bash benches/speed.sh [CNCC]
#
# Environment (all optional):
#   LINES=2000000      lines of the generated program for the speed figures
#   MEM_LINES=5000000  lines of the second program for the memory figures
#   ROUNDS=3           runs of each timed command (the least CPU time counts)
#   SECTIONS="check canon memory"   which parts to run; "simulate" (not run
#                      by default, minutes): issue 19's material benchmark,
#                      the LinuxCNC program at LINES lines cut on a 0.1 mm
#                      grid over a 200 x 200 mm stock, one run (--stock and
#                      --resolution given: simulate runs the program once)
#   MEM_LIMIT_MB=4096  address-space limit of each memory run (ulimit -v);
#                      a command that needs more dies and is flagged OVER
#   TIMEOUT=300        seconds before a memory run is killed (TIMEOUT)
#   DIALECTS="linuxcnc fanuc haas siemens840d heidenhain"
#   BENCH_DIR=target/bench-programs   where the programs are kept (reused)
#
# How it measures (the way issue 17 asks):
# - CPU time, user + system, of each process (GNU /usr/bin/time -f), never
#   wall time: the machine is shared, CPU time is what the program costs.
# - The program is ../shared/bench/gen_program.py's CAM program, written in
#   each of the five dialects with the same moves by benches/dialect_program.py.
#   `check` is reported as MB/s of that dialect's file.
# - `cncc canon` and LinuxCNC's `rs274` run interleaved in one loop
#   (canon, rs274, canon, rs274, ...) so that both see the same machine
#   load; rs274 writes its calls to a real file on disk (its fast, buffered
#   mode), as rs274-canon does. The ratio is rs274 CPU / canon CPU.
# - cncc's output goes to a real null device: /dev/null when it is a
#   character device (`test -c`); when it is not (on some machines it is a
#   regular file, and writing there measures a memory copy and fills a
#   disk), to a FIFO drained by a reader process that discards the bytes.
# - Peak resident memory (%M) of every command at LINES and at MEM_LINES
#   lines, with its CPU time and, for stepnc/port --verify/diff, the ratio
#   to `canon` on the same program (the issue asks for 3x at most).
#
# CNCC defaults to target/release/cncc (cargo build --release first).
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cncc="$(realpath "${1:-$root/target/release/cncc}")"
[[ -x "$cncc" ]] || { echo "no cncc at $cncc (cargo build --release)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "needs GNU time (/usr/bin/time)" >&2; exit 2; }
LINES=${LINES:-2000000}
MEM_LINES=${MEM_LINES:-5000000}
ROUNDS=${ROUNDS:-3}
SECTIONS=${SECTIONS:-"check canon memory"}
MEM_LIMIT_MB=${MEM_LIMIT_MB:-4096}
TIMEOUT=${TIMEOUT:-300}
DIALECTS=${DIALECTS:-"linuxcnc fanuc haas siemens840d heidenhain"}
dir="${BENCH_DIR:-$root/target/bench-programs}"
gen="$root/../shared/bench/gen_program.py"
tbl="$root/../shared/tools/default.tbl"
mkdir -p "$dir"
work="$(mktemp -d)"

# --- the null device ---------------------------------------------------------
drain=""
if [[ -c /dev/null ]]; then
    null=/dev/null
    null_how="/dev/null (a character device)"
else
    null="$work/sink"
    mkfifo "$null"
    # Holds the FIFO open for reading for the whole run and throws away
    # what arrives (no write to /dev/null, no disk).
    python3 -c 'import os,sys
fd=os.open(sys.argv[1], os.O_RDONLY)
w=os.open(sys.argv[1], os.O_WRONLY)  # keep a writer so EOF never comes
while os.read(fd, 1 << 20): pass' "$null" &
    drain=$!
    null_how="a FIFO drained by a reader process (/dev/null is not a character device here)"
fi
cleanup() {
    [[ -n "$drain" ]] && kill "$drain" 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT

ext() { case $1 in siemens840d) echo mpf ;; heidenhain) echo h ;; *) echo ngc ;; esac; }
program() { # dialect lines -> path (made once, kept in $dir)
    local p="$dir/cam-$2.$1.$(ext "$1")"
    if [[ ! -s "$p" ]]; then
        python3 "$root/benches/dialect_program.py" "$1" "$2" "$p.tmp" "$gen" >&2 \
            && mv "$p.tmp" "$p" || { echo "cannot generate $p" >&2; exit 2; }
    fi
    echo "$p"
}
mb() { awk -v b="$(stat -c %s "$1")" 'BEGIN {printf "%.1f", b / 1e6}'; }

# timed CMD...: runs CMD with stdout to the null device; sets cpu, rss (MB), code
timed() {
    local t="$work/time"
    /usr/bin/time -f "%U %S %M" -o "$t" "$@" >"$null" 2>"$work/stderr"
    code=$?
    read -r u s k < <(tail -n 1 "$t")
    cpu=$(awk -v u="$u" -v s="$s" 'BEGIN {printf "%.2f", u + s}')
    rss=$(awk -v k="$k" 'BEGIN {printf "%.0f", k / 1024}')
}
# limited CMD...: like timed, under the memory limit and the timeout
limited() {
    local t="$work/time"
    ( ulimit -v $((MEM_LIMIT_MB * 1024))
      exec timeout -s KILL "$TIMEOUT" /usr/bin/time -f "%U %S %M" -o "$t" "$@" ) \
        >"$null" 2>"$work/stderr"
    code=$?
    if read -r u s k < <(tail -n 1 "$t" 2>/dev/null) && [[ "$u" =~ ^[0-9.]+$ ]]; then
        cpu=$(awk -v u="$u" -v s="$s" 'BEGIN {printf "%.2f", u + s}')
        rss=$(awk -v k="$k" 'BEGIN {printf "%.0f", k / 1024}')
    else
        cpu="-"; rss="-"
    fi
    : >"$t"
}
best() { # best CPU of ROUNDS runs: sets bcpu, brss, code
    bcpu=""; brss=0
    for ((r = 0; r < ROUNDS; r++)); do
        timed "$@"
        if [[ -z "$bcpu" ]] || awk -v a="$cpu" -v b="$bcpu" 'BEGIN {exit !(a < b)}'; then bcpu=$cpu; fi
        (( rss > brss )) && brss=$rss
    done
}
rate() { awk -v m="$1" -v s="$2" 'BEGIN {if (s > 0) printf "%.1f", m / s; else print "-"}'; }

echo "cncc: $cncc ($(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "output to: $null_how; CPU = user + system; best of $ROUNDS"
echo

# --- check, per dialect -----------------------------------------------------
if [[ " $SECTIONS " == *" check "* ]]; then
    echo "## check on $LINES lines, per dialect (MB/s of CPU time)"
    printf '%-12s %7s %9s %9s %8s %9s %9s %8s\n' dialect MB "check s" "MB/s" "RSS MB" "no-run s" "MB/s" exit
    for d in $DIALECTS; do
        p=$(program "$d" "$LINES"); m=$(mb "$p")
        best "$cncc" check --dialect "$d" "$p"; c1=$bcpu; r1=$brss; e1=$code
        best "$cncc" check --no-run --dialect "$d" "$p"; c2=$bcpu
        printf '%-12s %7s %9s %9s %8s %9s %9s %8s\n' "$d" "$m" "$c1" "$(rate "$m" "$c1")" "$r1" \
            "$c2" "$(rate "$m" "$c2")" "$e1"
    done
    echo
fi

# --- canon against rs274, interleaved --------------------------------------
if [[ " $SECTIONS " == *" canon "* ]]; then
    p=$(program linuxcnc "$LINES"); m=$(mb "$p")
    echo "## canon against LinuxCNC rs274 on $LINES lines ($m MB), interleaved"
    rs274=${RS274:-$(command -v rs274 || true)}
    cbest=""; rbest=""
    printf '%-6s %9s %9s %8s\n' round "canon s" "rs274 s" ratio
    for ((r = 0; r < ROUNDS; r++)); do
        timed "$cncc" canon --dialect linuxcnc "$p"; cc=$cpu; crss=$rss
        rc="-"
        if [[ -n "$rs274" ]]; then
            cp "$tbl" "$work/tool.tbl"; : >"$work/rs274.var"
            ( cd "$work" && HOME="$work" LC_ALL=C timed "$rs274" -g -t "$work/tool.tbl" \
                -v "$work/rs274.var" "$p" "$work/rs274.out" </dev/null
              echo "$cpu $rss" >"$work/rs274.cpu" )
            read -r rc rrss <"$work/rs274.cpu"
            rm -f "$work/rs274.out"
        fi
        printf '%-6s %9s %9s %8s\n' "$((r + 1))" "$cc" "$rc" "$(rate "$rc" "$cc")x"
        [[ -z "$cbest" ]] || awk -v a="$cc" -v b="$cbest" 'BEGIN {exit !(a < b)}' && cbest=$cc
        [[ "$rc" == "-" ]] || { [[ -z "$rbest" ]] || awk -v a="$rc" -v b="$rbest" 'BEGIN {exit !(a < b)}'; } && rbest=$rc
    done
    echo "best: canon $cbest s ($(rate "$m" "$cbest") MB/s, RSS $crss MB), rs274 ${rbest:--} s" \
         "($(rate "$m" "${rbest:-0}") MB/s, RSS ${rrss:--} MB): canon is $(rate "${rbest:-0}" "$cbest")x rs274"
    echo
    printf '%-12s %9s %9s\n' dialect "canon s" "MB/s"
    for d in $DIALECTS; do
        pd=$(program "$d" "$LINES")
        best "$cncc" canon --dialect "$d" "$pd"
        printf '%-12s %9s %9s\n' "$d" "$bcpu" "$(rate "$(mb "$pd")" "$bcpu")"
    done
    echo
fi

# --- memory of every command, LINES and MEM_LINES -------------------------
# --- simulate: issue 19 (2M lines, 0.1 mm grid, 200 x 200 mm stock) ----------
if [[ " $SECTIONS " == *" simulate "* ]]; then
    p=$(program linuxcnc "$LINES"); m=$(mb "$p")
    # The generator's tools (its comments give D12 flat, D6 and D3 ball,
    # D8.5 drill); its stock is 200 x 150 x 30 with the top at Z0.
    printf '%s\n' "T1 P1 Z0 D12 ;D12 flat end mill" "T2 P2 Z0 D6 ;D6 ball end mill" \
        "T3 P3 Z0 D3 ;D3 ball end mill" "T4 P4 Z0 D8.5 ;D8.5 drill" >"$work/sim.tbl"
    echo "## simulate on $LINES lines ($m MB): grid 0.1 mm over 200 x 200 mm (2000 x 2000 cells)"
    timed "$cncc" simulate --dialect linuxcnc --machine-units mm --tool-table "$work/sim.tbl" \
        --stock 200x200x30+0-25-30 --resolution 0.1 "$p"
    echo "CPU ${cpu} s, peak RSS ${rss} MB, exit $code (issue 19 asks under 10 s on one core)"
    echo
fi

if [[ " $SECTIONS " == *" memory "* ]]; then
    echo "## peak memory per command (limit ${MEM_LIMIT_MB} MB address space, ${TIMEOUT} s)"
    printf '%-22s' command
    for n in $LINES $MEM_LINES; do printf ' %10s %8s %7s' "RSS@$n" "cpu s" "xcanon"; done
    echo
    declare -A canon_cpu
    cmds=("check" "check --no-run" "canon" "stats" "plot" "stepnc --cc1" "stepnc --cc2"
          "diff" "ir" "port --to fanuc" "port --verify")
    rows=()
    for c in "${cmds[@]}"; do
        line=$(printf '%-22s' "$c")
        for n in $LINES $MEM_LINES; do
            p=$(program linuxcnc "$n")
            case $c in
                plot) args=(plot --dialect linuxcnc -o "$work/plot.svg" "$p") ;;
                diff) args=(diff --dialect-a linuxcnc --dialect-b linuxcnc "$p" "$p") ;;
                "port --verify") args=(port --from linuxcnc --to fanuc --verify -o "$work/port.ngc" "$p") ;;
                "port --to fanuc") args=(port --from linuxcnc --to fanuc "$p") ;;
                *) read -ra a <<<"$c"; args=("${a[0]}" --dialect linuxcnc "${a[@]:1}" "$p") ;;
            esac
            limited "$cncc" "${args[@]}"
            rm -f "$work/plot.svg" "$work/port.ngc"
            flag=""
            (( code == 137 )) && flag="TIMEOUT"
            (( code == 134 )) && flag="OVER"
            [[ "$rss" == "-" ]] && [[ -z "$flag" ]] && flag="OVER"
            [[ -n "$flag" ]] || { (( code > 1 )) && flag="exit$code"; }
            [[ "$c" == canon ]] && canon_cpu[$n]=$cpu
            x="-"
            [[ "$cpu" != "-" && -n "${canon_cpu[$n]:-}" ]] && x="$(rate "$cpu" "${canon_cpu[$n]}")"
            line+=$(printf ' %10s %8s %7s' "${rss}${flag:+ $flag}" "$cpu" "$x")
        done
        echo "$line"
    done
fi
