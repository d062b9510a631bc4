#!/usr/bin/env bash
# Runs one fuzz target for a while, seeded with the test programs.
#
#   bash fuzz/run.sh TARGET [SECONDS]      # default 600
#
# TARGET: word_address sinumerik klartext part21 interp port post.
# Needs cargo-fuzz (`cargo install cargo-fuzz`); on a stable toolchain
# RUSTC_BOOTSTRAP=1 lets it use the flags it needs. Builds without a
# sanitizer (safe Rust; the memory figure is then the real one) and with
# debug assertions (overflow checks). The corpus grows in
# fuzz/corpus/TARGET (not committed); a crash is written to
# fuzz/artifacts/TARGET/ and ends the run. Runs at low priority on one core.
set -euo pipefail
target="${1:?target: word_address sinumerik klartext part21 interp port post}"
seconds="${2:-600}"
cd "$(dirname "$0")"
root=..
corpus="corpus/$target"
mkdir -p "$corpus"
seed() { # seed FOLDER... : small files of tests/FOLDER into the corpus
    for d in "$@"; do
        find "$root/tests/$d" -type f -size -64k | while read -r f; do
            cp "$f" "$corpus/seed_$(echo "${f#$root/}" | tr / _)"
        done
    done
}
case "$target" in
    word_address) seed programs/fanuc programs/haas programs/linuxcnc ;;
    sinumerik) seed programs/siemens840d ;;
    klartext) seed programs/heidenhain ;;
    part21 | post) seed programs/stepnc stepnc ;;
    interp) seed programs/fanuc programs/haas programs/linuxcnc programs/siemens840d programs/heidenhain ;;
    port) # the first byte chooses the source dialect (fuzzing::DIALECTS)
        # `sed -n`, not `head`: head closes the pipe after 20 names and,
        # with pipefail, find's SIGPIPE ended this script (status 141).
        k=0
        for d in fanuc haas linuxcnc siemens840d heidenhain; do
            find "$root/tests/programs/$d" -type f -size -64k | sed -n 1,20p | while read -r f; do
                { printf "\\x$(printf %02x $k)"; cat "$f"; } >"$corpus/seed_$(echo "${f#$root/}" | tr / _)"
            done
            k=$((k + 1))
        done ;;
    *) echo "unknown target $target" >&2; exit 2 ;;
esac
export RUSTC_BOOTSTRAP=1 CARGO_BUILD_JOBS=1
nice -n 10 cargo fuzz run --sanitizer none "$target" "$corpus" -- \
    -dict=dict/cncc.dict -max_total_time="$seconds" -rss_limit_mb=2048 \
    -timeout=10 -max_len=65536 -print_final_stats=1
