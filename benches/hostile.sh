#!/usr/bin/env bash
# Hostile-input benchmark (issue 14): not a test, figures are printed.
#
#   bash benches/hostile.sh [CNCC] [DIR]
#
# Writes the hostile inputs of issue 14 into DIR (default: a temporary
# folder, removed at the end) with benches/hostile_inputs.py, runs the
# cncc commands that read them under /usr/bin/time -v, and prints one row
# per run: exit status, peak resident memory, CPU time (user + system),
# wall time and bytes written to stdout and stderr. A run over 2 GB of
# memory or 60 s (CPU or wall) is flagged OVER; a run still going after
# 300 s is killed and flagged TIMEOUT. The exit status is 1 when any run is
# flagged. CNCC defaults to target/release/cncc (build it first).
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cncc="${1:-$root/target/release/cncc}"
dir="${2:-}"
if [[ -z "$dir" ]]; then
    dir="$(mktemp -d)"
    trap 'rm -rf "$dir"' EXIT
fi
[[ -x "$cncc" ]] || { echo "no cncc at $cncc (cargo build --release)" >&2; exit 2; }
cncc="$(realpath "$cncc")"
[[ -x /usr/bin/time ]] || { echo "needs GNU time (/usr/bin/time)" >&2; exit 2; }
python3 "$root/benches/hostile_inputs.py" "$dir" || exit 2
cd "$dir" || exit 2

limit_kb=$((2 * 1024 * 1024))
limit_s=60
flagged=0
printf '%-34s %5s %9s %8s %8s %10s %10s  %s\n' case exit "rss MB" "cpu s" "wall s" stdout stderr flag
run() {
    local name="$1"; shift
    local file="$dir/run_${name//[^A-Za-z0-9]/_}"
    local t="$file.time"
    timeout -s KILL 300 /usr/bin/time -v -o "$t" "$@" >"$file.out" 2>"$file.err"
    local code=$?
    local rss user sys wall flag=""
    rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$t" 2>/dev/null)
    user=$(awk -F': ' '/User time/ {print $2}' "$t" 2>/dev/null)
    sys=$(awk -F': ' '/System time/ {print $2}' "$t" 2>/dev/null)
    wall=$(awk '/Elapsed \(wall clock\)/ {print $NF}' "$t" 2>/dev/null \
        | awk -F: '{s=0; for (i=1;i<=NF;i++) s=s*60+$i; print s}')
    local cpu
    cpu=$(awk -v u="${user:-0}" -v s="${sys:-0}" 'BEGIN {printf "%.2f", u+s}')
    if [[ $code -eq 137 && -z "$rss" ]]; then
        flag="TIMEOUT"
    elif (( ${rss:-0} > limit_kb )) \
        || awk -v c="$cpu" -v w="${wall:-0}" -v l=$limit_s 'BEGIN {exit !(c > l || w > l)}'; then
        flag="OVER"
    elif [[ -s "$t" ]] && grep -q 'Command terminated by signal' "$t"; then
        flag="SIGNAL"
    fi
    [[ -n "$flag" ]] && flagged=1
    printf '%-34s %5s %9.1f %8s %8.2f %10s %10s  %s\n' "$name" "$code" \
        "$(awk -v k="${rss:-0}" 'BEGIN {print k/1024}')" "$cpu" "${wall:-0}" \
        "$(stat -c %s "$file.out")" "$(stat -c %s "$file.err")" "$flag"
    rm -f "$file.out"
}

# A 50 MB single line (8M words on one block).
run "line50mb check" "$cncc" check --dialect fanuc line50mb.nc
run "line50mb port" "$cncc" port --from fanuc --to linuxcnc line50mb.nc
# A 1 MB line of one repeated word (a diagnostic per word).
run "words1mb check" "$cncc" check --dialect fanuc words1mb.nc
# 100k nested IF/WHILE.
run "nest100k check (siemens)" "$cncc" check --dialect siemens840d nest100k.mpf
run "nest100k canon (siemens)" "$cncc" canon --dialect siemens840d nest100k.mpf
run "nest100k port siemens>linuxcnc" "$cncc" port --from siemens840d --to linuxcnc nest100k.mpf
run "nest100k port siemens>heid" "$cncc" port --from siemens840d --to heidenhain nest100k.mpf
run "nest100k check (o-words)" "$cncc" check --dialect linuxcnc nest100k.ngc
run "nest100k canon (o-words)" "$cncc" canon --dialect linuxcnc nest100k.ngc
run "nest100k port linuxcnc>siemens" "$cncc" port --from linuxcnc --to siemens840d nest100k.ngc
# A helix of 10^8 turns (and 10^7 in the other planes), drawn.
run "helix plot svg" "$cncc" plot --views top,side,iso -o helix.svg helix.ngc
run "helix plot png" "$cncc" plot --views top,side,iso -o helix.png helix.ngc
run "helix stats" "$cncc" stats helix.ngc
# A tool table that never ends.
run "tool-table /dev/zero" "$cncc" check --tool-table /dev/zero small.nc
# A 10M-entity Part 21 file.
run "part21 10M check" "$cncc" check part21_10m.stp
run "part21 10M post" "$cncc" post --to fanuc part21_10m.stp
run "part21 10M query" "$cncc" query part21_10m.stp /project/its_id
run "part21 2.2M points check" "$cncc" check part21_points.stp
run "part21 2.2M points post" "$cncc" post --to siemens840d part21_points.stp
run "part21 2.2M points stepnc" "$cncc" stepnc part21_points.stp
run "part21 50M params check" "$cncc" check part21_params.stp
# A dialect spec with 80k codes.
run "dialect 80k codes check" "$cncc" check --dialect-file dialect80k.xml --dialect big-fanuc small.nc
# Deep expressions.
run "sum 50k terms check" "$cncc" check --dialect fanuc sum50k.nc
run "sum 50k terms port" "$cncc" port --from fanuc --to siemens840d sum50k.nc
run "ABS[ 20k deep check" "$cncc" check --dialect fanuc abs20k.nc
run "ABS[ 20k deep port" "$cncc" port --from fanuc --to heidenhain abs20k.nc
# Large CAM programs (not hostile), when the shared generator is there.
if [[ -f cam48mb.ngc ]]; then
    run "cam 48MB check" "$cncc" check cam48mb.ngc
    run "cam 48MB canon" "$cncc" canon cam48mb.ngc
    run "cam 48MB stats" "$cncc" stats cam48mb.ngc
    run "cam 48MB plot png" "$cncc" plot -o cam.png cam48mb.ngc
    run "cam 24MB port linuxcnc>siemens" "$cncc" port --to siemens840d cam24mb.ngc
    run "cam 48MB port linuxcnc>heid" "$cncc" port --to heidenhain cam48mb.ngc
    run "cam 24MB port --verify" "$cncc" port --to siemens840d --verify cam24mb.ngc
    run "flow 48MB check" "$cncc" check flow48mb.ngc
    run "flow 48MB port linuxcnc>siemens" "$cncc" port --to siemens840d flow48mb.ngc
    run "flow 48MB port --verify" "$cncc" port --to siemens840d --verify flow48mb.ngc
fi
printf '\ninputs: %s\n' "$(du -sh --apparent-size "$dir" | cut -f1)"
exit $flagged
