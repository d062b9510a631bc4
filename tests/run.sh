#!/usr/bin/env bash
# The whole test suite, with its set-up, on a fresh machine.
# Used by the README and by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ ! -d ../shared ]; then
    echo "note: ../shared is absent: corpus and reference tests will say they were skipped"
fi
if ! command -v rs274 >/dev/null 2>&1; then
    echo "note: rs274 is absent (apt-get install linuxcnc-uspace): the live oracle tests will say they were skipped"
fi

cargo test 2>&1
