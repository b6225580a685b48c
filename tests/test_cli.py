"""The command line calculator, run as a user runs it: through a subprocess."""

from __future__ import annotations

import contextlib
import io
import json
import subprocess
import sys

import pytest

from trinormal import triangle_normal
from trinormal.cli import main


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "trinormal", *args], capture_output=True, text=True, timeout=60
    )


def test_worked_example_table():
    p = run("0,0,0", "1,0,0", "0,1,0")
    assert p.returncode == 0, p.stderr
    lines = p.stdout.splitlines()
    assert lines[0].split() == [
        "A,",
        "B,",
        "C",
        "(0,",
        "0,",
        "0)",
        "(1,",
        "0,",
        "0)",
        "(0,",
        "1,",
        "0)",
    ]
    assert "N = U × V      (0.0000, 0.0000, 1.0000)" in lines
    assert "area = |N|/2   0.5000" in lines
    assert "unit normal    (0.0000, 0.0000, 1.0000)" in lines
    assert p.stderr == ""


def test_negative_coordinates_need_no_double_dash():
    p = run("-1,2,3", "0,0,0", "1,1,1", "--precision", "3")
    assert p.returncode == 0, p.stderr
    expected = triangle_normal(("-1", "2", "3"), (0, 0, 0), (1, 1, 1)).format(3)
    assert f"N = U × V      {expected['normal']}" in p.stdout
    assert f"plane          {expected['plane']}" in p.stdout


def test_winding_flips():
    p = run("0,0,0", "1,0,0", "0,1,0", "--winding", "ACB")
    assert "(0.0000, 0.0000, -1.0000)" in p.stdout
    assert "A→C→B" in p.stdout


def test_json_has_every_field_and_exact_strings():
    p = run("0,0,0", "0.1,0,0", "0,1/3,0", "--json")
    assert p.returncode == 0
    data = json.loads(p.stdout)
    for key in ("a", "b", "c", "u", "v", "normal", "magnitude", "area", "unit_normal", "plane"):
        assert key in data
    assert data["exact"]["normal"] == ["0", "0", "1/30"]
    assert data["exact"]["b"] == ["1/10", "0", "0"]
    assert data["normal"][2] == 1 / 30
    assert data["degenerate"] is False
    assert data["formatted"]["area"] == "0.0167"


def test_json_non_finite_as_strings():
    data = json.loads(run("0,0,0", "1e300,0,0", "0,1e300,0", "--json").stdout)
    assert data["normal"][2] == "inf" and data["magnitude"] == "inf"
    assert data["unit_normal"] == [0.0, 0.0, 1.0]
    assert data["formatted"]["magnitude"] == "1.0000e+600"


def test_steps_use_the_users_numbers():
    p = run("1,1,1", "2,1,1", "1,2,2", "--steps")
    assert p.returncode == 0
    assert "U = B − A = (2 − 1, 1 − 1, 1 − 1) = (1, 0, 0)" in p.stdout
    assert "Ny = Uz·Vx − Ux·Vz = 0·0 − 1·1 = -1" in p.stdout
    assert "|N| = √2 ≈ 1.4142" in p.stdout
    assert "n̂ = N / |N| = (0, -√2/2, √2/2) ≈ (0.0000, -0.7071, 0.7071)" in p.stdout


