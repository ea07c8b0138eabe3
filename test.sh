#!/usr/bin/env bash
# The whole test suite, what CI runs (via .ci/run): the Rust tests (`cargo test`, extra
# arguments go to it), then the Python package built from ./python into a fresh virtual
# environment (pip with maturin as the PEP 517 backend, as a user installs it) and its
# pytest tests, with the physics engines the conformance adapters drive (PyBullet, Pymunk,
# MuJoCo: the `engines` extra, binary wheels) so that their adapter tests and the MuJoCo
# example's test run rather than skip.
#
# PYTHON picks the interpreter (default python3); CYLROLL_VENV the environment's directory
# (default target/pytest-venv, recreated on every run).
set -euo pipefail
cd "$(dirname "$0")"
# the report's browser check (tests/report_figures.rs) runs wherever Chromium is installed
# (.ci/run installs it, and fails loudly if it cannot)
if [ -z "${CYLROLL_BROWSER_CHECK:-}" ] &&
  { command -v chromium || command -v chromium-browser; } >/dev/null 2>&1; then
  export CYLROLL_BROWSER_CHECK=1
fi
cargo test "$@"

PY="${PYTHON:-python3}"
VENV="${CYLROLL_VENV:-target/pytest-venv}"
rm -rf "$VENV"
"$PY" -m venv "$VENV"
"$VENV/bin/python" -m pip install --quiet --disable-pip-version-check "./python[test,engines]"
# run from outside the source tree, so that the installed package is the one imported
(cd "$VENV" && bin/python -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests" "$OLDPWD/examples/mujoco")
