#!/usr/bin/env python3
"""Every reproducer of tests/reproducers/ through the release binary under `ulimit -v 1 GiB`,
timed by /usr/bin/time: the slowest six (seconds, peak resident MB, exit code) and the exit
codes seen. The wall-clock measure of issue 29's acceptance (each within 2 s and 1 GiB);
the test suite checks work, not time (tests/suite/reproducers.rs).

    cargo build --release && python3 tests/measure_reproducers.py

Headers as the suite reads them: `# run:` the arguments, the input last (after `--`);
`# repeat: N` an .expr body line repeated N times, on standard input; `# bytes: escaped` a
.scene whose `\\xHH` are bytes, written to a scratch file; a .claim's claim after
`--claim`. `MISSING` and `DANGLING` become paths that do not exist.
"""
import os
import re
import shlex
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BINARY = os.path.join(ROOT, "target", "release", "kinetics")
FOLDER = os.path.join(ROOT, "tests", "reproducers")


def read(path):
    """The headers (key: value) and the body lines of a reproducer."""
    headers, body = {}, []
    with open(path, encoding="utf-8", errors="surrogateescape") as f:
        for line in f.read().split("\n"):
            header = re.match(r"# (\w+): (.*)$", line)
            if header and not body:
                headers[header.group(1)] = header.group(2)
            else:
                body.append(line)
    return headers, body


def command(name, headers, body, scratch):
    """The arguments and standard input of one reproducer's run."""
    args = shlex.split(headers.get("run", ""))
    args = [a.replace("MISSING", "/nonexistent/folder/x").replace("DANGLING", "/nonexistent/link") for a in args]
    extension = name.rsplit(".", 1)[1]
    lines = [l for l in body if l and not l.startswith("# ")]
    if extension == "expr" and "repeat" in headers:
        text = lines[0] * int(headers["repeat"]) + (lines[1] if len(lines) > 1 else "")
        return args + ["--", "-"], text.encode("utf-8", "surrogateescape")
    if extension == "expr":
        return args + ["--", lines[0]], None
    if extension == "claim":
        return args + [lines[0]], None
    path = os.path.join(FOLDER, name)
    if headers.get("bytes") == "escaped":
        raw = "\n".join(body).encode("utf-8", "surrogateescape")
        raw = re.sub(rb"\\x([0-9a-fA-F]{2})", lambda m: bytes([int(m.group(1), 16)]), raw)
        path = os.path.join(scratch, name)
        with open(path, "wb") as f:
            f.write(raw)
    return args + ["--", path], None


def main():
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for name in sorted(os.listdir(FOLDER)):
            headers, body = read(os.path.join(FOLDER, name))
            argv, stdin = command(name, headers, body, scratch)
            run = ["bash", "-c", 'ulimit -v 1048576; exec /usr/bin/time -f "%e %M" "$@"', "-", BINARY] + argv
            done = subprocess.run(run, input=stdin, capture_output=True, timeout=120)
            seconds, kilobytes = done.stderr.decode(errors="replace").split()[-2:]
            rows.append((float(seconds), int(kilobytes) / 1024, done.returncode, name))
    rows.sort()
    for seconds, megabytes, code, name in rows[-6:]:
        print(f"{seconds:6.2f} s {megabytes:7.1f} MB exit {code}  {name}")
    print(f"{len(rows)} reproducers; exit codes {sorted({r[2] for r in rows})}; peak {max(r[1] for r in rows):.0f} MB")


if __name__ == "__main__":
    main()