def test_degenerate_is_an_answer():
    p = run("0,0,0", "0.1,0.2,0.3", "0.3,0.6,0.9")
    assert p.returncode == 0
    assert "unit normal    undefined" in p.stdout
    assert "collinear" in p.stdout
    p = run("0,0,0", "0.1,0.2,0.3", "0.3,0.6,0.9", "--steps")
    assert p.returncode == 0 and "n̂ = undefined" in p.stdout


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["0,0,0", "1,nan,0", "0,1,0"], "B.y is NaN"),
        (["0,0,0", "1,0", "0,1,0"], "B has 2 coordinates, expected 3"),
        (["0,0,0", "1,0,0", "0,abc,0"], "C.y = 'abc' is not a number"),
        (["0,0,0", "1,0,0", "0,1/0,0"], "C.y = '1/0' divides by zero"),
        (["0,0,0", "1,0,0"], "expected three points"),
        (["0,0,0", "1,0,0", "0,1,0", "--winding", "XYZ"], "invalid choice"),
        (["0,0,0", "1,0,0", "0,1,0", "--precision", "16"], "--precision must be from 0 to 15"),
        (["0,0,0", "1,0,0", "0,1,0", "--precision", "two"], "--precision must be a whole number"),
        (["0,0,0", "1,0,0", "0,1,0", "--tol", "-1"], "tol must be >= 0"),
        (["0,0,0", "1,0,0", "0,1,0", "--bogus"], "unrecognized arguments"),
        (["0,0,0", "1e39,0,0", "0,1,0", "--arithmetic", "float32"], "outside the float32 range"),
    ],
)
def test_bad_input_exits_2_with_one_line(args, message):
    p = run(*args)
    assert p.returncode == 2
    assert p.stdout == ""
    lines = p.stderr.splitlines()
    assert len(lines) == 1, p.stderr
    assert lines[0].startswith("trinormal: error: ")
    assert message in lines[0]
    assert "Traceback" not in p.stderr


def test_console_script_and_in_process_main(capsys):
    assert main(["0,0,0", "2,0,0", "0,3,0", "--precision", "0"]) == 0
    out = capsys.readouterr().out
    assert "area = |N|/2   3" in out
    p = subprocess.run(
        [sys.executable, "-c", "from trinormal.cli import main; raise SystemExit(main(['-h']))"],
        capture_output=True,
        text=True,
    )
    assert "usage: trinormal" in p.stdout


