#!/usr/bin/env bash
# The whole test suite, with its set-up, on a fresh machine: installs
# LinuxCNC's standalone interpreter (the oracle the tests compare against)
# when it is missing and the machine lets us, then runs every test.
# Used by the README and by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v rs274 >/dev/null 2>&1; then
    SUDO=""
    if [ "$(id -u)" != 0 ] && command -v sudo >/dev/null 2>&1; then SUDO="sudo"; fi
    if [ "$(id -u)" = 0 ] || [ -n "$SUDO" ]; then
        export DEBIAN_FRONTEND=noninteractive
        $SUDO apt-get update -qq
        $SUDO apt-get install -y -qq --no-install-recommends linuxcnc-uspace >/dev/null
    fi
fi
if [ ! -d ../shared ]; then
    echo "note: ../shared is absent: corpus and reference tests will say they were skipped"
fi
if ! command -v rs274 >/dev/null 2>&1; then
    echo "note: rs274 is absent (apt-get install linuxcnc-uspace): the live oracle tests will say they were skipped"
fi

cargo test 2>&1
