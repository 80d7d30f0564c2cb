"""Shared fixtures: the `gam` binary whose `--json` output the Python functions must equal.

GAM_BIN names it; by default the workspace's target/debug/gam or target/release/gam (the more
recently built). A missing binary fails the tests that need it (never a silent skip).
"""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def gam_bin():
    env = os.environ.get("GAM_BIN")
    if env:
        return env
    found = [p for p in (ROOT / "target" / "debug" / "gam", ROOT / "target" / "release" / "gam") if p.exists()]
    if not found:
        pytest.fail("no gam binary: build it (cargo build -p gam) or set GAM_BIN")
    return str(max(found, key=lambda p: p.stat().st_mtime))


class Cli:
    """Runs `gam ARGS` in a directory; `json()` parses stdout, `error()` the one error line."""

    def __init__(self, tmp_path):
        self.dir = tmp_path
        self.bin = gam_bin()

    def run(self, *args, files=None):
        for name, value in (files or {}).items():
            (self.dir / name).write_text(json.dumps(value, separators=(",", ":")))
        return subprocess.run([self.bin, *args], cwd=self.dir, capture_output=True, text=True, timeout=600)

    def json(self, *args, files=None):
        r = self.run(*args, files=files)
        assert r.stdout.strip(), f"gam {' '.join(args)}: no output, stderr {r.stderr!r}"
        return json.loads(r.stdout)

    def error(self, *args, files=None):
        r = self.run(*args, files=files)
        assert r.returncode in (1, 2) and r.stdout == "", (r.returncode, r.stdout, r.stderr)
        lines = r.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("error: "), r.stderr
        return lines[0][len("error: "):]


@pytest.fixture
def cli(tmp_path):
    return Cli(tmp_path)