def test_output_piped_into_a_reader_that_stops_early():
    """``trinormal ... --json | head -0``: no traceback when the pipe is already closed."""
    p = subprocess.Popen(
        [sys.executable, "-m", "trinormal", "0,0,0", "1,0,0", "0,1,0", "--json"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert p.stdout is not None and p.stderr is not None
    p.stdout.close()  # the reader is gone before the calculator writes a byte
    err = p.stderr.read().decode()
    assert p.wait(timeout=60) == 0
    assert "Traceback" not in err and "BrokenPipeError" not in err


# --------------------------------------------------------------------------- hard environments


def run_env(*args: str, **env: str) -> subprocess.CompletedProcess[bytes]:
    import os

    return subprocess.run(
        [sys.executable, "-m", "trinormal", *args],
        capture_output=True,
        timeout=60,
        env={**os.environ, **env},
    )


@pytest.mark.parametrize("encoding", ["ascii", "cp1252", "latin-1"])
@pytest.mark.parametrize("mode", [[], ["--steps"], ["--json"], ["--help"]])
def test_output_falls_back_to_ascii_when_the_stream_cannot_encode_symbols(encoding, mode):
    p = run_env("1,1,1", "2,1,1", "1,2,2", *mode, PYTHONIOENCODING=encoding)
    assert p.returncode == 0, p.stderr
    assert p.stderr == b""
    text = p.stdout.decode(encoding)
    if mode == ["--json"]:
        assert json.loads(text)["formatted"]["unit_normal"] == "(0.0000, -0.7071, 0.7071)"
    elif mode == ["--help"]:
        assert "usage: trinormal" in text and "U = B - A" in text
    elif mode == ["--steps"]:
        assert "|N| = sqrt(2) ~ 1.4142" in text
    else:
        assert "N = U x V      (0.0000, -1.0000, 1.0000)" in text
        assert "A->B->C" in text and "U = B - A" in text


def test_errors_fall_back_to_ascii_too():
    p = run_env("0,0,0", "1,0,0", "0,\uff11,0", PYTHONIOENCODING="ascii")
    assert p.returncode == 2
    assert p.stderr.decode("ascii").splitlines() == [
        "trinormal: error: C.y = '\\uff11' is not a number "
        "(use a decimal like 0.1 or a fraction like 1/3)"
    ]


@pytest.mark.parametrize("mode", [[], ["--json"], ["--steps"], ["--help"]])
def test_a_full_device_is_one_line_and_status_1(mode, tmp_path):
    import os

    if not os.path.exists("/dev/full"):  # pragma: no cover - Linux has it
        pytest.fail("this test needs /dev/full")
    with open("/dev/full", "w") as full:
        p = subprocess.run(
            [sys.executable, "-m", "trinormal", "0,0,0", "1,0,0", "0,1,0", *mode],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
        )
    assert p.returncode == 1
    assert p.stderr.splitlines() == [
        "trinormal: error: cannot write the output: No space left on device"
    ]


def test_print_model_says_why_when_its_report_line_cannot_be_written(tmp_path):
    # the model is written; the line saying so goes to a full device
    out = tmp_path / "t.stl"
    with open("/dev/full", "w") as full:
        p = subprocess.run(
            [
                sys.executable,
                "-m",
                "trinormal",
                "print-model",
                "0,0,0",
                "40,0,0",
                "0,30,0",
                str(out),
            ],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
        )
    assert p.returncode == 1
    assert p.stderr == "trinormal: error: cannot write the output: No space left on device\n"
    assert out.stat().st_size > 0


def test_what_readers_paste_is_read_and_long_input_is_not_echoed():
    p = run("\u22121,0,0", " 1 ,\u00a00 ,0", "0,1,0")
    assert p.returncode == 0, p.stderr
    assert "A, B, C        (\u22121, 0, 0)   (1, 0, 0)   (0, 1, 0)" in p.stdout
    p = run("0,0,0", "1,0,0", "0," + "1" * 5000 + ",0")
    assert p.returncode == 2
    assert p.stderr == "trinormal: error: C.y is too long (5000 characters; at most 1000)\n"


@pytest.mark.parametrize(
    "point",
    ["1e-2200,0,0", "1e399,0,0", "5e-324,1e308,0"],
)
def test_extreme_accepted_input_prints_in_every_mode(point):
    for mode in ([], ["--json"], ["--steps"], ["--arithmetic", "float32"]):
        p = run("0,0,0", point, "0,1,1e-300", *mode)
        assert p.returncode in (0, 2), p.stderr
        assert "Traceback" not in p.stderr
        if p.returncode == 2:  # refused: one line naming the coordinate
            assert p.stderr.startswith("trinormal: error: ") and p.stderr.count("\n") == 1


def test_a_closed_output_stream_is_one_line_and_status_1():
    import os

    p = subprocess.run(
        [sys.executable, "-m", "trinormal", "0,0,0", "1,0,0", "0,1,0"],
        stderr=subprocess.PIPE,
        text=True,
        timeout=60,
        preexec_fn=lambda: os.close(1),  # start with the output stream closed
    )
    assert p.returncode == 1
    assert p.stderr == "trinormal: error: cannot write the output: the output stream is closed\n"


def _json_verdict(*args: str) -> tuple[bool, str]:
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main([*args, "--json"]) == 0
    out = json.loads(buf.getvalue())
    return out["degenerate"], out["reason"]


@pytest.mark.parametrize(
    ("points", "tol", "degenerate"),
    [
        (("0,0,0", "1,0,0", "0,1e-13,0"), None, True),  # a right angle at A, 1e-13 high
        (("0,0,0", "1,0,0", "1e-13,1e-13,0"), None, True),  # C within 1e-13 of A
        (("0,0,0", "1,0,0", "0,1e-11,0"), None, False),
        (("0,0,0", "4,0,0", "1,1,0"), "1/4", True),  # |N| / L² = 1/4 exactly
        (("0,0,0", "4,0,0", "1,1,0"), "0.2499", False),
    ],
)
def test_json_verdict_is_the_same_in_every_order_of_the_corners(points, tol, degenerate):
    a, b, c = points
    extra = [] if tol is None else ["--tol", tol]
    verdicts = {
        _json_verdict(p, q, r, "--winding", w, *extra)
        for p, q, r in ((a, b, c), (b, c, a), (c, a, b))
        for w in ("ABC", "ACB")
    }
    assert len(verdicts) == 1 and next(iter(verdicts))[0] is degenerate
    # and as a user runs it
    p = run(b, c, a, "--winding", "ACB", "--json", *extra)
    assert json.loads(p.stdout)["degenerate"] is degenerate


def test_help_states_the_rule():
    p = run("--help")
    assert "|N| <= tol · L², L the longest side" in " ".join(p.stdout.split())
