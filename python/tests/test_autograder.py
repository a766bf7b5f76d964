"""The autograder example (examples/autograder) marks a right and a slipped submission."""

import os
import subprocess
import sys

from conftest import ROOT

AUTOGRADER = ROOT / "examples" / "autograder"


def run(submission):
    env = dict(os.environ, KINETICS_SUBMISSION=submission)
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", os.fspath(AUTOGRADER)],
        env=env, capture_output=True, text=True, cwd=ROOT, timeout=600)


def test_right_submission_passes():
    done = run("submission.py")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "4 passed" in done.stdout


def test_slipped_submission_fails_with_named_slips():
    done = run("submissions/slipped.py")
    assert done.returncode == 1, done.stdout + done.stderr
    assert "4 failed" in done.stdout
    out = done.stdout
    assert "the parallel-axis term is missing" in out
    assert "the cross product is reversed: the transport term is Ω × H" in out
    assert "correct: D_y = -3*M/(16*c) - 1/4*m*c*w^2" in out
    assert "q4: no answer given" in out
