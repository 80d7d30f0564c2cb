#!/bin/sh
# The Gröbner benchmark suite against Singular and sympy (docs/performance.md).
# Installs Singular (Debian package `singular`) and sympy where missing; never run in CI.
# Writes each ideal to target/groebner-suite/NAME.sing and NAME.py, then prints one table of
# GAM's in-process time, Singular's rtimer time, sympy's time and the ratios, all in one run.
# Usage: tests/bench/groebner-suite.sh [NAME...] [--gam-only]
# (--gam-only: GAM's times alone, for A/B runs of the engine; Singular and sympy are skipped)
set -eu
cd "$(dirname "$0")/../.."
if ! command -v Singular >/dev/null 2>&1; then
    apt-get update && apt-get install -y singular
fi
if ! python3 -c "import sympy" 2>/dev/null; then
    python3 -m venv target/sympy-venv && target/sympy-venv/bin/pip install sympy
    PATH="$PWD/target/sympy-venv/bin:$PATH"
    export PATH
fi
nice -n 10 cargo bench -p algebra-core --features rug --bench groebner_suite -j 1 -- "$@"
